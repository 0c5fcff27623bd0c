// Camera images in a recording (issue 46, docs/recording.md): a run that
// renders its cameras records both of every robot as foxglove.CompressedImage
// (PNG, base64 in JSON) at the recorder's camera rate, and each recorded
// image is, pixel for pixel, the frame the run rendered at that moment.
// Built only with cameras (the sanitizer builds have none).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "app/view/Mcap.hpp"
#include "sim/camera/Png.hpp"
#include "sim/record/Recorder.hpp"
#include "sim/runner/Runner.hpp"
#include "sim/runner/TickObserver.hpp"

using namespace simswift;
namespace al = common::libagent;
namespace fs = std::filesystem;

namespace {

// Both cameras' RGB bytes at every tick (ns of simulated time).
struct Frames : runner::TickObserver {
  std::map<uint64_t, std::vector<uint8_t>> top, bottom;
  void observe(const runner::Runner& r, int64_t t_us) override {
    const al::CameraImages* im = r.images(0);
    if (!im) return;
    const auto t_ns = static_cast<uint64_t>(t_us) * 1000;
    if (im->valid[0]) top[t_ns].assign(im->rgb[0], im->rgb[0] + im->rgbBytes(0));
    if (im->valid[1]) bottom[t_ns].assign(im->rgb[1], im->rgb[1] + im->rgbBytes(1));
  }
};

// RFC 4648 base64 (the CompressedImage's `data` in JSON).
std::string base64Decode(std::string_view in) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : c == '/' ? 63 : -1;
  };
  std::string out;
  uint32_t bits = 0;
  int n = 0;
  for (const char c : in) {
    const int v = value(c);
    if (v < 0) break;  // '=' padding ends it
    bits = (bits << 6) | static_cast<uint32_t>(v);
    if ((n += 6) >= 8) out.push_back(static_cast<char>((bits >> (n -= 8)) & 0xff));
  }
  return out;
}

// The string value of `"key":"..."` in a flat JSON object (no escapes in
// the values read here: base64, "png", a frame id).
std::string jsonString(std::string_view json, const std::string& key) {
  const std::string k = "\"" + key + "\":\"";
  const size_t at = json.find(k);
  if (at == std::string_view::npos) return "";
  const size_t from = at + k.size();
  return std::string(json.substr(from, json.find('"', from) - from));
}

}  // namespace

TEST(RecordedImages, EachIsTheFrameTheRunRenderedThen) {
  const fs::path dir = fs::temp_directory_path() / ("simswift-recorded-images-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  runner::Scenario sc = runner::Scenario::loadFile(SIMSWIFT_SOURCE_DIR "/scenarios/cameras_demo.yaml");
  sc.duration = 0.5;
  Frames frames;
  {
    runner::Runner r(sc);
    record::Recorder rec((dir / "cams.mcap").string());  // default rates: images at 10 Hz
    r.addObserver(&rec);
    r.addObserver(&frames);
    runner::RunOptions o;
    o.progress = false;
    r.run(o);
    rec.finish();
  }
  const view::McapFile f = view::McapFile::open((dir / "cams.mcap").string());
  int checked = 0;
  for (const auto& [topic, rendered] : {std::pair{"/robot0/camera/top", &frames.top},
                                        std::pair{"/robot0/camera/bottom", &frames.bottom}}) {
    SCOPED_TRACE(topic);
    const view::McapChannel* c = f.channelOf(topic);
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(f.schemas().at(c->schema_id).name, "foxglove.CompressedImage");
    const std::vector<view::McapMessage>& messages = f.messages().at(c->id);
    // 10 Hz over 0.5 s: the first tick (0.01 s), then 0.1, 0.2, ... 0.5 s.
    ASSERT_EQ(messages.size(), 6u);
    for (const view::McapMessage& m : messages) {
      SCOPED_TRACE(m.log_time);
      const std::string_view json = f.payload(m);
      EXPECT_EQ(jsonString(json, "format"), "png");
      EXPECT_EQ(jsonString(json, "frame_id"), "robot0/Head");
      const std::string png = base64Decode(jsonString(json, "data"));
      ASSERT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
      const fs::path file = dir / "image.png";
      std::ofstream(file, std::ios::binary) << png;
      int w = 0, h = 0;
      const std::vector<uint8_t> pixels = camera::readPng(file.string(), &w, &h);
      EXPECT_EQ(w, 640);  // cameras_demo.yaml's resolution
      EXPECT_EQ(h, 480);
      ASSERT_EQ(rendered->count(m.log_time), 1u) << "no frame rendered at the image's time";
      EXPECT_TRUE(pixels == rendered->at(m.log_time)) << "the recorded image is not the frame rendered then";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 12);
  fs::remove_all(dir);
}
