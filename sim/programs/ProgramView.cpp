#include "sim/programs/ProgramView.hpp"

#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

namespace simswift::programs {

namespace fs = std::filesystem;

namespace {

bool under(const std::string& path, const std::string& folder) {
  return path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 && path[folder.size()] == '/';
}

// The path's deepest folder that is a real folder on the machine (no
// symlink on the way), walking down from /.
fs::path deepestFolder(const fs::path& path) {
  fs::path at = "/";
  for (const fs::path& part : path.relative_path()) {
    const fs::path next = at / part;
    struct stat st {};
    if (lstat(next.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) break;
    at = next;
  }
  return at;
}

void makeFolder(const fs::path& p) {
  std::error_code ec;
  fs::create_directories(p, ec);
  if (ec) throw std::runtime_error("cannot make " + p.string() + " for the program's view: " + ec.message());
}

// Puts `e` at `at` (in a staging folder): its content, or a mount point for
// its `from` (an empty folder or file, the same kind as `from`).
void stage(const FileEntry& e, const fs::path& at) {
  makeFolder(at.parent_path());
  std::error_code ec;
  fs::remove_all(at, ec);
  if (!e.from.empty() && fs::is_directory(e.from)) {
    makeFolder(at);
    return;
  }
  {
    std::ofstream out(at, std::ios::binary);
    if (!e.from.empty()) {
      // A file mapped in: an empty mount point.
    } else {
      out << e.content;
    }
    if (!out) throw std::runtime_error(e.where + ": cannot write " + at.string() + " for the program's view");
  }
  if (chmod(at.c_str(), e.mode) != 0)
    throw std::runtime_error(e.where + ": chmod " + at.string() + ": " + std::strerror(errno));
}

MountOp bindMount(const std::string& source, const std::string& target, const std::string& what, bool optional = false) {
  MountOp op;
  op.source = source;
  op.target = target;
  op.flags = MS_BIND | MS_REC;
  op.what = what;
  op.optional = optional;
  return op;
}

}  // namespace

std::string fileEntryProblem(const std::string& path) {
  if (path.empty() || path[0] != '/') return "must be an absolute path";
  if (fs::path(path).lexically_normal().string() != path || path.back() == '/')
    return "must be a normal path (no '.', '..', '//' or trailing '/')";
  if (path == "/" || path == "/tmp" || path == "/home") return "cannot replace " + path + " itself";
  if (path == "/proc" || under(path, "/proc") || path == "/dev" || under(path, "/dev"))
    return "cannot be under /proc or /dev";
  if (path == "/tmp/robocup") return "is the robot's LoLA socket";
  if (path.find_first_of(":,\n") != std::string::npos) return "must not contain ':', ',' or a newline";
  return "";
}

std::vector<FileEntry> defaultFiles() {
  std::vector<FileEntry> v;
  // B-Human (2025) asserts it can open these: the NAO V6's CPU (Intel Atom
  // E3845) core temperatures through hwmon, in millidegrees Celsius (the
  // kernel's hwmon sysfs interface, Documentation/hwmon/sysfs-interface).
  // simswift does not model the CPU: a constant 50 degC.
  for (int i = 2; i <= 5; ++i)
    v.push_back({"/sys/class/hwmon/hwmon1/temp" + std::to_string(i) + "_input", "50000\n", "", 0444, "default"});
  // Where NaoTH looks for LoLA's executable (it checks that one exists): this
  // robot's LoLA is simswift, so the file only says so.
  const std::string lola = "#!/bin/sh\n# simswift: this robot's LoLA is simswift itself, serving /tmp/robocup.\nexit 0\n";
  v.push_back({"/opt/aldebaran/bin/lola", lola, "", 0755, "default"});
  v.push_back({"/usr/bin/lola", lola, "", 0755, "default"});
  return v;
}

std::vector<std::string> pathsUnderTmp(const std::vector<std::string>& texts) {
  std::vector<std::string> out;
  for (const std::string& t : texts) {
    for (size_t at = t.find("/tmp/"); at != std::string::npos; at = t.find("/tmp/", at + 1)) {
      if (at > 0 && t[at - 1] != '=' && t[at - 1] != ':' && t[at - 1] != ',') continue;
      const size_t begin = at + 5;
      const size_t end = t.find_first_of("/:,", begin);
      const std::string first = t.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
      if (first.empty() || first == "." || first == "..") continue;
      const std::string p = "/tmp/" + first;
      if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
    }
  }
  return out;
}

std::vector<MountOp> planView(const ProgramView& view, bool prepare) {
  std::vector<MountOp> ops;
  if (!view.isolate) return ops;
  const fs::path root = view.folder;
  if (root.string().find_first_of(":,") != std::string::npos)
    throw std::runtime_error("the program's view folder " + root.string() + " must not contain ':' or ','");
  std::error_code ec;
  if (prepare) fs::remove_all(root, ec);
  // What a joining program finds made stays as the run made it.
  const auto missing = [prepare](const fs::path& p) {
    struct stat st {};
    return prepare || lstat(p.c_str(), &st) != 0;
  };
  const fs::path tmp = root / "tmp", home = root / "home";
  makeFolder(tmp);
  makeFolder(home);
  chmod(tmp.c_str(), 01777);  // as a machine's /tmp

  // Its PID namespace's own /proc (optional: a container may forbid it).
  MountOp proc;
  proc.source = "proc";
  proc.target = "/proc";
  proc.fstype = "proc";
  proc.flags = MS_NOSUID | MS_NODEV | MS_NOEXEC;
  proc.optional = true;
  proc.what = "its own /proc";
  ops.push_back(proc);

  // The files: the last entry of a path wins (the scenario's over the defaults).
  std::map<std::string, FileEntry> files;
  for (const FileEntry& e : view.files) files[e.path] = e;
  // /home/nao: a folder of the run unless the scenario maps one there.
  std::string home_source = home.string();
  if (auto it = files.find("/home/nao"); it != files.end()) {
    home_source = it->second.from;
    files.erase(it);
  }
  std::map<std::string, fs::path> layers;  // deepest machine folder -> its overlay's upper layer
  std::vector<MountOp> binds, inner_binds;
  const bool defaults_optional = true;
  for (const auto& [path, e] : files) {
    const bool optional = defaults_optional && e.where == "default";
    fs::path at;
    if (under(path, "/tmp")) {
      at = tmp / path.substr(5);
    } else if (under(path, "/home/nao")) {
      if (home_source != home.string())
        throw std::runtime_error(e.where + ": files: " + path + " is inside the folder mapped at /home/nao");
      at = home / path.substr(10);
    } else {
      const fs::path folder = deepestFolder(fs::path(path).parent_path());
      if (folder == "/") {
        if (optional) continue;  // e.g. no /opt on this machine: NaoTH finds /usr/bin/lola
        throw std::runtime_error(e.where + ": files: " + path + ": no folder of its path but / exists on this "
                                 "machine (the view adds files below an existing folder)");
      }
      auto [it, fresh] = layers.try_emplace(folder.string(), root / "layers" / std::to_string(layers.size()));
      at = it->second / fs::path(path).lexically_relative(folder);
    }
    if (missing(at)) stage(e, at);
    if (!e.from.empty()) {
      // Into a staging folder (under /tmp or /home/nao): before those are
      // bound; elsewhere: after the overlay made its path.
      if (under(path, "/tmp") || under(path, "/home/nao"))
        inner_binds.push_back(bindMount(e.from, at.string(), "files: " + path, optional));
      else
        binds.push_back(bindMount(e.from, path, "files: " + path, optional));
    }
  }
  // /home/nao must exist to be bound on: an (empty) folder in the overlay
  // of its deepest machine folder, unless the machine has it.
  bool home_possible = true;
  struct stat st {};
  if (lstat("/home/nao", &st) != 0 || !S_ISDIR(st.st_mode)) {
    const fs::path folder = deepestFolder("/home");
    home_possible = folder != "/";
    if (home_possible) {
      auto [it, fresh] = layers.try_emplace(folder.string(), root / "layers" / std::to_string(layers.size()));
      makeFolder(it->second / fs::path("/home/nao").lexically_relative(folder));
    }
  }
  // Overlays, shallowest first (a deeper one then lies on the shallower's view).
  std::vector<std::pair<std::string, fs::path>> order(layers.begin(), layers.end());
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return std::count(a.first.begin(), a.first.end(), '/') < std::count(b.first.begin(), b.first.end(), '/');
  });
  for (const auto& [folder, layer] : order) {
    MountOp op;
    op.source = "overlay";
    op.target = folder;
    op.fstype = "overlay";
    op.data = "lowerdir=" + layer.string() + ":" + folder;  // read-only: the layer over the machine's folder
    op.what = "the robot's files on " + folder;
    bool all_default = true;
    for (const auto& [path, e] : files)
      if (under(path, folder) && e.where != "default") all_default = false;
    op.optional = all_default;
    ops.push_back(op);
  }
  for (MountOp& b : binds) ops.push_back(std::move(b));
  for (MountOp& b : inner_binds) ops.push_back(std::move(b));
  ops.push_back(bindMount(home_source, "/home/nao", "/home/nao", !home_possible));

