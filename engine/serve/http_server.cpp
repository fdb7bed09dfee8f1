#include "serve/http_server.h"

#include <httplib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "core/text.h"
#include "serve/state_json.h"

namespace squawk::serve {

namespace {

using nlohmann::json;

// Messages may quote request bytes (path, Host, query) that are not UTF-8:
// those bytes are written as U+FFFD instead of failing the reply.
void send_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(body.dump(-1, ' ', false, json::error_handler_t::replace), "application/json");
}

void fail(httplib::Response& res, int status, const std::string& message) {
  send_json(res, status, {{"ok", false}, {"message", message}});
}

int http_status(const Status& st) {
  switch (st.code()) {
    case Code::kUnavailable: return 503;
    case Code::kTimeout: return 504;
    default: return 500;
  }
}

// The JSON object of a POST body, or an error naming what was wrong.
Result<json> json_body(const httplib::Request& req) {
  const std::string type = req.get_header_value("Content-Type");
  if (type.rfind("application/json", 0) != 0)
    return Status::invalid("Content-Type '" + type + "': expected application/json");
  json j = json::parse(req.body, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) return Status::invalid("body: expected a JSON object");
  return j;
}

// Query parameter `name` as a finite number, or `fallback` when absent.
Result<double> number_param(const httplib::Request& req, const char* name, double fallback) {
  if (!req.has_param(name)) return fallback;
  const std::string v = req.get_param_value(name);
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(d))
    return Status::invalid(std::string(name) + "='" + v + "': expected a number of degrees");
  return d;
}

}  // namespace

HttpServer::HttpServer(LiveSim& live, const command::NavDb* navdb, ServerOptions options, const Geography* geo)
    : live_(live), navdb_(navdb), options_(std::move(options)), geo_(geo), server_(std::make_unique<httplib::Server>()) {
  const int threads = options_.threads;
  server_->new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<size_t>(threads)); };
  // SO_REUSEADDR only: the library's default adds SO_REUSEPORT, which would
  // let a second server share the port and take half of the connections.
  server_->set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  server_->set_payload_max_length(options_.max_body);
  server_->set_read_timeout(5, 0);
  server_->set_write_timeout(5, 0);
  routes();
}

HttpServer::~HttpServer() = default;

Result<int> HttpServer::bind() {
  if (!options_.web_dir.empty() && !server_->set_mount_point("/", options_.web_dir))
    return Status::not_found("web folder '" + options_.web_dir + "' does not exist");
  const std::string where = options_.host + ":" + std::to_string(options_.port);
  if (options_.port == 0) {
    const int port = server_->bind_to_any_port(options_.host);
    if (port < 0) return Status::unavailable("cannot listen on " + options_.host + " (any port)");
    return port;
  }
  if (!server_->bind_to_port(options_.host, options_.port))
    return Status::unavailable("cannot listen on " + where + " (in use, or not an address of this machine)");
  return options_.port;
}

Status HttpServer::listen() {
  if (!server_->listen_after_bind()) return Status::io_error("the HTTP server stopped with an error");
  return Status::ok();
}

void HttpServer::stop() { server_->stop(); }

