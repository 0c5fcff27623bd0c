// The viewer's server (app/view/HttpServer.hpp, ViewerSite.hpp): requests
// parsed and refused by the rules, only the viewer's own names served (no
// path leads out of its folder), the recording's messages by time.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

#include "app/view/HttpServer.hpp"
#include "app/view/Mcap.hpp"
#include "app/view/ViewerSite.hpp"
#include "tests/support/Sockets.hpp"

namespace simswift::view {
namespace {

// This process's threads (/proc/self/task).
int threadCount() {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator("/proc/self/task")) n += e.exists() ? 1 : 0;
  return n;
}

// The thread count once it is down to `n`, waiting up to 1 s (a joined
// thread may stay listed a moment while the kernel ends it).
int threadCountDownTo(int n) {
  for (int i = 0; i < 100 && threadCount() > n; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return threadCount();
}

// The server owns its connections' threads: stopped with a client that
// never sends its request, serve() returns at once (not after the 5 s
// client timeout) and leaves no thread running that could reach the
// handler or the server once they are gone (ASan in CI).
TEST(HttpServerRun, StopsWithAConnectionOpenAndLeavesNoThreadRunning) {
  const int before = threadCount();
  {
    auto server = std::make_unique<HttpServer>(0);
    const HttpServer::Handler echo = [](const HttpRequest& r) { return HttpResponse{200, "text/plain", r.path}; };
    std::thread serving([&] { server->serve(echo); });
    const int idle = simswift::testing::connectLoopback(server->port());
    ASSERT_GE(idle, 0);
    // A whole request answered: the idle connection, accepted first, has its thread.
    const int fd = simswift::testing::connectLoopback(server->port());
    ASSERT_TRUE(simswift::testing::writeAll(fd, "GET /x HTTP/1.1\r\n\r\n"));
    const std::string answer = simswift::testing::readToEnd(fd);
    ::close(fd);
    EXPECT_EQ(answer.rfind("HTTP/1.1 200", 0), 0u) << answer;
    EXPECT_GT(threadCount(), before + 1);  // serving and the idle connection's thread
    const auto t0 = std::chrono::steady_clock::now();
    server->stop();
    serving.join();
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2));
    EXPECT_EQ(threadCountDownTo(before), before);
    server.reset();
    char c;
    EXPECT_EQ(::recv(idle, &c, 1, 0), 0);  // the server closed it
    ::close(idle);
  }
  EXPECT_EQ(threadCountDownTo(before), before);
}

TEST(HttpRequest, ParsesPathAndQuery) {
  const ParsedRequest p = parseRequest("GET /api/at?topic=%2Frobot0%2Fjoints&t=15&x+y=a+b HTTP/1.1\r\nHost: h\r\n\r\n");
  ASSERT_EQ(p.status, 0) << p.error;
  EXPECT_EQ(p.request.path, "/api/at");
  EXPECT_EQ(p.request.query.at("topic"), "/robot0/joints");
  EXPECT_EQ(p.request.query.at("t"), "15");
  EXPECT_EQ(p.request.query.at("x y"), "a b");
}

TEST(HttpRequest, RefusesBadRequests) {
  EXPECT_EQ(parseRequest("POST / HTTP/1.1\r\n\r\n").status, 405);
  EXPECT_EQ(parseRequest("GET / HTTP/2.0\r\n\r\n").status, 505);
  EXPECT_EQ(parseRequest("GET http://x/ HTTP/1.1\r\n\r\n").status, 400);
  EXPECT_EQ(parseRequest("GET /a%2 HTTP/1.1\r\n\r\n").status, 400);
  EXPECT_EQ(parseRequest("GET /a%00b HTTP/1.1\r\n\r\n").status, 400);
  EXPECT_EQ(parseRequest("GET /?q=%zz HTTP/1.1\r\n\r\n").status, 400);
  EXPECT_EQ(parseRequest("GET  / HTTP/1.1\r\n\r\n").status, 400);
  EXPECT_EQ(parseRequest("garbage").status, 400);
  EXPECT_EQ(parseRequest("GET /" + std::string(kMaxHead, 'a') + " HTTP/1.1\r\n\r\n").status, 431);
}

class Site : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("simswift-view-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_ / "viewer");
    std::ofstream(dir_ / "viewer" / "index.html") << "<html>page</html>";
    std::ofstream(dir_ / "viewer" / "viewer.js") << "// js";
    std::ofstream(dir_ / "secret.txt") << "secret";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  HttpResponse get(const ViewerSite& site, const std::string& target) {
    const ParsedRequest p = parseRequest("GET " + target + " HTTP/1.1\r\n\r\n");
    if (p.status != 0) return HttpResponse{p.status, "", p.error};
    return site.handle(p.request);
  }
  std::filesystem::path dir_;
};

