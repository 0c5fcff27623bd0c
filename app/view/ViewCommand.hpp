// `simswift view FILE.mcap [--port N] [--no-browser] [--at SECONDS]`: the
// replay viewer (docs/viewer.md). Declared on simswift's command line
// (app/simswift.cpp) with CLI11 (app/cli).
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace simswift::view {

class ViewCommand {
 public:
  explicit ViewCommand(CLI::App& parent);
  ViewCommand(const ViewCommand&) = delete;
  ViewCommand& operator=(const ViewCommand&) = delete;

  bool chosen() const;
  // Serves until interrupted: 0 then; 1 no three.js, viewer files or port;
  // 2 a bad command line or recording (the message names the file and byte).
  int run() const;

 private:
  CLI::App* cmd_ = nullptr;
  std::string file_;
  int port_ = 0;
  bool no_browser_ = false;
  double at_ = -1;  // s; < 0: not given
};

}  // namespace simswift::view
