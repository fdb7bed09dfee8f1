// HttpTransport: the small wall between the LLM clients and the network.
//
// Contract: post() sends one HTTP/1.1 POST and hands every received body
// chunk, together with the response status code, to `sink` as it arrives
// (so streaming replies are seen token by token). The sink returns false to
// abort the transfer. post() returns the final status code, or a non-ok
// Status for transport failures only (connection refused: kUnavailable,
// deadline passed: kTimeout); an HTTP error status is not a transport
// failure. The production implementation is CurlTransport; tests talk to a
// loopback server through the same code.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/status.h"

namespace squawk::llm {

struct HttpRequest {
  std::string url;                   // absolute http(s) URL
  std::string body;                  // request body (JSON)
  std::vector<std::string> headers;  // "Name: value"
  double connect_timeout_s = 5.0;    // [s] to establish the connection
  double timeout_s = 120.0;          // [s] for the whole exchange
};

// Receives (HTTP status, next body bytes); returns false to abort.
using BodySink = std::function<bool(long status, std::string_view chunk)>;

class HttpTransport {
 public:
  virtual ~HttpTransport() = default;
  // Returns the HTTP status code of the response.
  virtual Result<long> post(const HttpRequest& request, const BodySink& sink) = 0;
};

}  // namespace squawk::llm
