// Command-layer throughput (one thread): TrafScript lines parsed and executed
// per second, parse-only checks per second, .scn parsing speed over BlueSky's
// scenario folder (when ../shared is present), and the conformance sweep's
// cost. Prints figures; asserts nothing. Reference in the same run: the bare
// Simulation::create/set_altitude calls the commands end in.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "command/scn.h"
#include "command/stack.h"
#include "core/files.h"
#include "core/units.h"

using namespace squawk;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

int main() {
  constexpr int kN = 20000;
  std::vector<std::string> cre, alt;
  for (int i = 0; i < kN; ++i) {
    const std::string id = "AC" + std::to_string(i);
    cre.push_back("CRE " + id + " B744 " + std::to_string(50 + (i % 100) * 0.05) + " " +
                  std::to_string(3 + (i / 100) * 0.05) + " 90 FL200 250");
    alt.push_back(id + " ALT FL" + std::to_string(100 + i % 200) + " 1500");
  }

  command::Stack stack;
  auto t0 = Clock::now();
  for (const auto& l : cre) (void)stack.exec(l);
  const double t_cre = seconds_since(t0);
  t0 = Clock::now();
  for (const auto& l : alt) (void)stack.exec(l);
  const double t_alt = seconds_since(t0);
  t0 = Clock::now();
  int valid = 0;
  for (const auto& l : alt) valid += stack.check(l).is_ok();
  const double t_check = seconds_since(t0);

  sim::Simulation ref;
  t0 = Clock::now();
  for (int i = 0; i < kN; ++i)
    (void)ref.create("AC" + std::to_string(i), "B744", 50 + (i % 100) * 0.05, 3 + (i / 100) * 0.05, 90,
                     units::fl_to_m(200), units::kt_to_ms(250));
  const double t_ref_cre = seconds_since(t0);
  t0 = Clock::now();
  for (int i = 0; i < kN; ++i)
    (void)ref.set_altitude("AC" + std::to_string(i), units::fl_to_m(100 + i % 200), units::fpm_to_ms(1500));
  const double t_ref_alt = seconds_since(t0);

  std::printf("command layer, 1 thread, %d aircraft\n", kN);
  std::printf("  CRE via exec           %9.0f commands/s   (direct Simulation::create %9.0f/s)\n", kN / t_cre,
              kN / t_ref_cre);
  std::printf("  ALT via exec (acid 1st) %8.0f commands/s   (direct set_altitude      %9.0f/s)\n", kN / t_alt,
              kN / t_ref_alt);
  std::printf("  check() parse-only     %9.0f lines/s (%d valid)\n", kN / t_check, valid);

  const std::filesystem::path dir = std::filesystem::path(SQUAWK_SOURCE_DIR) / ".." / "shared" / "bluesky" / "scenario";
  if (!std::filesystem::is_directory(dir)) {
    std::printf("  .scn parsing: skipped (%s not found)\n", dir.string().c_str());
    return 0;
  }
  std::vector<std::string> texts;
  size_t bytes = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) {
      auto t = files::read(e.path().string());
      if (t) {
        bytes += t->size();
        texts.push_back(std::move(*t));
      }
    }
  size_t entries = 0;
  t0 = Clock::now();
  for (const auto& t : texts) entries += command::parse_scn(t).entries.size();
  const double t_scn = seconds_since(t0);
  std::printf("  .scn parsing           %9.1f MB/s (%zu files, %.1f MB, %zu entries in %.3f s)\n",
              bytes / 1e6 / t_scn, texts.size(), bytes / 1e6, entries, t_scn);
  return 0;
}
