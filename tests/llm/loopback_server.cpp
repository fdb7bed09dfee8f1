#include "loopback_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <stdexcept>

namespace squawk::testing {

namespace {

constexpr int kPollMs = 20;         // granularity of stop checks
constexpr int kReadLimitMs = 3000;  // give up on a client that sends nothing

int listen_on_ephemeral(int* port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) throw std::runtime_error("socket() failed");
  int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = 0;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(fd, 16) != 0) {
    ::close(fd);
    throw std::runtime_error("bind/listen on 127.0.0.1 failed");
  }
  socklen_t len = sizeof addr;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
  *port = ntohs(addr.sin_port);
  return fd;
}

bool write_all(int fd, const std::string& s) {
  size_t off = 0;
  while (off < s.size()) {
    const ssize_t n = ::send(fd, s.data() + off, s.size() - off, MSG_NOSIGNAL);
    if (n <= 0) return false;
    off += static_cast<size_t>(n);
  }
  return true;
}

const char* reason(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 404: return "Not Found";
    case 500: return "Internal Server Error";
    case 503: return "Service Unavailable";
    default: return "Status";
  }
}

}  // namespace

Reply Reply::json(int status, std::string body) {
  Reply r;
  r.status = status;
  r.pieces.push_back(std::move(body));
  return r;
}

LoopbackServer::LoopbackServer(Handler handler) : handler_(std::move(handler)) {
  listen_fd_ = listen_on_ephemeral(&port_);
  acceptor_ = std::thread([this] { accept_loop(); });
}

LoopbackServer::~LoopbackServer() { stop(); }

std::string LoopbackServer::url() const { return "http://127.0.0.1:" + std::to_string(port_); }

std::vector<HttpRequestSeen> LoopbackServer::requests() {
  std::lock_guard<std::mutex> lock(mu_);
  return seen_;
}

void LoopbackServer::stop() {
  if (stopping_.exchange(true)) return;
  if (acceptor_.joinable()) acceptor_.join();
  std::vector<std::thread> workers;
  {
    std::lock_guard<std::mutex> lock(mu_);
    workers.swap(workers_);
  }
  for (auto& w : workers) w.join();
  ::close(listen_fd_);
}

bool LoopbackServer::sleep_ms(int ms) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  while (std::chrono::steady_clock::now() < end) {
    if (stopping_) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return !stopping_;
}

void LoopbackServer::accept_loop() {
  int index = 0;
  while (!stopping_) {
    pollfd p{listen_fd_, POLLIN, 0};
    if (::poll(&p, 1, kPollMs) <= 0) continue;
    const int fd = ::accept(listen_fd_, nullptr, nullptr);
    if (fd < 0) continue;
    std::lock_guard<std::mutex> lock(mu_);
    workers_.emplace_back([this, fd, i = index++] { serve(fd, i); });
  }
}

void LoopbackServer::serve(int fd, int index) {
  std::string data;
  size_t header_end = std::string::npos;
  size_t content_length = 0;
  int waited = 0;
  char buf[4096];
  while (!stopping_ && waited < kReadLimitMs) {
    if (header_end != std::string::npos && data.size() >= header_end + 4 + content_length) break;
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, kPollMs) <= 0) {
      waited += kPollMs;
      continue;
    }
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n <= 0) break;
    data.append(buf, static_cast<size_t>(n));
    if (header_end == std::string::npos && (header_end = data.find("\r\n\r\n")) != std::string::npos) {
      std::string head = data.substr(0, header_end);
      for (auto& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      const auto cl = head.find("content-length:");
      if (cl != std::string::npos) content_length = std::stoul(head.substr(cl + 15));
    }
  }
  if (header_end == std::string::npos) {
    ::close(fd);
    return;
  }
  HttpRequestSeen req;
  const auto line_end = data.find("\r\n");
  const auto sp1 = data.find(' ');
  const auto sp2 = data.find(' ', sp1 + 1);
  req.method = data.substr(0, sp1);
  req.path = data.substr(sp1 + 1, std::min(sp2, line_end) - sp1 - 1);
  req.body = data.substr(header_end + 4, content_length);
  {
    std::lock_guard<std::mutex> lock(mu_);
    seen_.push_back(req);
  }
  const Reply r = handler_(req, index);
  if (r.drop || !sleep_ms(r.delay_ms)) {
    ::close(fd);
    return;
  }
  std::string head = "HTTP/1.1 " + std::to_string(r.status) + " " + reason(r.status) + "\r\n";
  head += "Content-Type: " + r.content_type + "\r\nConnection: close\r\n";
  if (r.chunked) {
    head += "Transfer-Encoding: chunked\r\n\r\n";
  } else {
    size_t total = 0;
    for (const auto& p : r.pieces) total += p.size();
    head += "Content-Length: " + std::to_string(total) + "\r\n\r\n";
  }
  bool ok = write_all(fd, head);
  for (size_t i = 0; ok && i < r.pieces.size(); ++i) {
    if (i > 0 && !sleep_ms(r.delay_ms)) {
      ok = false;
      break;
    }
    const auto& p = r.pieces[i];
    if (r.chunked) {
      char size_line[32];
      std::snprintf(size_line, sizeof size_line, "%zx\r\n", p.size());
      std::string framed(size_line);
      framed.append(p).append("\r\n");
      ok = write_all(fd, framed);
    } else {
      ok = write_all(fd, p);
    }
  }
  if (ok && r.chunked && !r.truncate) write_all(fd, "0\r\n\r\n");
  ::shutdown(fd, SHUT_WR);
  ::close(fd);
}

int closed_port() {
  int port = 0;
  const int fd = listen_on_ephemeral(&port);
  ::close(fd);
  return port;
}

}  // namespace squawk::testing
