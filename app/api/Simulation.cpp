// The public API (include/simswift/Simulation.hpp) over the Runner: one
// Runner per Simulation, started at the first step; controllers are the
// program side's ApiController (sim/programs), Motion steps run inline on
// the simulator's thread, so a controller's robot
// goes through the same libagent block, in the same tick stage, as every
// other robot program (the same commands give the same state hash).
#include "simswift/Simulation.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>

#include "common/libagent/AgentShared.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/record/Recorder.hpp"
#include "sim/runner/Runner.hpp"
#include "sim/runner/Scenario.hpp"
#include "sim/world/FieldConfig.hpp"
#include "app/api/ConfigErrors.hpp"
#include "app/api/SimulationAccess.hpp"

namespace simswift::api {

namespace al = common::libagent;

// The public types are libagent 2017's layout.
static_assert(sizeof(JointValues) == sizeof(al::JointValues));
static_assert(sizeof(SensorValues) == sizeof(al::SensorValues));
static_assert(offsetof(SensorValues, sensors) == offsetof(al::SensorValues, sensors));
static_assert(offsetof(SensorValues, sonar) == offsetof(al::SensorValues, sonar));
static_assert(offsetof(JointValues, stiffnesses) == offsetof(al::JointValues, stiffnesses));
static_assert(kNumJoints == al::kNumJoints && kNumSensors == al::kNumSensors && kNumSonars == al::kNumSonars);
// The index enums count the same slots (compared as ints: distinct enums).
constexpr bool sameIndex(int a, int b) { return a == b; }
static_assert(sameIndex(RHand, al::Joints::RHand) && sameIndex(LKneePitch, al::Joints::LKneePitch));
static_assert(sameIndex(Sonar, al::Sensors::US) && sameIndex(RFsrRearRight, al::Sensors::RFoot_FSR_RearRight) &&
              sameIndex(ChestButton, al::Sensors::ChestBoard_Button) &&
              sameIndex(BatteryCharge, al::Sensors::Battery_Charge));

ConfigError configError(const simswift::ConfigError& e) { return ConfigError(e.what(), e.file, e.line, e.key); }
ConfigError configError(const simswift::ModelError& e) { return ConfigError(e.what(), e.file, e.line, ""); }

// The simulator's errors for a bad scenario, model or field (its own
// ConfigError, ModelError) as the API's ConfigError, for every call that
// reads a file or starts the simulation.
template <class F>
auto translated(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const simswift::ConfigError& e) {
    throw configError(e);
  } catch (const simswift::ModelError& e) {
    throw configError(e);
  }
}

struct Simulation::Impl {
  explicit Impl(runner::Scenario sc) : runner(std::move(sc)) {}
  runner::Runner runner;
  std::unique_ptr<record::Recorder> recorder;  // Simulation::record (after the runner: goes first)
  std::vector<std::shared_ptr<JointValues>> held;  // setJoints' commands, by robot (null: none)
  bool begun = false;    // start() was called (a controller is too late from here on)
  bool started = false;  // ... and succeeded
  // Builds the world and starts the programs. A start that fails throws the
  // same error again on every later call (Runner::start keeps it).
  void start() {
    if (started) return;
    if (!begun) {
      begun = true;
      // Controllers and every builtin program on this thread, right after the
      // tick is posted (Programs::setThreading): no thread hand-over per tick.
      runner.programs().setThreading(programs::Threading::Inline);
    }
    translated([&] { runner.start(); });
    started = true;
  }
};

