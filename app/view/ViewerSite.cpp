#include "app/view/ViewerSite.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "app/view/Json.hpp"
#include "common/json/JsonString.hpp"

namespace simswift::view {

using common::json::quote;  // JSON strings (common/json)

namespace {

constexpr std::size_t kDefaultMax = 2000;     // messages per /api/messages answer unless max= says
constexpr std::size_t kLargestMax = 200000;  // the most a max= may ask

HttpResponse error(int status, const std::string& why) { return {status, "text/plain; charset=utf-8", why + "\n"}; }

// A whole decimal number of ns (u64), or false.
bool parseNs(const std::string& text, std::uint64_t& out) {
  if (text.empty() || text.size() > 20) return false;
  std::uint64_t v = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return false;
    const std::uint64_t d = static_cast<std::uint64_t>(c - '0');
    if (v > (UINT64_MAX - d) / 10) return false;
    v = v * 10 + d;
  }
  out = v;
  return true;
}

void appendMessage(std::string& out, const McapFile& f, const McapMessage& m) {
  out += "{\"t\":";
  out += std::to_string(m.log_time);
  out += ",\"data\":";
  out += f.payload(m);
  out += '}';
}

std::string typeOf(const std::string& name) {
  const auto ends = [&](const char* e) {
    const std::string s(e);
    return name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
  };
  if (ends(".html")) return "text/html; charset=utf-8";
  if (ends(".js")) return "text/javascript; charset=utf-8";
  if (ends(".css")) return "text/css; charset=utf-8";
  if (ends(".png")) return "image/png";
  if (ends(".svg")) return "image/svg+xml";
  return "application/octet-stream";
}

bool plainName(const std::string& name) {
  if (name.empty() || name[0] == '.' || name.size() > 100) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' ||
           c == '_';
  });
}

}  // namespace

void checkPayloads(const McapFile& file) {
  for (const auto& [id, list] : file.messages()) {
    if (file.channels().at(id).message_encoding != "json") continue;
    for (const McapMessage& m : list) {
      const std::size_t bad = json::invalidAt(file.payload(m));
      if (bad != std::string_view::npos)
        throw McapError(file.name(), m.offset + bad,
                        "message on '" + file.channels().at(id).topic + "' is not valid JSON (its channel says json)");
    }
  }
}

ViewerSite::ViewerSite(const McapFile& file, std::string viewer_dir, std::string three_dir)
    : file_(file), viewer_dir_(std::move(viewer_dir)), three_dir_(std::move(three_dir)) {}

HttpResponse ViewerSite::handle(const HttpRequest& r) const {
  const std::string& p = r.path;
  if (p == "/" || p == "/index.html") return file(viewer_dir_ + "/index.html", typeOf(".html"));
  if (p == "/api/info") return info();
  if (p == "/api/messages") return messages(r);
  if (p == "/api/at") return at(r);
  // three.js r111 (Debian's libjs-three): the library and its orbit controls.
  if (p == "/three/three.min.js") return file(three_dir_ + "/three.min.js", typeOf(".js"));
  if (p == "/three/OrbitControls.js")
    return file(three_dir_ + "/examples/js/controls/OrbitControls.js", typeOf(".js"));
  const std::string prefix = "/viewer/";
  if (p.compare(0, prefix.size(), prefix) == 0) {
    const std::string name = p.substr(prefix.size());
    if (!plainName(name)) return error(404, "no such file");
    return file(viewer_dir_ + "/" + name, typeOf(name));
  }
  return error(404, "no such page: " + p);
}

HttpResponse ViewerSite::file(const std::string& path, const std::string& type) const {
  std::ifstream in(path, std::ios::binary);
  if (!in) return error(404, "no such file");
  std::ostringstream s;
  s << in.rdbuf();
  return {200, type, std::move(s).str()};
}