// A recording with /tf at 0, 10, ..., 90 ns.
McapFile tenMessages() {
  auto str = [](const std::string& s) {
    std::string b(4, '\0');
    for (int i = 0; i < 4; ++i) b[i] = static_cast<char>((s.size() >> (8 * i)) & 0xFF);
    return b + s;
  };
  auto le = [](std::uint64_t v, int n) {
    std::string b;
    for (int i = 0; i < n; ++i) b += static_cast<char>((v >> (8 * i)) & 0xFF);
    return b;
  };
  auto rec = [&](int op, const std::string& c) { return std::string(1, static_cast<char>(op)) + le(c.size(), 8) + c; };
  const std::string magic("\x89MCAP0\r\n", 8);
  std::string f = magic + rec(1, str("") + str("t")) + rec(3, le(1, 2) + str("foxglove.FrameTransforms") + str("jsonschema") + str("{}")) +
                  rec(4, le(1, 2) + le(1, 2) + str("/tf") + str("json") + le(0, 4));
  for (int k = 0; k < 10; ++k) f += rec(5, le(1, 2) + le(k, 4) + le(10 * k, 8) + le(10 * k, 8) + "{\"k\":" + std::to_string(k) + "}");
  f += rec(0x0F, le(0, 4)) + rec(2, le(0, 8) + le(0, 8) + le(0, 4)) + magic;
  return McapFile::parse(f, "ten.mcap");
}

TEST_F(Site, ServesOnlyItsOwnNames) {
  const McapFile f = tenMessages();
  const ViewerSite site(f, (dir_ / "viewer").string(), (dir_ / "no-three").string());
  EXPECT_EQ(get(site, "/").body, "<html>page</html>");
  EXPECT_EQ(get(site, "/viewer/viewer.js").status, 200);
  EXPECT_EQ(get(site, "/viewer/viewer.js").type.rfind("text/javascript", 0), 0u);
  for (const char* bad : {"/viewer/../secret.txt", "/viewer/..%2Fsecret.txt", "/viewer/%2e%2e/secret.txt",
                          "/viewer/.hidden", "/viewer/", "/secret.txt", "/viewer//etc/passwd", "/three/../../secret.txt"}) {
    const HttpResponse r = get(site, bad);
    EXPECT_EQ(r.status, 404) << bad;
    EXPECT_EQ(r.body.find("secret\n"), std::string::npos) << bad;
  }
  EXPECT_EQ(get(site, "/three/three.min.js").status, 404);  // not installed in this test's folder
}

TEST_F(Site, AnswersMessagesByTime) {
  const McapFile f = tenMessages();
  const ViewerSite site(f, (dir_ / "viewer").string(), "");
  EXPECT_EQ(get(site, "/api/at?topic=/tf&t=25").body, "{\"t\":20,\"data\":{\"k\":2}}");
  EXPECT_EQ(get(site, "/api/at?topic=/tf&t=0").body, "{\"t\":0,\"data\":{\"k\":0}}");
  EXPECT_EQ(get(site, "/api/messages?topic=/tf&from=20&to=40").body,
            "{\"topic\":\"/tf\",\"total\":3,\"messages\":[{\"t\":20,\"data\":{\"k\":2}},{\"t\":30,\"data\":{\"k\":3}},"
            "{\"t\":40,\"data\":{\"k\":4}}]}");
  // Thinned evenly, first and last kept.
  EXPECT_EQ(get(site, "/api/messages?topic=/tf&max=3").body,
            "{\"topic\":\"/tf\",\"total\":10,\"messages\":[{\"t\":0,\"data\":{\"k\":0}},{\"t\":40,\"data\":{\"k\":4}},"
            "{\"t\":90,\"data\":{\"k\":9}}]}");
  const std::string info = get(site, "/api/info").body;
  EXPECT_NE(info.find("\"end_ns\":90"), std::string::npos) << info;
  EXPECT_NE(info.find("{\"topic\":\"/tf\",\"encoding\":\"json\",\"schema\":\"foxglove.FrameTransforms\",\"count\":10"),
            std::string::npos) << info;
  EXPECT_EQ(get(site, "/api/at?topic=/nope&t=1").status, 404);
  EXPECT_EQ(get(site, "/api/at?topic=/tf").status, 400);
  EXPECT_EQ(get(site, "/api/at?topic=/tf&t=-1").status, 400);
  EXPECT_EQ(get(site, "/api/messages?topic=/tf&max=0").status, 400);
  EXPECT_EQ(get(site, "/api/messages?topic=/tf&from=99999999999999999999999").status, 400);
  EXPECT_EQ(get(site, "/api/nothing").status, 404);
}

}  // namespace
}  // namespace simswift::view
