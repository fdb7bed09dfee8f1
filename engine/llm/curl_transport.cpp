#include "llm/curl_transport.h"

#include <curl/curl.h>

#include <mutex>

namespace squawk::llm {

namespace {

// A local server is never reached through a proxy from http_proxy & co.
constexpr const char* kNoProxy = "localhost,127.0.0.1,::1";

struct Transfer {
  CURL* curl = nullptr;
  const BodySink* sink = nullptr;
  bool aborted = false;
};

size_t on_write(char* data, size_t size, size_t n, void* user) {
  auto* t = static_cast<Transfer*>(user);
  long status = 0;
  curl_easy_getinfo(t->curl, CURLINFO_RESPONSE_CODE, &status);
  if (!(*t->sink)(status, std::string_view(data, size * n))) {
    t->aborted = true;
    return 0;  // tells curl to stop
  }
  return size * n;
}

long to_ms(double s) { return s > 0 ? static_cast<long>(s * 1000.0 + 0.5) : 0; }

}  // namespace

CurlTransport::CurlTransport() {
  static std::once_flag once;
  std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

Result<long> CurlTransport::post(const HttpRequest& request, const BodySink& sink) {
  CURL* curl = curl_easy_init();
  if (!curl) return Status::internal("curl_easy_init failed");
  curl_slist* headers = nullptr;
  for (const auto& h : request.headers) headers = curl_slist_append(headers, h.c_str());
  char errbuf[CURL_ERROR_SIZE] = {0};
  Transfer t{curl, &sink, false};
  curl_easy_setopt(curl, CURLOPT_URL, request.url.c_str());
  curl_easy_setopt(curl, CURLOPT_POST, 1L);
  curl_easy_setopt(curl, CURLOPT_POSTFIELDS, request.body.data());
  curl_easy_setopt(curl, CURLOPT_POSTFIELDSIZE_LARGE, static_cast<curl_off_t>(request.body.size()));
  curl_easy_setopt(curl, CURLOPT_HTTPHEADER, headers);
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);
  curl_easy_setopt(curl, CURLOPT_NOPROXY, kNoProxy);
  curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT_MS, to_ms(request.connect_timeout_s));
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, to_ms(request.timeout_s));
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, on_write);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &t);
  curl_easy_setopt(curl, CURLOPT_ERRORBUFFER, errbuf);
  const CURLcode rc = curl_easy_perform(curl);
  long status = 0;
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &status);
  curl_slist_free_all(headers);
  curl_easy_cleanup(curl);

  if (rc == CURLE_OK || (rc == CURLE_WRITE_ERROR && t.aborted)) return status;
  std::string why = errbuf[0] ? errbuf : curl_easy_strerror(rc);
  std::string msg = "POST ";
  msg.append(request.url).append(": ").append(why);
  if (rc == CURLE_OPERATION_TIMEDOUT) return Status::timeout(msg);
  return Status::unavailable(msg);
}

}  // namespace squawk::llm
