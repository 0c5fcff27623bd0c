// `simswift view` as a user runs it (app/view/ViewCommand.hpp): a bad
// recording or option exits 2 with a message naming the file and byte or
// the option; a good one is served on 127.0.0.1, and raw requests over a
// socket (no client normalising the path) cannot leave the viewer's folder.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/Shell.hpp"
#include "tests/support/Sockets.hpp"
#include "tests/view/McapBytes.hpp"

namespace simswift::view {
namespace {

using namespace testing;
using simswift::testing::shell;

const std::string kSimswift = SIMSWIFT_BINARY_DIR "/simswift";

class ViewCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("simswift-view-cmd-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    good_ = (dir_ / "good.mcap").string();
    std::ofstream(good_, std::ios::binary)
        << kMagic + header() + schema(1) + channel(1, 1, "/tf") + message(1, 0, "{\"k\":0}") +
               message(1, 2000000000, "{\"k\":1}") + tail();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
  std::string good_;
};

TEST_F(ViewCommand, ABadRecordingOrOptionExitsTwoNamingWhere) {
  const std::string cut = (dir_ / "cut.mcap").string();
  std::filesystem::copy_file(good_, cut);
  std::filesystem::resize_file(cut, std::filesystem::file_size(good_) - 20);
  auto r = shell(kSimswift + " view " + cut + " --no-browser");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(cut + ": byte "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("truncated"), std::string::npos) << r.output;
  r = shell(kSimswift + " view " + good_ + " --no-browser --at 2.5");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--at 2.5 is after the recording's end (2.000 s)"), std::string::npos) << r.output;
  r = shell(kSimswift + " view " + good_ + " --no-browser --port 70000");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--port"), std::string::npos) << r.output;
}

// One raw request to 127.0.0.1:port; the whole answer.
std::string request(int port, const std::string& raw) {
  const int fd = simswift::testing::connectLoopback(port);
  if (fd < 0) return "";
  simswift::testing::writeAll(fd, raw);
  const std::string out = simswift::testing::readToEnd(fd);
  ::close(fd);
  return out;
}

TEST_F(ViewCommand, ServesTheRecordingOnLoopbackAndNothingElseOfTheDisk) {
  int out[2];
  ASSERT_EQ(::pipe(out), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::dup2(out[1], 1);
    ::execl(kSimswift.c_str(), kSimswift.c_str(), "view", good_.c_str(), "--no-browser", "--at", "1",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(out[1]);
  std::string line;
  char c;
  while (::read(out[0], &c, 1) == 1 && c != '\n') line += c;
  ::close(out[0]);
  const auto at = line.find("http://127.0.0.1:");
  ASSERT_NE(at, std::string::npos) << line;
  const int port = std::stoi(line.substr(at + 17));
  EXPECT_NE(line.find("/?t=1"), std::string::npos) << line;  // --at: the page opens there

  EXPECT_EQ(request(port, "GET /api/at?topic=/tf&t=1999999999 HTTP/1.1\r\n\r\n").find("HTTP/1.1 200"), 0u);
  EXPECT_NE(request(port, "GET /api/at?topic=/tf&t=1999999999 HTTP/1.1\r\n\r\n").find("{\"t\":0,\"data\":{\"k\":0}}"),
            std::string::npos);
  EXPECT_EQ(request(port, "GET / HTTP/1.1\r\n\r\n").find("HTTP/1.1 200"), 0u);
  for (const char* bad : {"GET /../../../../etc/passwd HTTP/1.1\r\n\r\n", "GET /viewer/../../../../../etc/passwd HTTP/1.1\r\n\r\n",
                          "GET /viewer/%2e%2e%2f%2e%2e%2fmodels%2fnao_v5.urdf HTTP/1.1\r\n\r\n"}) {
    const std::string r = request(port, bad);
    EXPECT_EQ(r.find("HTTP/1.1 404"), 0u) << bad << r;
    EXPECT_EQ(r.find("root:"), std::string::npos) << bad;
  }
  EXPECT_EQ(request(port, "DELETE / HTTP/1.1\r\n\r\n").find("HTTP/1.1 405"), 0u);
  EXPECT_EQ(request(port, "\r\n\r\n").find("HTTP/1.1 400"), 0u);
  // A client that connects and sends nothing does not hold up the others.
  const int idle = simswift::testing::connectLoopback(port);
  ASSERT_GE(idle, 0);
  EXPECT_EQ(request(port, "GET /api/info HTTP/1.1\r\n\r\n").find("HTTP/1.1 200"), 0u);
  ::close(idle);

  ::kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

}  // namespace
}  // namespace simswift::view
