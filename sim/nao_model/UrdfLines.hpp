// A pre-pass over URDF text, before urdfdom sees it: refuses absurd input
// cheaply, then reads the document with TinyXML (the parser urdfdom 3.0
// itself uses) to record the line of every <link>/<joint> and of their
// sub-elements, so that RobotModel's errors can say "file:line: ...". It also
// keeps what urdfdom drops without a word (the number of <collision>
// elements per link).
//
// Limits (UrdfLimits), each refused with the file and the line where it is
// passed, in one linear scan before any XML parser runs:
//   - size: 4 MB (the NAO's URDF is 25 KB);
//   - a NUL byte anywhere (not a text file; the parsers would stop at it);
//   - element nesting: 32 deep (URDF needs 5; the XML parser recurses per
//     level and its time grows with the square of the depth);
//   - elements: 16384 in the document (the NAO's has about 600; urdfdom and
//     the checks below do work per element and the World a body per link);
//   - attributes: 64 on one element (URDF's most is 6, <inertia>; TinyXML
//     looks each new attribute up among the ones before it, so its time
//     grows with the square of the count: 1 MB of them took 59 s).
// All time here is linear in the size of the input.
#pragma once

#include <cstddef>
#include <map>
#include <string>

namespace simswift {

struct UrdfLimits {
  static constexpr size_t kMaxBytes = 4u << 20;   // the NAO URDF is ~25 KB
  static constexpr int kMaxDepth = 32;            // URDF needs 5 (robot/link/collision/geometry/box)
  static constexpr int kMaxElements = 16384;      // the NAO URDF has ~600
  static constexpr int kMaxAttributes = 64;       // per element; URDF's most is 6 (<inertia>)
};

class UrdfLines {
 public:
  // Throws ModelError "source:line: ..." for input over a limit above or
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
  // The line of the first link or joint named in `text` (urdfdom's
  // messages name them "[name]", ours 'name'), else the <robot> line. One
  // pass over `text`.
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
