#include "app/view/ViewCommand.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/cli/CommandLine.hpp"
#include "app/view/HttpServer.hpp"
#include "app/view/Mcap.hpp"
#include "app/view/ViewerSite.hpp"
#include "sim/runner/RunStats.hpp"
#include "sim/runner/Scenario.hpp"

namespace simswift::view {

namespace {

// Opens `url` in the desktop's browser (xdg-open, detached); false if it cannot start.
bool openBrowser(const std::string& url) {
  std::signal(SIGCHLD, SIG_IGN);  // xdg-open is reaped by the kernel: not waited for
  const pid_t pid = ::fork();
  if (pid < 0) return false;
  if (pid == 0) {
    ::setsid();
    const int null = ::open("/dev/null", O_RDWR);
    if (null >= 0) {
      ::dup2(null, 0);
      ::dup2(null, 1);
      ::dup2(null, 2);
    }
    ::execlp("xdg-open", "xdg-open", url.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return true;  // xdg-open's own outcome is not waited for: it may block until the browser exits
}

}  // namespace

ViewCommand::ViewCommand(CLI::App& parent) {
  cmd_ = parent.add_subcommand("view", "replay a recording (MCAP) in the browser");
  cmd_->footer(
      "Serves a page on 127.0.0.1 that replays FILE.mcap (`simswift run --record FILE.mcap`):\n"
      "the field in 3D, a timeline with the run's events, each robot's joints, sensors and\n"
      "beliefs (docs/viewer.md). Prints the page's address and opens it in the browser;\n"
      "Ctrl-C stops it.\n"
      "\n"
      "Exit codes: 0 stopped; 1 the viewer's files, three.js or the port missing;\n"
      "2 bad command line or recording (the message names the file and byte).");
  cmd_->add_option("FILE", file_, "the recording (FILE.mcap)")->type_name("")->required();
  cmd_->add_option("--port", port_, "the port on 127.0.0.1 (default 0: any free one)")
      ->type_name("N")
      ->transform(cli::number(0, 65535, true));
  cmd_->add_flag("--no-browser", no_browser_, "print the address only (CI, a remote shell)");
  cmd_->add_option("--at", at_, "open the page at this time of the run (s)")
      ->type_name("SECONDS")
      ->transform(cli::number(0, 1e6));
}

bool ViewCommand::chosen() const { return cmd_->parsed(); }

int ViewCommand::run() const {
  McapFile file;
  try {
    file = McapFile::open(file_);
    checkPayloads(file);
  } catch (const McapError& e) {
    std::fprintf(stderr, "simswift view: %s\n", e.what());
    return 2;
  }
  const double duration_s = static_cast<double>(file.endTime()) * 1e-9;
  // 1 ms of slack: a report line prints times to the ms (and the page clamps to the end).
  if (at_ > duration_s + 1e-3) {
    return cli::usageError(*cmd_, "--at " + runner::formatNumber("%g", at_) + " is after the recording's end (" +
                                      runner::formatNumber("%.3f", duration_s) + " s)");
  }
  // The page's files: staged in the build tree or installed (the data folder's rule, docs/library.md).
  std::string viewer_dir;
  std::vector<std::string> tried;
  for (const std::string& d : runner::dataDirs()) {
    const std::string c = d + "/viewer";
    if (std::filesystem::exists(c + "/index.html")) {
      viewer_dir = c;
      break;
    }
    tried.push_back(c);
  }
  if (viewer_dir.empty()) {
    std::string where;
    for (const std::string& t : tried) where += "\n  " + t;
    std::fprintf(stderr, "simswift view: the viewer's files (index.html) are not in%s\n", where.c_str());
    return 1;
  }
  const std::string three_dir = SIMSWIFT_THREE_DIR;
  if (!std::filesystem::exists(three_dir + "/three.min.js")) {
    std::fprintf(stderr,
                 "simswift view: three.js is not at %s/three.min.js: install Debian's libjs-three "
                 "(scripts/install-deps.sh)\n",
                 three_dir.c_str());
    return 1;
  }
  try {
    HttpServer server(port_);
    const ViewerSite site(file, viewer_dir, three_dir);
    std::string url = "http://127.0.0.1:" + std::to_string(server.port()) + "/";
    if (at_ >= 0) url += "?t=" + runner::formatNumber("%g", at_);
    std::printf("simswift view: %s (%zu messages, %.3f s) at %s\n", file_.c_str(), file.messageCount(), duration_s,
                url.c_str());
    std::fflush(stdout);
    if (!no_browser_ && !openBrowser(url))
      std::fprintf(stderr, "simswift view: could not start a browser; open %s\n", url.c_str());
    server.serve([&](const HttpRequest& r) { return site.handle(r); });
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "simswift view: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace simswift::view
