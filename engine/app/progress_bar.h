// ProgressBar: a one-line progress bar with ETA on stderr for long commands
// (train, eval, table3), redrawn at most 5 times a second, only on a terminal.
// note() prints a line above the bar (or alone when there is no bar).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace squawk::app {

// "H:MM:SS" of s seconds (negative counts as 0).
inline std::string fmt_duration(double s) {
  char buf[32];
  const long t = std::lround(std::max(0.0, s));
  std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  return buf;
}

// A one-line progress bar with ETA on stderr, redrawn at most 5 times a second.
class ProgressBar {
 public:
  ProgressBar(std::string label, long long total, bool enabled)
      : label_(std::move(label)), total_(total), enabled_(enabled && isatty(STDERR_FILENO)) {}
  void update(long long done, const std::string& extra = "") {
    if (!enabled_) return;
    const double el = elapsed();
    if (done < total_ && el - last_ < 0.2) return;
    last_ = el;
    const double frac = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
    const int width = 30, fill = static_cast<int>(frac * width);
    std::string bar(static_cast<size_t>(fill), '#');
    bar.append(static_cast<size_t>(width - fill), '.');
    const double eta = frac > 0 ? el * (1.0 - frac) / frac : 0.0;
    std::fprintf(stderr, "\r%s [%s] %5.1f%% %lld/%lld  %s elapsed, ETA %s %s", label_.c_str(),
                 bar.c_str(), 100.0 * frac, done, total_, fmt_duration(el).c_str(),
                 fmt_duration(eta).c_str(), extra.c_str());
    std::fflush(stderr);
  }
  // Prints `line` (with its newline) on stdout without tearing the bar.
  void note(const std::string& line) {
    if (enabled_ && last_ >= 0.0) std::fprintf(stderr, "\r\033[K");
    std::fputs(line.c_str(), stdout);
    std::fflush(stdout);
    last_ = -1.0;
  }
  void finish() {
    if (enabled_) std::fprintf(stderr, "\n");
  }
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

 private:
  std::string label_;
  long long total_;
  bool enabled_;
  double last_ = -1.0;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};


}  // namespace squawk::app
