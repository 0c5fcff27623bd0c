// `simswift run` with game: {udp: on}, as a user runs it: a bad value exits
// 2 naming file, line and field; a good run sends the GameController packets
// a plain UDP listener hears, and says so in its summary.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Result {
  int code = -1;
  std::string out;  // stdout and stderr
};

Result run(const std::string& scenario) {
  const std::string cmd = std::string(SIMSWIFT_BINARY_DIR) + "/simswift run " + scenario + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  Result r;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) r.out += buf;
  const int st = pclose(p);
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return r;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("simswift_cli_udp_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

const std::string kOne = "duration: 1\nnoise: off\nrobots:\n  - {team: 19, player: 1, x: -1, y: 0}\n";

}  // namespace

TEST(CliGameUdp, BadValueExitsTwoNamingFileLineAndField) {
  const std::string s = write("bad_udp.yaml", kOne + "game: {udp: on, return_port: 3838}\n");
  const Result r = run(s);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find(s + ":5: game.return_port: must differ from port"), std::string::npos) << r.out;
}

TEST(CliGameUdp, RunSendsPacketsAListenerHears) {
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  socklen_t len = sizeof a;
  getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  const std::string s = write("udp.yaml", kOne + "game: {udp: on, return_port: 0, port: " +
                                              std::to_string(ntohs(a.sin_port)) + "}\n");
  const Result r = run(s);
  EXPECT_EQ(r.code, 0) << r.out;
  // t = 0, 0.5 and 1 s of simulated time.
  EXPECT_NE(r.out.find("| gc udp 3 sent |"), std::string::npos) << r.out;
  int heard = 0;
  unsigned char buf[1024];
  ssize_t n;
  while ((n = recv(fd, buf, sizeof buf, MSG_DONTWAIT)) >= 0) {
    EXPECT_EQ(n, 588);
    EXPECT_EQ(std::string(reinterpret_cast<char*>(buf), 4), "RGme");
    ++heard;
  }
  EXPECT_EQ(heard, 3);
  close(fd);
}
