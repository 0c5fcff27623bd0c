// See FuzzCases.hpp.
#include "FuzzCases.hpp"

#include <cctype>
#include <fstream>
#include <memory>
#include <sstream>

#include "agent/program/Postures.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/nao_model/RobotModel.hpp"
#include "sim/runner/Scenario.hpp"
#include "sim/world/FieldConfig.hpp"
#include "sim/world/World.hpp"

namespace simswift::fuzz {

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::shared_ptr<const RobotModel> goodModel() {
  static auto m = std::make_shared<const RobotModel>(RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf"));
  return m;
}

// "<source>:<digits>: " at the start.
bool namesFileAndLine(const std::string& msg, const std::string& source) {
  if (msg.rfind(source + ":", 0) != 0) return false;
  size_t i = source.size() + 1, digits = 0;
  while (i < msg.size() && std::isdigit(static_cast<unsigned char>(msg[i]))) ++i, ++digits;
  return digits > 0 && msg.compare(i, 2, ": ") == 0;
}

// A few ticks with `model` standing on `field` at (x, y, theta).
void stepWorld(const FieldConfig& field, std::shared_ptr<const RobotModel> model, double x, double y, double theta) {
  World w(field);
  const auto q = simswift::NaoBinding(*model).posture(agent::program::postureAngles(agent::program::Posture::Stand));
  const int i = w.addRobot(model, x, y, theta, q);
  w.robot(i).holdPosture(q);
  for (int k = 0; k < 3; ++k) w.step();
}

}  // namespace

const char* loaderName(Loader l) {
  return l == Loader::Urdf ? "urdf" : l == Loader::Field ? "field" : "scenario";
}

const char* sourceName(Loader l) {
  return l == Loader::Urdf ? "fuzz.urdf" : l == Loader::Field ? "fuzz_field.yaml" : "fuzz_scenario.yaml";
}

std::string seedText(Loader l) {
  switch (l) {
    case Loader::Urdf:
      return readFile(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf");
    case Loader::Field:
      return readFile(SIMSWIFT_SOURCE_DIR "/fields/spl_2017.yaml");
    case Loader::Scenario:
      // Every feature in one file: cameras, physics, noise map, script,
      // actions with a push, buttons, several robots.
      return readFile(SIMSWIFT_SOURCE_DIR "/scenarios/walk_one.yaml") +
             "  - team: 1\n    player: 2\n    x: 2.0\n    y: 1.0\n    theta: 3.1\n"
             "    script: [{t: 1.0, joint: HeadYaw, angle: 0.5, duration: 0.5}, {t: 2, posture: crouch}]\n"
             "    buttons: [{t: 3.0, button: chest, duration: 0.1}]\n"
             "physics: {substeps: 2, solver: quick, iterations: 20}\n"
             "watchdog: 5\nattach_timeout: 30\n"
             "camera: {enabled: off, resolution: 640x480, overview: {enabled: off, mode: robot, robot: 1}}\n";
  }
  return "";
}

CaseResult runCase(Loader l, const std::string& text) {
  const std::string source = sourceName(l);
  CaseResult r;
  try {
    switch (l) {
      case Loader::Urdf: {
        auto m = std::make_shared<const RobotModel>(RobotModel::loadUrdfString(text, source));
        stepWorld(FieldConfig::spl2017(), m, 0, 0, 0);
        break;
      }
      case Loader::Field: {
        const FieldConfig f = FieldConfig::parseYaml(text, source);
        stepWorld(f, goodModel(), -1.0, 0.0, 0.0);
        break;
      }
      case Loader::Scenario: {
        const runner::Scenario sc = runner::Scenario::parse(text, source);
        const FieldConfig f = FieldConfig::spl2017();
        sc.checkAgainstField(f);
        World w(f);
        if (sc.ball) w.placeBall(sc.ball->first, sc.ball->second);
        const auto model = goodModel();
        for (const auto& rs : sc.robots) {
          const int i = w.addRobot(model, rs.x, rs.y, rs.theta,
                                   simswift::NaoBinding(*model).posture(agent::program::postureAngles(rs.posture)));
          for (const auto& p : rs.pushes) w.applyImpulse(i, Eigen::Vector3d(p.jx, p.jy, 0));
        }
        for (int k = 0; k < 3; ++k) w.step();
        break;
      }
    }
    r.outcome = Outcome::Accepted;
  } catch (const ModelError& e) {
    r.message = e.what();
    r.outcome = namesFileAndLine(r.message, source) ? Outcome::Refused : Outcome::ErrorWithoutFile;
  } catch (const ConfigError& e) {
    r.message = e.what();
    r.outcome = namesFileAndLine(r.message, source) ? Outcome::Refused : Outcome::ErrorWithoutFile;
  } catch (const std::exception& e) {
    r.message = std::string("unexpected exception: ") + e.what();
    r.outcome = Outcome::ErrorWithoutFile;
  }
  return r;
}

}  // namespace simswift::fuzz
