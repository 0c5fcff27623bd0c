// URDF pre-pass: size and depth limits, then line numbers. See UrdfLines.hpp.
#include "sim/nao_model/UrdfLines.hpp"

#include <tinyxml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <locale>
#include <sstream>

#include "sim/nao_model/RobotModel.hpp"

namespace simswift {

namespace {

[[noreturn]] void failPrePass(const std::string& source, int line, const std::string& what) {
  throw ModelError(source, line, what);
}

// The first limit of UrdfLimits (depth, elements, attributes) `xml` passes,
// found by one linear scan (comments, processing instructions, declarations
// and quoted attribute values skipped): what is wrong and the line of the
// tag where it was passed. Empty `what` if none.
struct Excess {
  std::string what;
  int line = 1;
};

Excess scanLimits(const std::string& xml) {
  int depth = 0, elements = 0, row = 1;
  const size_t n = xml.size();
  auto skipTo = [&](size_t& i, const char* end) {
    const size_t e = xml.find(end, i);
    const size_t stop = e == std::string::npos ? n : e + std::strlen(end);
    for (; i < stop; ++i)
      if (xml[i] == '\n') ++row;
  };
  for (size_t i = 0; i < n;) {
    const char c = xml[i];
    if (c != '<') {
      if (c == '\n') ++row;
      ++i;
      continue;
    }
    if (xml.compare(i, 4, "<!--") == 0) {
      skipTo(i, "-->");
    } else if (xml.compare(i, 9, "<![CDATA[") == 0) {
      skipTo(i, "]]>");
    } else if (xml.compare(i, 2, "<?") == 0) {
      skipTo(i, "?>");
    } else if (xml.compare(i, 2, "<!") == 0) {
      skipTo(i, ">");
    } else if (xml.compare(i, 2, "</") == 0) {
      if (depth > 0) --depth;
      skipTo(i, ">");
    } else {
      // An opening tag: find its end outside quotes, counting attributes
      // (one '=' each); "/>" closes it at once.
      const int tag_row = row;
      size_t name_end = i + 1;
      while (name_end < n && name_end - i <= 40 && !std::isspace(static_cast<unsigned char>(xml[name_end])) &&
             xml[name_end] != '/' && xml[name_end] != '>')
        ++name_end;
      const std::string name = xml.substr(i + 1, name_end - i - 1);
      char quote = 0;
      int attributes = 0;
      size_t j = i + 1;
      for (; j < n; ++j) {
        const char d = xml[j];
        if (d == '\n') ++row;
        if (quote) {
          if (d == quote) quote = 0;
        } else if (d == '"' || d == '\'') {
          quote = d;
        } else if (d == '=') {
          if (++attributes > UrdfLimits::kMaxAttributes)
            return {"<" + name + "> has more than " + std::to_string(UrdfLimits::kMaxAttributes) +
                        " attributes (a URDF element needs at most 6)",
                    tag_row};
        } else if (d == '>') {
          break;
        }
      }
      if (++elements > UrdfLimits::kMaxElements)
        return {"more than " + std::to_string(UrdfLimits::kMaxElements) +
                    " elements (the NAO's URDF has about 600)",
                tag_row};
      const bool empty = j < n && j > i + 1 && xml[j - 1] == '/';
      if (!empty && ++depth > UrdfLimits::kMaxDepth)
        return {"elements nested more than " + std::to_string(UrdfLimits::kMaxDepth) + " deep (a URDF needs 5)",
                tag_row};
      i = j + 1;
    }
  }
  return {};
}

// Numeric attributes URDF defines: element, attribute, how many numbers.
struct NumericAttribute {
  const char* element;
  const char* attribute;
  int count;
};
constexpr NumericAttribute kNumeric[] = {
    {"origin", "xyz", 3},    {"origin", "rpy", 3},      {"axis", "xyz", 3},      {"mass", "value", 1},
    {"inertia", "ixx", 1},   {"inertia", "ixy", 1},     {"inertia", "ixz", 1},   {"inertia", "iyy", 1},
    {"inertia", "iyz", 1},   {"inertia", "izz", 1},     {"box", "size", 3},      {"sphere", "radius", 1},
    {"cylinder", "radius", 1}, {"cylinder", "length", 1}, {"limit", "lower", 1}, {"limit", "upper", 1},
    {"limit", "velocity", 1}, {"limit", "effort", 1},    {"mimic", "multiplier", 1}, {"mimic", "offset", 1},
    {"mesh", "scale", 3},    {"color", "rgba", 4},
};

// Checks every numeric attribute below `e` is `count` finite numbers;
// urdfdom would otherwise drop the element or keep a default in silence.
void checkNumbers(const TiXmlElement* e, const std::string& source, const std::string& owner, int depth) {
  if (depth > UrdfLimits::kMaxDepth) return;
  for (const NumericAttribute& na : kNumeric) {
    if (e->ValueStr() != na.element) continue;
    const char* v = e->Attribute(na.attribute);
    if (!v) continue;
    std::istringstream in(v);
    in.imbue(std::locale::classic());
    int n = 0;
    std::string word;
    bool ok = true;
    while (in >> word) {
      char* end = nullptr;
      const double d = std::strtod(word.c_str(), &end);
      if (*end != '\0' || !std::isfinite(d)) ok = false;
      ++n;
    }
    if (!ok || n != na.count)
      failPrePass(source, e->Row(),
           owner + "<" + std::string(na.element) + " " + na.attribute + "=\"" + std::string(v).substr(0, 80) + "\">: expected " +
               std::to_string(na.count) + (na.count == 1 ? " finite number" : " finite numbers"));
  }
  for (const TiXmlElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
    checkNumbers(c, source,
                 depth == 1 && c->Attribute("name") ? c->ValueStr() + " '" + c->Attribute("name") + "': " : owner,
                 depth + 1);
}

const char* nameOf(const TiXmlElement* e) {
  const char* n = e->Attribute("name");
  return n ? n : "";
}

// Records the line of each descendant path ("inertial/mass"), first wins.
void collectChildren(const TiXmlElement* e, const std::string& prefix, std::map<std::string, int>& out,
                     int depth) {
  if (depth > UrdfLimits::kMaxDepth) return;
  for (const TiXmlElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string path = prefix.empty() ? c->ValueStr() : prefix + "/" + c->ValueStr();
    out.emplace(path, c->Row());
    collectChildren(c, path, out, depth + 1);
  }
}

}  // namespace

UrdfLines::UrdfLines(const std::string& xml, const std::string& source) {
  if (xml.size() > UrdfLimits::kMaxBytes)
    failPrePass(source, 1, "URDF is " + std::to_string(xml.size()) + " bytes, more than the " +
                        std::to_string(UrdfLimits::kMaxBytes >> 20) + " MB limit");
  if (const size_t nul = xml.find('\0'); nul != std::string::npos) {
    // Found once: the line count is one pass up to it (linear in the size).
    const int row = 1 + static_cast<int>(std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(nul), '\n'));
    failPrePass(source, row, "URDF contains a NUL byte (not a text file?)");
  }
  if (const Excess e = scanLimits(xml); !e.what.empty()) failPrePass(source, e.line, e.what);

