// LoopbackServer: a small threaded HTTP/1.1 server on 127.0.0.1 with an
// ephemeral port, for testing the LLM clients through their real curl code.
//
// Each connection gets its own thread; the test's handler turns the parsed
// request into a scripted Reply: a status and body pieces written with delays
// (chunked transfer encoding when `chunked`), or a connection dropped before
// any reply. Every reply closes its connection. stop() (also run by the
// destructor) ends all threads within a bounded time, even mid-delay.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace squawk::testing {

struct HttpRequestSeen {
  std::string method;
  std::string path;
  std::string body;
};

struct Reply {
  int status = 200;
  std::string content_type = "application/json";
  std::vector<std::string> pieces;  // body, written piece by piece
  int delay_ms = 0;                 // pause before each piece (and before headers)
  bool chunked = false;             // Transfer-Encoding: chunked instead of Content-Length
  bool drop = false;                // close the connection without replying
  bool truncate = false;            // chunked: close before the final empty chunk

  static Reply json(int status, std::string body);
};

class LoopbackServer {
 public:
  using Handler = std::function<Reply(const HttpRequestSeen& request, int index)>;
  explicit LoopbackServer(Handler handler);
  ~LoopbackServer();
  LoopbackServer(const LoopbackServer&) = delete;
  LoopbackServer& operator=(const LoopbackServer&) = delete;

  int port() const { return port_; }
  std::string url() const;  // http://127.0.0.1:PORT
  std::vector<HttpRequestSeen> requests();
  void stop();

 private:
  void accept_loop();
  void serve(int fd, int index);
  bool sleep_ms(int ms);  // false when stopping

  Handler handler_;
  int listen_fd_ = -1;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::thread acceptor_;
  std::mutex mu_;
  std::vector<std::thread> workers_;
  std::vector<HttpRequestSeen> seen_;
};

// A port on 127.0.0.1 with nothing listening (bound then closed).
int closed_port();

}  // namespace squawk::testing
