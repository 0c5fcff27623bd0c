// A pre-pass over URDF text, before urdfdom sees it: refuses absurd input
// cheaply (size, element nesting depth: the XML parser recurses per level and
// its time grows with the square of the depth), then reads the document with
// TinyXML (the parser urdfdom 3.0 itself uses) to record the line of every
// <link>/<joint> and of their sub-elements, so that NaoModel's errors can say
// "file:line: ...". It also keeps what urdfdom drops without a word (the
// number of <collision> elements per link).
#pragma once

#include <cstddef>
#include <map>
#include <string>

namespace simswift {

struct UrdfLimits {
  static constexpr size_t kMaxBytes = 4u << 20;  // the NAO URDF is ~40 KB
  static constexpr int kMaxDepth = 32;           // URDF needs 5 (robot/link/collision/geometry/box)
};

class UrdfLines {
 public:
  // Throws ModelError "source:line: ..." for oversize, too deep or
  // malformed XML.
  UrdfLines(const std::string& xml, const std::string& source);

  // Line of <link name=...> / <joint name=...> (the <robot> line if unknown).
  int link(const std::string& name) const;
  int joint(const std::string& name) const;
  // Line of the first `path` sub-element ("inertial/mass", "axis", ...)
  // of that link/joint; the element's own line if absent.
  int linkChild(const std::string& name, const std::string& path) const;
  int jointChild(const std::string& name, const std::string& path) const;
  bool linkHas(const std::string& name, const std::string& path) const;
  // Line of the i-th <collision> of a link.
  int collision(const std::string& link, size_t i) const;
  size_t collisionCount(const std::string& link) const;
  int robot() const { return robot_line_; }
  // The line of the first link or joint whose name appears in `text`
  // (urdfdom's messages name them "[name]"), else the <robot> line.
  int lineMentioned(const std::string& text) const;

 private:
  struct Element {
    int line = 0;
    std::map<std::string, int> children;  // "inertial/mass" -> line
    std::map<size_t, int> collisions;      // index -> line
  };
  std::map<std::string, Element> links_, joints_;
  int robot_line_ = 1;
};

}  // namespace simswift
