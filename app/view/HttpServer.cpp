#include "app/view/HttpServer.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <list>
#include <stdexcept>
#include <thread>

namespace simswift::view {

namespace {

volatile std::sig_atomic_t g_stop = 0;
void onSignal(int) { g_stop = 1; }

constexpr int kClientTimeoutS = 5;   // s: a client that stalls mid-request or mid-answer is dropped
constexpr int kMaxConnections = 32;  // open at once

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

ParsedRequest refuse(int status, std::string why) {
  ParsedRequest p;
  p.status = status;
  p.error = std::move(why);
  return p;
}

bool sendAll(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::send(fd, data.data(), data.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace

bool percentDecode(std::string_view s, bool plus, std::string& out) {
  out.clear();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%') {
      if (i + 2 >= s.size()) return false;
      const int hi = hexDigit(s[i + 1]), lo = hexDigit(s[i + 2]);
      if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) return false;
      out += static_cast<char>(hi * 16 + lo);
      i += 2;
    } else if (plus && s[i] == '+') {
      out += ' ';
    } else {
      out += s[i];
    }
  }
  return true;
}

const char* statusText(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 414: return "URI Too Long";
    case 431: return "Request Header Fields Too Large";
    case 500: return "Internal Server Error";
    case 505: return "HTTP Version Not Supported";
    default: return "Error";
  }
}

ParsedRequest parseRequest(std::string_view head) {
  if (head.size() > kMaxHead) return refuse(431, "request head over " + std::to_string(kMaxHead) + " bytes");
  const std::size_t eol = head.find("\r\n");
  if (eol == std::string_view::npos) return refuse(400, "no request line");
  const std::string_view line = head.substr(0, eol);
  const std::size_t sp1 = line.find(' ');
  const std::size_t sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
  if (sp2 == std::string_view::npos || line.find(' ', sp2 + 1) != std::string_view::npos)
    return refuse(400, "the request line is not METHOD TARGET VERSION");
  const std::string_view method = line.substr(0, sp1), target = line.substr(sp1 + 1, sp2 - sp1 - 1),
                         version = line.substr(sp2 + 1);
  if (version != "HTTP/1.1" && version != "HTTP/1.0") return refuse(505, "HTTP/1.0 or 1.1 only");
  if (method != "GET" && method != "HEAD") return refuse(405, "GET and HEAD only");
  if (target.empty() || target[0] != '/') return refuse(400, "the target is not an absolute path");
  for (const char c : target)
    if (static_cast<unsigned char>(c) <= 0x20 || static_cast<unsigned char>(c) >= 0x7F)
      return refuse(400, "a control or non-ASCII byte in the target");
  ParsedRequest p;
  p.request.method = std::string(method);
  const std::size_t q = target.find('?');
  if (!percentDecode(target.substr(0, q), false, p.request.path)) return refuse(400, "a bad %-escape in the path");
  if (q != std::string_view::npos) {
    std::string_view rest = target.substr(q + 1);
    const std::size_t hash = rest.find('#');
    if (hash != std::string_view::npos) rest = rest.substr(0, hash);
    while (!rest.empty()) {
      const std::size_t amp = rest.find('&');
      const std::string_view pair = rest.substr(0, amp);
      rest = amp == std::string_view::npos ? std::string_view() : rest.substr(amp + 1);
      if (pair.empty()) continue;
      const std::size_t eq = pair.find('=');
      std::string key, value;
      if (!percentDecode(pair.substr(0, eq), true, key) ||
          (eq != std::string_view::npos && !percentDecode(pair.substr(eq + 1), true, value)))
        return refuse(400, "a bad %-escape in the query");
      p.request.query[key] = value;
    }
  }
  return p;
}

HttpServer::HttpServer(int port) {
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) throw std::runtime_error(std::string("cannot make a socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // loopback only: never reachable from the network
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(listen_fd_, 16) != 0) {
    const std::string why = std::strerror(errno);
    ::close(listen_fd_);
    throw std::runtime_error("cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + why);
  }
  socklen_t len = sizeof addr;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
}

HttpServer::~HttpServer() {
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

void HttpServer::serve(const Handler& handler) {
  struct sigaction sa {};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  // Each connection's thread sets `done`; the loop joins it and only then
  // closes its fd (so a shutdown below never reaches a reused fd number).
  struct Connection {
    int fd;
    std::atomic<bool> done{false};
    std::thread thread;
  };
  std::list<Connection> open;
  const auto reap = [&open] {
    for (auto it = open.begin(); it != open.end();) {
      if (!it->done) {
        ++it;
        continue;
      }
      it->thread.join();
      ::close(it->fd);
      it = open.erase(it);
    }
  };
  while (!g_stop && !stop_) {
    reap();
    pollfd p{listen_fd_, POLLIN, 0};
    if (::poll(&p, 1, 200) <= 0) continue;  // 200 ms: how soon a signal or stop() is noticed
    const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) continue;
    timeval tv{kClientTimeoutS, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
    // A thread per connection: a browser keeps idle connections open
    // (preconnects), which must not hold up the requests on the others.
    if (open.size() >= static_cast<std::size_t>(kMaxConnections)) {
      ::close(fd);  // more than a page asks for at once: dropped, the browser retries
      continue;
    }
    Connection& c = open.emplace_back();
    c.fd = fd;
    c.thread = std::thread([this, &c, &handler] {
      answer(c.fd, handler);
      c.done = true;
    });
  }
  // A client still to send its request is cut off (its recv ends); answers
  // under way finish (each send bounded by the client timeout). All joined:
  // no thread outlives serve(), its handler or this server.
  for (Connection& c : open) ::shutdown(c.fd, SHUT_RD);
  for (Connection& c : open) {
    c.thread.join();
    ::close(c.fd);
  }
}

void HttpServer::answer(int fd, const Handler& handler) {
  std::string head;
  char buf[4096];
  while (head.find("\r\n\r\n") == std::string::npos) {
    if (head.size() > kMaxHead) break;
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // closed or timed out before a whole head: nothing to answer
    head.append(buf, static_cast<std::size_t>(n));
  }
  const std::size_t end = head.find("\r\n\r\n");
  const ParsedRequest parsed = parseRequest(end == std::string::npos ? std::string_view(head)
                                                                     : std::string_view(head).substr(0, end + 2));
  HttpResponse r;
  if (parsed.status != 0) {
    r.status = parsed.status;
    r.type = "text/plain; charset=utf-8";
    r.body = parsed.error + "\n";
  } else {
    try {
      r = handler(parsed.request);
    } catch (const std::exception& e) {
      r = HttpResponse{500, "text/plain; charset=utf-8", std::string(e.what()) + "\n"};
    }
  }
  std::string out = "HTTP/1.1 " + std::to_string(r.status) + " " + statusText(r.status) + "\r\n";
  out += "Content-Type: " + r.type + "\r\n";
  out += "Content-Length: " + std::to_string(r.body.size()) + "\r\n";
  out += "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n";
  if (r.status == 405) out += "Allow: GET, HEAD\r\n";
  out += "\r\n";
  if (!sendAll(fd, out)) return;
  if (parsed.status != 0 || parsed.request.method != "HEAD") sendAll(fd, r.body);
}

}  // namespace simswift::view