  TiXmlDocument doc;
  doc.Parse(xml.c_str(), nullptr, TIXML_ENCODING_UTF8);
  if (doc.Error()) {
    failPrePass(source, doc.ErrorRow() > 0 ? doc.ErrorRow() : 1,
         std::string("URDF parse failed: XML syntax error: ") + (doc.ErrorDesc() ? doc.ErrorDesc() : "?"));
  }
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) failPrePass(source, 1, "no <robot> element");
  robot_line_ = robot->Row();
  checkNumbers(robot, source, "", 1);
  for (const TiXmlElement* e = robot->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const bool is_link = e->ValueStr() == "link";
    if (!is_link && e->ValueStr() != "joint") continue;
    Element& el = (is_link ? links_ : joints_)[nameOf(e)];
    if (el.line) continue;  // a duplicate name: urdfdom reports it
    el.line = e->Row();
    collectChildren(e, "", el.children, 1);
    size_t i = 0;
    for (const TiXmlElement* c = e->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision"))
      el.collisions[i++] = c->Row();
  }
}

int UrdfLines::link(const std::string& name) const {
  auto it = links_.find(name);
  return it == links_.end() ? robot_line_ : it->second.line;
}

int UrdfLines::joint(const std::string& name) const {
  auto it = joints_.find(name);
  return it == joints_.end() ? robot_line_ : it->second.line;
}

int UrdfLines::linkChild(const std::string& name, const std::string& path) const {
  auto it = links_.find(name);
  if (it == links_.end()) return robot_line_;
  auto c = it->second.children.find(path);
  return c == it->second.children.end() ? it->second.line : c->second;
}

int UrdfLines::jointChild(const std::string& name, const std::string& path) const {
  auto it = joints_.find(name);
  if (it == joints_.end()) return robot_line_;
  auto c = it->second.children.find(path);
  return c == it->second.children.end() ? it->second.line : c->second;
}

bool UrdfLines::linkHas(const std::string& name, const std::string& path) const {
  auto it = links_.find(name);
  return it != links_.end() && it->second.children.count(path) > 0;
}

int UrdfLines::collision(const std::string& link, size_t i) const {
  auto it = links_.find(link);
  if (it == links_.end()) return robot_line_;
  auto c = it->second.collisions.find(i);
  return c == it->second.collisions.end() ? it->second.line : c->second;
}

size_t UrdfLines::collisionCount(const std::string& link) const {
  auto it = links_.find(link);
  return it == links_.end() ? 0 : it->second.collisions.size();
}

int UrdfLines::lineMentioned(const std::string& text) const {
  // Each "[...]" (innermost) and '...' in one pass, looked up as it closes
  // (searching the text once per known name took time links x text).
  auto lineOf = [&](size_t open, size_t close) -> int {
    const std::string name = text.substr(open + 1, close - open - 1);
    if (name.empty()) return 0;
    if (auto it = links_.find(name); it != links_.end()) return it->second.line;
    if (auto it = joints_.find(name); it != joints_.end()) return it->second.line;
    return 0;
  };
  size_t bracket = std::string::npos, quote = std::string::npos;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '[') {
      bracket = i;
    } else if (c == ']' && bracket != std::string::npos) {
      if (const int line = lineOf(bracket, i)) return line;
      bracket = std::string::npos;
    } else if (c == '\'') {
      // An unknown name's closing quote may open the next name.
      if (quote != std::string::npos)
        if (const int line = lineOf(quote, i)) return line;
      quote = i;
    }
  }
  return robot_line_;
}

}  // namespace simswift