  // /tmp last: what it covers (the socket, the launch's folders) is bound in first.
  if (!view.robocup_socket.empty()) {
    if (missing(tmp / "robocup")) std::ofstream((tmp / "robocup").string()).put('\0');  // the mount point (a file)
    MountOp op = bindMount(view.robocup_socket, (tmp / "robocup").string(), "/tmp/robocup");
    op.flags = MS_BIND;
    ops.push_back(op);
  }
  std::vector<std::string> carried;
  for (const std::string& c : view.carry) {
    if (!under(c, "/tmp")) continue;
    const std::string first = "/tmp/" + fs::path(c.substr(5)).begin()->string();
    if (first == "/tmp/robocup" || std::find(carried.begin(), carried.end(), first) != carried.end()) continue;
    struct stat cs {};
    if (lstat(first.c_str(), &cs) != 0) continue;  // nothing there to see
    const fs::path at = tmp / first.substr(5);
    if (S_ISDIR(cs.st_mode)) {
      makeFolder(at);
    } else if (S_ISREG(cs.st_mode)) {
      if (missing(at)) std::ofstream(at.string()).put('\0');
    } else {
      continue;
    }
    carried.push_back(first);
    ops.push_back(bindMount(first, at.string(), "the machine's " + first));
  }
  ops.push_back(bindMount(tmp.string(), "/tmp", "a /tmp of its own"));
  return ops;
}

int applyView(const std::vector<MountOp>& mounts, size_t* failed) {
  for (size_t i = 0; i < mounts.size(); ++i) {
    const MountOp& m = mounts[i];
    if (mount(m.source.c_str(), m.target.c_str(), m.fstype.empty() ? nullptr : m.fstype.c_str(), m.flags,
              m.data.empty() ? nullptr : m.data.c_str()) == 0)
      continue;
    const int e = errno;
    if (m.optional) {
      // Said in the program's log (stderr is the log by now).
      const char* a = "simswift: the program's view goes without ";
      ssize_t w = write(2, a, std::strlen(a));
      w = write(2, m.what.c_str(), m.what.size());
      const char* b = ": the mount failed: ";
      w = write(2, b, std::strlen(b));
      const char* s = strerrordesc_np(e);
      w = write(2, s, std::strlen(s));
      w = write(2, "\n", 1);
      (void)w;
      continue;
    }
    if (failed) *failed = i;
    return e;
  }
  return 0;
}

}  // namespace simswift::programs
