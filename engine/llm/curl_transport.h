// CurlTransport: HttpTransport over libcurl (the only code that includes
// curl.h). One easy handle per request, no signals, both timeouts enforced.
// The usual proxy variables apply, except to localhost / 127.0.0.1 / ::1.
#pragma once

#include "llm/http_transport.h"

namespace squawk::llm {

class CurlTransport : public HttpTransport {
 public:
  CurlTransport();
  Result<long> post(const HttpRequest& request, const BodySink& sink) override;
};

}  // namespace squawk::llm
