// squawk serve: the radar scope. The simulation runs live on the server
// (serve/live_sim.h); the page (web/) and the HTTP API (serve/http_server.h)
// read its published state and post commands to it.
#include <signal.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

#include "app/cli.h"
#include "app/scope_teammate.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/paths.h"
#include "core/text.h"
#include "script/serve_session.h"
#include "serve/http_server.h"
#include "serve/live_sim.h"

namespace squawk::app {

namespace {
volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_stop_signal(int) { g_stop = 1; }
}  // namespace

int cmd_serve(const ArgV& argv) {
  Args::Spec spec = with_vm_flags({{"--port", "--host", "--allow-host", "--mode", "--speed", "--web", "--policy", "--checkpoint"},
                                      {"--paused", "--auto", "--agent"}});
  auto args = Args::parse(argv, spec);
  if (!args) return usage_error("serve", args.status().message());
  if (args->positional().size() > 1) return usage_error("serve", "expected at most one SCENARIO");
  auto vmo = vm_options(*args);
  if (!vmo) return usage_error("serve", vmo.status().message());
  vmo->max_instructions = 0;  // a live session has no instruction budget

  serve::ServerOptions so;
  so.host = args->get_or("--host", "127.0.0.1");
  if (auto names = args->get("--allow-host"))
    for (const auto& n : text::split(*names, ','))
      if (!n.empty()) so.allowed_hosts.push_back(n);
  const std::string port = args->get_or("--port", "8080");
  char* end = nullptr;
  const long p = std::strtol(port.c_str(), &end, 10);
  if (port.empty() || *end != '\0' || p < 0 || p > 65535)
    return usage_error("serve", "--port '" + port + "': expected a port number 0..65535 (0: any free port)");
  so.port = static_cast<int>(p);
  so.web_dir = args->get_or("--web", paths::resource("web"));
  const std::string speed = args->get_or("--speed", "1");
  const double mult = std::strtod(speed.c_str(), &end);
  if (speed.empty() || *end != '\0' || !(mult > 0 && mult <= 1000))
    return usage_error("serve", "--speed '" + speed + "': expected a multiple of real time in (0, 1000]");

  auto named = named_scenario(*args, *vmo);
  if (!named) return failure(named.status());
  const std::string& scenario = *named;
  script::Vm vm(*vmo);
  auto session = script::ServeSession::open(vm, scenario, args->get_or("--mode", ""));
  if (!session) return failure(session.status());
  command::Stack& stack = (*session)->stack();
  if (!args->has("--paused")) stack.sim().op();  // OP sets DTMULT 1: the speed comes after
  stack.set_dtmult(mult);

  std::unique_ptr<ScopeTeammate> teammate;
  if (args->has("--agent")) {
    TeammateOptions to;
    to.policy = args->get_or("--policy", "mlp");
    to.checkpoint = args->get_or("--checkpoint", "");
    auto made = ScopeTeammate::make(to, *vmo);
    if (!made) return failure(made.status());
    teammate = std::move(*made);
    if (Status st = teammate->start(stack); !st.is_ok()) return failure(st);
  } else if (args->has("--policy") || args->has("--checkpoint") || args->has("--auto")) {
    return usage_error("serve", "--policy, --checkpoint and --auto go with --agent");
  }

  serve::LiveOptions lo;
  lo.auto_advisories = args->has("--auto");
  serve::LiveSim live(**session, lo, teammate.get());
  // Coastlines and FIR borders come from the navdata folder, when one is given.
  serve::Geography geo;
  if (!vmo->navdata_dir.empty()) {
    auto g = serve::Geography::load(vmo->navdata_dir);
    if (!g) return failure(g.status());
    geo = std::move(*g);
  }
  serve::HttpServer server(live, stack.navdb(), so, &geo);
  auto bound = server.bind();
  if (!bound) return failure(bound.status());

  // SIGINT / SIGTERM set a flag (whichever thread receives them, library
  // threads included); a watcher thread stops the server when it is set.
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  live.start();
  std::atomic<bool> done{false};
  std::thread watcher([&] {
    while (!g_stop && !done) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    live.stop();
    server.stop();
  });
  std::printf("squawk serve: http://%s:%d/  (%s, %zu aircraft; Ctrl-C stops)\n", so.host.c_str(), *bound,
              scenario.empty() ? "no scenario" : scenario.c_str(), static_cast<size_t>(stack.sim().n()));
  std::fflush(stdout);
  Status st = server.listen();
  done = true;
  watcher.join();
  return st.is_ok() ? kExitOk : failure(st);
}

}  // namespace squawk::app