void HttpServer::routes() {
  httplib::Server& s = *server_;
  const auto command_timeout = std::chrono::seconds(options_.command_timeout_s);

  // The server answers only requests addressed to a loopback name or an
  // allowed one, whatever it listens on, so a web page whose domain
  // re-resolves to this machine (DNS rebinding) cannot read the state or
  // send commands.
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    std::string host = req.get_header_value("Host");
    host = host.substr(0, host.rfind(':') == std::string::npos || host.back() == ']' ? host.size() : host.rfind(':'));
    for (char& c : host) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (host == "127.0.0.1" || host == "localhost" || host == "[::1]") return httplib::Server::HandlerResponse::Unhandled;
    for (const auto& name : options_.allowed_hosts)
      if (text::iequals(host, name)) return httplib::Server::HandlerResponse::Unhandled;
    fail(res, 403, "Host '" + req.get_header_value("Host") +
                       "': this server answers 127.0.0.1, localhost and names given with --allow-host only");
    return httplib::Server::HandlerResponse::Handled;
  });

  s.Get("/api/state", [this](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_content(*live_.state().second, "application/json");
  });

  s.Get("/api/stream", [this](const httplib::Request&, httplib::Response& res) {
    if (streams_.fetch_add(1) >= options_.max_streams) {
      streams_.fetch_sub(1);
      fail(res, 503, "too many open streams (" + std::to_string(options_.max_streams) + ")");
      return;
    }
    res.set_header("Cache-Control", "no-store");
    auto seen = std::make_shared<uint64_t>(0);
    res.set_chunked_content_provider(
        "text/event-stream",
        [this, seen](size_t, httplib::DataSink& sink) {
          auto [version, text] = live_.wait_state(*seen, std::chrono::seconds(2));
          if (live_.stopping()) return false;
          if (version == *seen) {
            static const std::string keepalive = ": keep-alive\n\n";
            return sink.write(keepalive.data(), keepalive.size());
          }
          *seen = version;
          const std::string event = "data: " + *text + "\n\n";
          return sink.write(event.data(), event.size());
        },
        [this](bool) { streams_.fetch_sub(1); });
  });

  // The box of a request's south/north/west/east parameters (absent: the world).
  const auto box_of = [](const httplib::Request& req) -> Result<GeoBox> {
    GeoBox box;
    for (auto [name, field] : {std::pair{"south", &box.lat0}, std::pair{"north", &box.lat1},
                               std::pair{"west", &box.lon0}, std::pair{"east", &box.lon1}}) {
      auto v = number_param(req, name, *field);
      if (!v) return v.status();
      *field = *v;
    }
    return box;
  };

  s.Get("/api/navdata", [this, box_of](const httplib::Request& req, httplib::Response& res) {
    auto box = box_of(req);
    if (!box) return fail(res, 400, box.status().message());
    NavKinds kinds;
    if (req.has_param("kinds")) {
      const std::string k = "," + req.get_param_value("kinds") + ",";
      kinds = {k.find(",airports,") != std::string::npos, k.find(",navaids,") != std::string::npos,
               k.find(",fixes,") != std::string::npos};
    }
    send_json(res, 200, navdata_json(navdb_, *box, 4000, kinds));
  });

  s.Get("/api/geo", [this, box_of](const httplib::Request& req, httplib::Response& res) {
    auto box = box_of(req);
    if (!box) return fail(res, 400, box.status().message());
    auto step = number_param(req, "step", 0.01);
    if (!step) return fail(res, 400, step.status().message());
    if (!geo_) return send_json(res, 200, {{"coast", json::array()}, {"fir", json::array()}, {"truncated", false}});
    send_json(res, 200, geo_->in_box(*box, std::max(0.0, *step)));
  });

  s.Post("/api/command", [this, command_timeout](const httplib::Request& req, httplib::Response& res) {
    auto body = json_body(req);
    if (!body) return fail(res, 400, body.status().message());
    if (!body->contains("text") || !(*body)["text"].is_string())
      return fail(res, 400, "body: expected {\"text\": \"English or !TrafScript\"}");
    std::string text = (*body)["text"].get<std::string>();
    if (text.size() > options_.max_text)
      return fail(res, 413, "text of " + std::to_string(text.size()) + " characters: at most " +
                                std::to_string(options_.max_text));
    script::CommandOptions opts;
    for (auto [name, field] : {std::pair{"client", &opts.client}, std::pair{"selected", &opts.selected}}) {
      if (!body->contains(name)) continue;
      const json& v = (*body)[name];
      if (!v.is_string() || v.get<std::string>().size() > 64)
        return fail(res, 400, std::string("body: \"") + name + "\" must be a string of at most 64 characters");
      *field = v.get<std::string>();
    }
    auto r = live_.call([text, opts](LiveSim& l) { return l.command(text, "controller", opts); }, command_timeout);
    if (!r) return fail(res, http_status(r.status()), r.status().message());
    send_json(res, 200, *r);
  });

  s.Post("/api/advisory", [this](const httplib::Request& req, httplib::Response& res) {
    auto body = json_body(req);
    if (!body) return fail(res, 400, body.status().message());
    const json& b = *body;
    if (!b.contains("id") || !b["id"].is_number_integer() || !b.contains("decision") || !b["decision"].is_string() ||
        (b["decision"] != "accept" && b["decision"] != "reject"))
      return fail(res, 400, "body: expected {\"id\": N, \"decision\": \"accept\" or \"reject\"}");
    const int64_t id64 = b["id"].get<int64_t>();
    if (id64 < 0 || id64 > std::numeric_limits<int>::max())
      return fail(res, 400, "body: \"id\" " + b["id"].dump() + " is not an advisory id (0.." +
                                std::to_string(std::numeric_limits<int>::max()) + ")");
    const int id = static_cast<int>(id64);
    const bool accept = b["decision"] == "accept";
    auto r = live_.call([id, accept](LiveSim& l) { return l.decide(id, accept, "controller"); },
                        std::chrono::seconds(options_.command_timeout_s));
    if (!r) return fail(res, http_status(r.status()), r.status().message());
    send_json(res, (*r)["ok"].get<bool>() ? 200 : 409, *r);
  });

  s.Post("/api/auto", [this](const httplib::Request& req, httplib::Response& res) {
    auto body = json_body(req);
    if (!body) return fail(res, 400, body.status().message());
    if (!body->contains("on") || !(*body)["on"].is_boolean()) return fail(res, 400, "body: expected {\"on\": true|false}");
    const bool on = (*body)["on"].get<bool>();
    auto r = live_.call(
        [on](LiveSim& l) {
          l.set_auto(on);
          return json{{"ok", true}, {"auto", on}};
        },
        std::chrono::seconds(10));
    if (!r) return fail(res, http_status(r.status()), r.status().message());
    send_json(res, 200, *r);
  });

  s.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (res.body.empty() && req.path.rfind("/api/", 0) == 0)
      send_json(res, res.status, {{"ok", false}, {"message", "HTTP " + std::to_string(res.status) + " for " + req.path}});
  });
}

}  // namespace squawk::serve