HttpResponse ViewerSite::info() const {
  std::string o = "{\"file\":" + quote(file_.name());
  o += ",\"bytes\":" + std::to_string(file_.bytes().size());
  o += ",\"profile\":" + quote(file_.profile()) + ",\"library\":" + quote(file_.library());
  o += ",\"start_ns\":" + std::to_string(file_.startTime()) + ",\"end_ns\":" + std::to_string(file_.endTime());
  o += ",\"messages\":" + std::to_string(file_.messageCount());
  o += ",\"metadata\":{";
  bool first = true;
  for (const auto& [name, map] : file_.metadata()) {
    o += (first ? "" : ",") + quote(name) + ":{";
    first = false;
    bool first_kv = true;
    for (const auto& [k, v] : map) {
      o += (first_kv ? "" : ",") + quote(k) + ":" + quote(v);
      first_kv = false;
    }
    o += "}";
  }
  o += "},\"channels\":[";
  first = true;
  for (const auto& [id, ch] : file_.channels()) {
    const auto& list = file_.messages().at(id);
    const auto schema = file_.schemas().find(ch.schema_id);
    o += std::string(first ? "" : ",") + "{\"topic\":" + quote(ch.topic) +
         ",\"encoding\":" + quote(ch.message_encoding) +
         ",\"schema\":" + quote(schema == file_.schemas().end() ? "" : schema->second.name) +
         ",\"count\":" + std::to_string(list.size());
    if (!list.empty())
      o += ",\"first_ns\":" + std::to_string(list.front().log_time) +
           ",\"last_ns\":" + std::to_string(list.back().log_time);
    o += "}";
    first = false;
  }
  o += "]}";
  return {200, "application/json", o};
}

namespace {

// The JSON channel a request's topic= names, or the refusal.
const McapChannel* jsonChannel(const McapFile& f, const HttpRequest& r, HttpResponse& refusal) {
  const auto topic = r.query.find("topic");
  if (topic == r.query.end()) {
    refusal = error(400, "topic= is missing");
    return nullptr;
  }
  const McapChannel* ch = f.channelOf(topic->second);
  if (!ch) {
    refusal = error(404, "no topic '" + topic->second + "' in the recording");
    return nullptr;
  }
  if (ch->message_encoding != "json") {
    refusal = error(400, "topic '" + topic->second + "' is " + ch->message_encoding + ", not json");
    return nullptr;
  }
  return ch;
}

bool nsParam(const HttpRequest& r, const char* key, std::uint64_t& out, HttpResponse& refusal) {
  const auto it = r.query.find(key);
  if (it == r.query.end()) return true;
  if (!parseNs(it->second, out)) {
    refusal = error(400, std::string(key) + "= must be a whole number of ns (got '" + it->second + "')");
    return false;
  }
  return true;
}

}  // namespace

HttpResponse ViewerSite::messages(const HttpRequest& r) const {
  HttpResponse refusal;
  const McapChannel* ch = jsonChannel(file_, r, refusal);
  if (!ch) return refusal;
  std::uint64_t from = 0, to = UINT64_MAX, max = kDefaultMax;
  if (!nsParam(r, "from", from, refusal) || !nsParam(r, "to", to, refusal) || !nsParam(r, "max", max, refusal))
    return refusal;
  if (max == 0 || max > kLargestMax)
    return error(400, "max= must be in [1, " + std::to_string(kLargestMax) + "]");
  const auto& list = file_.messages().at(ch->id);
  const auto earlier = [](const McapMessage& m, std::uint64_t t) { return m.log_time < t; };
  const auto later = [](std::uint64_t t, const McapMessage& m) { return t < m.log_time; };
  const auto begin = std::lower_bound(list.begin(), list.end(), from, earlier);
  const auto end = std::upper_bound(begin, list.end(), to, later);
  const std::size_t n = static_cast<std::size_t>(end - begin);
  const std::size_t shown = std::min<std::size_t>(n, max);
  std::string o = "{\"topic\":" + quote(ch->topic) + ",\"total\":" + std::to_string(n) + ",\"messages\":[";
  for (std::size_t k = 0; k < shown; ++k) {
    // Evenly thinned; the first and (if more than one) the last always kept.
    const std::size_t i = shown < 2 ? 0 : k * (n - 1) / (shown - 1);
    if (k) o += ',';
    appendMessage(o, file_, begin[static_cast<std::ptrdiff_t>(i)]);
  }
  o += "]}";
  return {200, "application/json", o};
}

HttpResponse ViewerSite::at(const HttpRequest& r) const {
  HttpResponse refusal;
  const McapChannel* ch = jsonChannel(file_, r, refusal);
  if (!ch) return refusal;
  std::uint64_t t = 0;
  if (r.query.find("t") == r.query.end()) return error(400, "t= is missing");
  if (!nsParam(r, "t", t, refusal)) return refusal;
  const auto& list = file_.messages().at(ch->id);
  if (list.empty()) return {200, "application/json", "{\"t\":null,\"data\":null}"};
  auto it = std::upper_bound(list.begin(), list.end(), t,
                             [](std::uint64_t x, const McapMessage& m) { return x < m.log_time; });
  if (it != list.begin()) --it;
  std::string o;
  appendMessage(o, file_, *it);
  return {200, "application/json", o};
}

}  // namespace simswift::view
