// A small HTTP/1.1 server on the loopback interface for `simswift view`
// (docs/viewer.md): GET and HEAD only, one request per connection
// (Connection: close), each connection on a thread of its own (at most
// 32 at once; the handler must be safe to call from several threads),
// owned by serve(), which joins them all before it returns. Requests are parsed by
// parseRequest (a pure function, tested alone): a bad request line, an
// unknown method, a path that is not absolute, an invalid or NUL %-escape,
// or a head over kMaxHead bytes is refused with its status. The handler
// gets the decoded path and query; what a path may name is its business
// (ViewerSite refuses anything but its own names).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace simswift::view {

struct HttpRequest {
  std::string method;  // GET or HEAD
  std::string path;    // %-decoded, starts with '/'
  std::map<std::string, std::string> query;  // %-decoded ('+' is a space)
};

struct HttpResponse {
  int status = 200;
  std::string type = "application/json";
  std::string body;
};

// The outcome of parsing a request's head (up to and including the blank
// line): status 0 and the request, or the status to refuse it with and why.
struct ParsedRequest {
  int status = 0;
  std::string error;
  HttpRequest request;
};

constexpr std::size_t kMaxHead = 16 * 1024;  // bytes: a request head longer is refused (431)

ParsedRequest parseRequest(std::string_view head);
// %-decodes `s` ('+' as a space if `plus`); false on a bad or NUL escape.
bool percentDecode(std::string_view s, bool plus, std::string& out);
const char* statusText(int status);

class HttpServer {
 public:
  using Handler = std::function<HttpResponse(const HttpRequest&)>;
  // Listens on 127.0.0.1:`port` (0: any free port); std::runtime_error if it cannot.
  explicit HttpServer(int port);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  int port() const { return port_; }
  // Serves until SIGINT or SIGTERM (installed here) or stop(); returns
  // once every connection's thread has ended (an answer under way is
  // finished, a client that has not sent its request is cut off).
  void serve(const Handler& handler);
  // Ends serve() (from any thread, e.g. a test's).
  void stop() { stop_ = true; }

 private:
  void answer(int fd, const Handler& handler);
  int listen_fd_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
};

}  // namespace simswift::view
