// HttpServer: the radar scope's HTTP side (the only file that includes the
// HTTP library, cpp-httplib). Serves the static page from `web_dir` and the
// API; every route reads the LiveSim's published state or posts a request to
// its owner thread, never the simulation itself.
//
//   GET  /api/state      the state (state_json.h, plus log and advisories)
//   GET  /api/stream     server-sent events: one `data: <state>` per publish
//   GET  /api/navdata?south=&north=&west=&east=[&kinds=airports,navaids,fixes]
//                        airports, navaids and fixes in a box (state_json.h)
//   GET  /api/geo?south=&north=&west=&east=&step=   coastlines and FIR borders
//                        in a box, points `step` degrees apart (geography.h)
//   POST /api/command    {"text": "English or !TrafScript", "client"?: page id, "selected"?: callsign}
//                        -> command reply (each client has its own dialogue;
//                        a line naming no aircraft may go to "selected")
//   POST /api/advisory   {"id": n, "decision": "accept"|"reject"}
//   POST /api/auto       {"on": true|false}  execute advisories automatically
// Whatever address it listens on, only requests whose Host is 127.0.0.1,
// localhost, [::1] or a name in allowed_hosts are answered (403 otherwise:
// DNS rebinding). POST bodies must be application/json (a page from another origin cannot
// send those without a preflight, which is never granted) and at most
// max_body bytes; command text at most max_text characters. Replies are JSON
// with "ok"; failures carry "message" and a 4xx/5xx status.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "command/navdb.h"
#include "core/status.h"
#include "serve/geography.h"
#include "serve/live_sim.h"

namespace httplib {
class Server;
}

namespace squawk::serve {

struct ServerOptions {
  std::string host = "127.0.0.1";  // listen address (all interfaces only when asked)
  std::vector<std::string> allowed_hosts;  // Host names answered besides the loopback ones
  int port = 8080;                 // 0: any free port
  std::string web_dir;             // static files of the page
  size_t max_body = 16 * 1024;     // [bytes] request body limit
  size_t max_text = 1000;          // [chars] command text limit
  int max_streams = 16;            // concurrent push streams
  int threads = 32;                // HTTP worker threads (each stream holds one)
  int command_timeout_s = 120;     // [s] waiting for the owner thread (LLM translation)
};

class HttpServer {
 public:
  // `geo` (may be null: no coastlines or borders) outlives the server.
  HttpServer(LiveSim& live, const command::NavDb* navdb, ServerOptions options, const Geography* geo = nullptr);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  // Binds; returns the port (useful with port 0). Error names the address.
  Result<int> bind();
  // Serves until stop() (from another thread). Error when listening failed.
  Status listen();
  void stop();

 private:
  void routes();
  LiveSim& live_;
  const command::NavDb* navdb_;
  ServerOptions options_;
  const Geography* geo_;
  std::unique_ptr<httplib::Server> server_;
  std::atomic<int> streams_{0};
};

}  // namespace squawk::serve