Simulation::Simulation(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {
  impl_->held.resize(impl_->runner.scenario().robots.size());
}
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;
Simulation::~Simulation() = default;

Simulation Simulation::fromScenario(const std::string& path) {
  return translated([&] { return Simulation(std::make_unique<Impl>(runner::Scenario::loadFile(path))); });
}

Simulation Simulation::fromYaml(const std::string& text, const std::string& name, const std::string& base_dir) {
  return translated([&] {
    runner::Scenario sc = runner::Scenario::parse(text, name);
    if (!base_dir.empty()) sc.base_dir = base_dir;
    return Simulation(std::make_unique<Impl>(std::move(sc)));
  });
}

void Simulation::step() {
  impl_->start();
  impl_->runner.tick();
}

void Simulation::record(const std::string& path, double rate_hz) {
  if (impl_->recorder) throw std::logic_error("record(" + path + "): already recording " + impl_->recorder->path());
  if (!(rate_hz > 0 && rate_hz <= 1000))
    throw std::invalid_argument("record(" + path + "): rate_hz must be in (0, 1000] (got " + std::to_string(rate_hz) + ")");
  record::RecordOptions o;
  o.rate_hz = rate_hz;
  try {
    impl_->recorder = std::make_unique<record::Recorder>(path, o);
  } catch (const record::RecordError& e) {
    throw std::runtime_error(e.what());
  }
  impl_->runner.addObserver(impl_->recorder.get());
}

void Simulation::finishRecording() {
  if (!impl_->recorder) return;
  impl_->runner.removeObserver(impl_->recorder.get());
  std::unique_ptr<record::Recorder> rec = std::move(impl_->recorder);
  try {
    rec->finish();
  } catch (const record::RecordError& e) {
    throw std::runtime_error(e.what());
  }
}

double Simulation::run(double seconds, const std::function<bool(const Simulation&)>& until) {
  impl_->start();
  const World& w = impl_->runner.world();
  const int64_t n = w.ticksIn(seconds);  // the robots' tick (12 ms on a V6)
  int64_t k = 0;
  for (; k < n; ++k) {
    step();
    if (until && until(*this)) {
      ++k;
      break;
    }
  }
  return static_cast<double>(k) * w.tickSeconds();
}

double Simulation::time() const { return impl_->started ? impl_->runner.world().time() : 0.0; }
int64_t Simulation::ticks() const { return impl_->runner.ticks(); }
int Simulation::numRobots() const { return static_cast<int>(impl_->runner.scenario().robots.size()); }
double Simulation::duration() const { return impl_->runner.scenario().duration; }

Robot Simulation::robot(int i) {
  if (i < 0 || i >= numRobots())
    throw std::out_of_range("robot " + std::to_string(i) + ": the scenario has " + std::to_string(numRobots()));
  return Robot(this, i);
}

BallState Simulation::ball() const {
  BallState b;
  if (!impl_->started) {  // as the scenario places it: at rest on the carpet
    const runner::Scenario& sc = impl_->runner.scenario();
    if (sc.no_ball) return b;
    b.present = true;
    if (sc.ball) b.x = sc.ball->first, b.y = sc.ball->second;  // default: the centre spot
    b.z = translated([&] { return FieldConfig::loadYaml(sc.fieldFile()).ball.diameter / 2; });
    return b;
  }
  if (!impl_->runner.world().hasBall()) return b;
  const Eigen::Vector3d p = impl_->runner.world().ballPosition(), v = impl_->runner.world().ballVelocity();
  b = {true, p.x(), p.y(), p.z(), v.x(), v.y(), v.z()};
  return b;
}

void Simulation::placeBall(double x, double y) {
  impl_->start();  // throws ConfigError (translated) if the simulation cannot start
  impl_->runner.world().placeBall(x, y);
}

uint64_t Simulation::stateHash() const { return impl_->started ? impl_->runner.world().stateHash() : 0; }

SensorValues Robot::sensors() const {
  if (!sim_->impl_->started)
    throw std::logic_error("robot " + std::to_string(index_) +
                           ": sensors() before the first step(): a robot's sensors are read at each tick");
  SensorValues s;
  std::memcpy(&s, &sim_->impl_->runner.lastSensors(index_), sizeof s);
  return s;
}

void Robot::setController(Controller c) {
  if (sim_->impl_->begun)
    throw std::logic_error("robot " + std::to_string(index_) + ": setController before the first step");
  if (!c) throw std::invalid_argument("robot " + std::to_string(index_) + ": setController: empty controller");
  if (sim_->impl_->runner.scenario().robots[index_].program != runner::RobotSpec::Program::Builtin)
    throw std::logic_error("robot " + std::to_string(index_) +
                           ": its scenario runs an external program; a controller needs program: builtin");
  // The public types are libagent 2017's layout (checked above).
  sim_->impl_->runner.programs().setController(index_, [c = std::move(c)](const al::SensorValues& sensors,
                                                                           al::JointValues& out) {
    SensorValues s;
    std::memcpy(&s, &sensors, sizeof s);
    JointValues j;
    std::memcpy(&j, &out, sizeof j);
    c(s, j);
    std::memcpy(&out, &j, sizeof j);
  });
}

// The libagent controller also sees `standing` and the buttons and sends
// STIFFEN through the program, as an external program does in the block.
void Robot::setController(LibagentController c) {
  if (!c) throw std::invalid_argument("robot " + std::to_string(index_) + ": setController: empty controller");
  setController([](const SensorValues&, JointValues&) {});  // the same checks, then replaced
  sim_->impl_->runner.programs().setLibagentController(
      index_, [c = std::move(c)](const al::SensorValues& sensors, al::JointValues& out,
                                 programs::LibagentExtras& io) {
        SensorValues s;
        std::memcpy(&s, &sensors, sizeof s);
        JointValues j;
        std::memcpy(&j, &out, sizeof j);
        Libagent l;
        l.standing = io.standing;
        l.buttons = io.buttons;
        c(s, j, l);
        io.stiffen = l.stiffen;
        std::memcpy(&out, &j, sizeof j);
      });
}

void Robot::setJoints(const JointValues& joints) {
  std::shared_ptr<JointValues>& held = sim_->impl_->held[index_];
  if (held) {
    *held = joints;
    return;
  }
  if (sim_->impl_->begun)
    throw std::logic_error("robot " + std::to_string(index_) +
                           ": setJoints before the first step (then any time), or setController");
  held = std::make_shared<JointValues>(joints);
  std::shared_ptr<JointValues> h = held;
  setController([h](const SensorValues&, JointValues& j) {
    std::memcpy(j.angles, h->angles, sizeof j.angles);
    std::memcpy(j.stiffnesses, h->stiffnesses, sizeof j.stiffnesses);
  });
}

Pose Robot::pose() const {
  const runner::Runner& r = sim_->impl_->runner;
  Pose p;
  if (!sim_->impl_->started) {
    const runner::RobotSpec& s = r.scenario().robots[index_];
    p.x = s.x, p.y = s.y, p.theta = s.theta;
    return p;
  }
  const RobotBody::TorsoPose t = r.world().robot(index_).torsoPose();
  p.x = t.x, p.y = t.y, p.z = t.z, p.theta = t.heading;
  return p;
}

// Before the first step: up, no falls (every scenario posture starts upright).
bool Robot::fallen() const { return sim_->impl_->started && sim_->impl_->runner.robotFall(index_).fallen; }
int Robot::falls() const { return sim_->impl_->started ? sim_->impl_->runner.robotFall(index_).falls : 0; }

void Robot::push(double jx, double jy) {
  sim_->impl_->start();
  sim_->impl_->runner.world().applyImpulse(index_, Eigen::Vector3d(jx, jy, 0));
}

void Robot::teleport(double x, double y, double theta) {
  sim_->impl_->start();
  sim_->impl_->runner.placeRobot(index_, x, y, theta);
}

// The walk test kit's view of the runner (app/api/SimulationAccess.hpp).
const runner::Runner& SimulationAccess::runner(const Simulation& s) { return s.impl_->runner; }
bool SimulationAccess::started(const Simulation& s) { return s.impl_->started; }

}  // namespace simswift::api
