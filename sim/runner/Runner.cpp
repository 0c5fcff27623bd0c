#include "sim/runner/Runner.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "common/libagent/SharedNames.hpp"
#include "common/nao/Postures.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Bodies.hpp"
#include "sim/vision/VisionOracle.hpp"
#include "sim/runner/Tracer.hpp"

namespace simswift::runner {

namespace al = common::libagent;
namespace an = common::nao;
using common::libagent::SyncMode;
using Clock = std::chrono::steady_clock;

Runner::Runner(Scenario scenario)
    : scenario_(std::move(scenario)),
      programs_(std::make_unique<programs::Programs>(static_cast<int>(scenario_.robots.size()))) {}

Runner::~Runner() { shutdown(); }

bool Runner::camerasAvailable() { return runner::camerasAvailable(); }

void Runner::startCameras() {
  std::vector<int> colours;
  // Jerseys by side (colour), whatever the SPL team numbers.
  for (auto& r : robots_) colours.push_back(static_cast<int>(r->spec.colour));
  cameras_ = makeRunCameras(*world_, scenario_.camera, camerasLens(), std::move(colours));
}

// Renders robot `index`'s cameras for this frame (if anyone wants them) and
// marks the frame's images valid.
void Runner::renderFrame(int64_t frame, int64_t t_us, al::CameraFrame& f, Robot& r, int index) {
  if (!cameras_ || !r.images) return;
  if (cameras_->renderRobot(*world_, index, r.spec.team, r.spec.player, r.perception, *r.images, frame, t_us))
    f.images_valid = 1;
}

int64_t Runner::framesDumped() const { return cameras_ ? cameras_->framesDumped() : 0; }

int64_t Runner::overviewFrames() const { return cameras_ ? cameras_->overviewFrames() : 0; }

std::string Runner::finishOverview() {
  if (cameras_) overview_message_ = cameras_->finishOverview();
  return overview_message_;
}

std::vector<double> Runner::modelPosture(const an::JointArray& angles) const {
  return nao_->posture(angles);
}

// The composition root, in stages: the world, then one body (World robot,
// SensorSuite, BodyHost) per robot, what drives each body (sim/programs),
// the game and team network around them, the cameras and the vision oracle.
// A start that failed (a missing model, a program that cannot start) leaves
// the runner half built: every later start() or tick() throws the same error.
void Runner::start() {
  if (start_error_) std::rethrow_exception(start_error_);
  if (started_) return;
  started_ = true;
  try {
    buildWorld();
    buildHosts();
    attachPrograms();
    buildTeamAndGame();
    bool v4l2 = false;
    for (auto& r : robots_) v4l2 = v4l2 || r->v4l2;
    if (scenario_.camera.any() || v4l2) startCameras();
    buildVision();
  } catch (...) {
    start_error_ = std::current_exception();
    throw;
  }
  wall_start_ = Clock::now();
}

// The model, the field (the scenario's placements checked against it) and
// the World with the scenario's ball.
void Runner::buildWorld() {
  model_ = std::make_shared<const RobotModel>(RobotModel::loadUrdf(scenario_.modelFile()));
  const FieldConfig field = FieldConfig::loadYaml(scenario_.fieldFile());
  scenario_.checkAgainstField(field);
  world_ = std::make_unique<World>(field, scenario_.world);
  if (scenario_.no_ball) world_->removeBall();
  else if (scenario_.ball) world_->placeBall(scenario_.ball->first, scenario_.ball->second);
  if (scenario_.camera.any() && !camerasAvailable())
    throw RunnerError("camera rendering was asked for (camera: enabled, --dump-frames or --overview), but this "
                      "simswift was built without cameras (-DSIMSWIFT_CAMERAS=OFF)");
}

// The sensors' configuration: the scenario's seed and noise switches.
sensors::SensorConfig Runner::sensorConfig() const {
  sensors::SensorConfig sc;
  sc.seed = scenario_.seed;
  sc.noise = scenario_.noise.on;
  sc.gyr_raw_sign = scenario_.gyr_raw_sign;
  sc.acc_raw_sign = scenario_.acc_raw_sign;
  auto off = [](sensors::NoiseSpec& n, bool on) {
    if (!on) n = sensors::NoiseSpec{};
  };
  off(sc.gyro, scenario_.noise.gyro);
  off(sc.accel, scenario_.noise.accel);
  off(sc.angle, scenario_.noise.angle);
  off(sc.fsr, scenario_.noise.fsr);
  off(sc.sonar, scenario_.noise.sonar);
  off(sc.encoder, scenario_.noise.encoder);
  return sc;
}

// Each robot's body in the world and its body side (Bodies.hpp: libagent
// in-process for a builtin program, in named shared memory for an external
// one; LoLA on its socket), in scenario order; then its SensorSuite, once it
// has settled (settleRobots).
void Runner::buildHosts() {
  // Every robot is attached through its body side: the model must be a NAO
  // whose 25 joint slots it can drive (ModelError "file:line: missing joint ..." if not).
  nao_ = std::make_unique<NaoBinding>(*model_);
  robots_.resize(scenario_.robots.size());
  for (auto& r : robots_) r = std::make_unique<Robot>();
  // Objects a killed run left: this run's robots take theirs over (a
  // waiting program may hold them open); other robots' are left to
  // `simswift clean`, so a run never removes objects it does not use (two
  // runs starting at once would race on them).
  for (size_t i = 0; i < scenario_.robots.size(); ++i) {
    Robot& r = *robots_[i];
    r.spec = scenario_.robots[i];
    r.tag = al::robotTag(r.spec.team, r.spec.player);
    world_->addRobot(model_, r.spec.x, r.spec.y, r.spec.theta, modelPosture(an::postureAngles(r.spec.posture)));
    const bool external = r.spec.program == RobotSpec::Program::External;
    r.body = makeBody(r.spec, {external, scenario_.camera.renderRobots()});
    r.images = r.body->images();
    if (external && free_running_) r.body->setSync(SyncMode::FreeRunning);
    r.latched = r.body->readActuators();  // what the body gets before any command (limp or stiff start)
    r.ext = r.body->extension();  // game state + team link, beside the block
    // An external robot's block is named by the robot (a program started by
    // hand finds it: `simswift attach`); a killed run's is taken over, also
    // when this run serves it none (attach must not hand that one on).
    const bool hand_started = external && !r.spec.launch.launched();
    const std::string block = hand_started ? common::v4l2::blockName(r.tag) : std::string();
    if (servesV4l2(r.spec)) {
      // A robot set up in code (an experiment's) has no paths: its body's.
      const bool unset = r.spec.v4l2.path[0].empty() && r.spec.v4l2.path[1].empty();
      r.v4l2 = std::make_unique<bridge::V4l2Devices>(
          r.tag, unset ? defaultCameraDevices(r.spec.body) : r.spec.v4l2.path, block);
    } else if (hand_started) {
      bridge::V4l2Devices::remove(block);
    }
  }
  settleRobots();
}

// The robots come to rest in their start postures before their programs
// first read them (issue 45: a V6 program's first packet read accelerometer
// z -2.98 m/s^2 and an FSR sum of 2.42 kg, a robot still sinking into its
// contacts, settled by the third). Each is held in its start posture at
// stiffness 1, whatever its body gives before any command (a V6 boots limp:
// settling with that let it sag out of its posture), for kSettleTicks ticks
// of physics, untimed (the clock and the tick count start after them), and
// through the run's first tick (applyCommands), so its first reading is of
// that posture at rest. The sensors are made from the settled state (their
// velocity and rotation differences would otherwise span the settling).
void Runner::settleRobots() {
  for (size_t i = 0; i < robots_.size(); ++i) holdStartPosture(static_cast<int>(i));
  world_->settle(kSettleTicks);
  const sensors::SensorConfig sc = sensorConfig();
  for (size_t i = 0; i < robots_.size(); ++i)
    robots_[i]->sensors = std::make_unique<sensors::SensorSuite>(*world_, static_cast<int>(i), sc);
}

void Runner::holdStartPosture(int i) {
  const an::JointArray angles = an::postureAngles(robots_[i]->spec.posture);
  std::array<float, al::kNumJoints> stiff;
  stiff.fill(1.f);
  nao_->command(world_->robot(i), angles, stiff);
}

// Team network and GameController; the robots see the game state at t = 0.
void Runner::buildTeamAndGame() {
  network_ = std::make_unique<network::TeamNetwork>(scenario_.team_comms, scenario_.seed);
  std::vector<game::GameController::RobotId> ids;
  links_.clear();
  // The game and the network know the two teams by side (GameController
  // team index: blue 0, red 1); the game-state block carries each side's
  // SPL team number, as the GameController's packet does.
  for (auto& r : robots_) {
    const int side = static_cast<int>(r->spec.colour);
    network_->addEndpoint(side, r->spec.player);
    ids.push_back({side, r->spec.player, r->spec.team});
    links_.push_back(&r->ext->team);
  }
  game_ = std::make_unique<game::GameController>(scenario_.game, ids);
  placer_ = std::make_unique<game::PenaltyPlacer>(modelPosture(an::postureAngles(an::Posture::Stand)));
  if (scenario_.game.udp.on) {
    try {
      gc_udp_ = std::make_unique<game::GameControllerUdp>(scenario_.game.udp);
    } catch (const std::runtime_error& e) {
      throw RunnerError(std::string(e.what()) + " (scenario " + scenario_.source + ")");
    }
  }
  buildRobotLan();
  teamAndGame(0);
}

common::nao::CameraLens Runner::camerasLens() const {
  return scenario_.robots.empty() ? common::nao::kV5CameraLens : bodyCameraLens(scenario_.robots.front().body);
}

// The vision oracle: its noise follows the scenario's master switch too;
// its field of view is the robots' lens unless the scenario sets one.
void Runner::buildVision() {
  vision::VisionConfig vc = scenario_.vision;
  vc.noise = vc.noise && scenario_.noise.on;
  const common::nao::CameraLens lens = camerasLens();
  if (!vc.hfov_deg) vc.hfov_deg = lens.horizontal_fov / common::nao::kDeg;
  if (!vc.vfov_deg) vc.vfov_deg = lens.vertical_fov / common::nao::kDeg;
  vision_ = std::make_unique<vision::VisionOracle>(world_->field(), vc, scenario_.seed);
  std::vector<int> teams, colours;
  for (auto& r : robots_) {
    teams.push_back(r->spec.team);
    colours.push_back(static_cast<int>(r->spec.colour));
  }
  vision_->setTeams(teams, colours);
}

bridge::BodyHost& Runner::host(int i) {
  auto* h = dynamic_cast<bridge::BodyHost*>(robots_[i]->body.get());
  if (!h) throw RunnerError("robot " + robots_[i]->tag + " has a " + bodyInterfaceName(robots_[i]->body->interface()) +
                            " body, not libagent");
  return *h;
}

void Runner::setFreeRunning(bool on) {
  free_running_ = on;
  for (auto& r : robots_)
    if (r && r->body && r->spec.program == RobotSpec::Program::External)
      r->body->setSync(on ? SyncMode::FreeRunning : SyncMode::LockStep);
}

// Each robot's driver (sim/programs): a builtin program composed and
// started (its threads, or its inline steps, wait for the first tick), a
// launched program's process started with its {config} file, an external
// program awaited at the first tick.
void Runner::attachPrograms() {
  std::vector<programs::ProgramEntry> entries;
  for (size_t i = 0; i < robots_.size(); ++i) {
    const RobotSpec& spec = robots_[i]->spec;
    const int index = static_cast<int>(i);
    entries.push_back({{index, robots_[i]->tag, spec.player, robots_[i]->body.get()},
                       spec.program,
                       spec.launch,
                       robots_[i]->v4l2 ? robots_[i]->v4l2->blockName() : std::string(),
                       programs::robotSetup(spec.setup, programIdentity(scenario_, index))});
  }
  programs::ProgramRun run{scenario_.attach_timeout_s, scenario_.program_logs, scenario_.base_dir};
  run.tick_us = world_->tickUs();
  run.clock_epoch_ns = scenario_.clock_epoch_s * 1'000'000'000;
  programs_->build(run, entries);
}

// The watchdog ends a run only when it is on and no debugger is attached: a
// thread stopped at a breakpoint keeps the run waiting (docs/runner.md,
// "Debugging in gdb"). Off (watchdog: off / --watchdog off), the runner waits
// in 1 s slices.
double Runner::watchdogWait() const { return scenario_.watchdog_s > 0 ? scenario_.watchdog_s : 1.0; }
bool Runner::watchdogArmed() const { return scenario_.watchdog_s > 0 && !tracerAttached(); }

void Runner::watchdogFail(int i, const char* thread) const {
  const Robot& r = *robots_[i];
  const std::string error = programs_->driver(i).error();
  std::ostringstream m;
  m << "robot " << r.tag << ": " << thread << " thread did not answer within " << scenario_.watchdog_s << " s (tick "
    << world_->tick() << ", sim " << formatNumber("%.2f", world_->time()) << " s)";
  if (!error.empty()) m << ": " << error;
  throw WatchdogError(m.str());
}

// The stages of one tick, in the order Runner.hpp documents (Runner::tick).

void Runner::applyCommands() {
  for (size_t i = 0; i < robots_.size(); ++i) {
    Robot& r = *robots_[i];
    if (r.placed) {
      holdStartPosture(static_cast<int>(i));
      r.sensors->setSonarMode(r.latched.sonar);
      continue;
    }
    std::array<float, al::kNumJoints> angles, stiff;
    for (int j = 0; j < al::kNumJoints; ++j) {
      angles[j] = r.latched.joints.angles[j];
      stiff[j] = r.latched.joints.stiffnesses[j];
    }
    nao_->command(world_->robot(static_cast<int>(i)), angles, stiff);
    r.sensors->setSonarMode(r.latched.sonar);
  }
}

void Runner::applyPushes() {
  for (size_t i = 0; i < robots_.size(); ++i) {
    Robot& r = *robots_[i];
    while (r.next_push < r.spec.pushes.size() && r.spec.pushes[r.next_push].t_s <= world_->time() + 1e-9) {
      const RobotSpec::Push& p = r.spec.pushes[r.next_push++];
      world_->applyImpulse(static_cast<int>(i), Eigen::Vector3d(p.jx, p.jy, 0.0));
    }
  }
}

void Runner::handleWorldEvents() {
  for (const WorldEvent& e : world_->takeEvents()) {
    if (e.kind == WorldEvent::Kind::BlowUp) {
      ++blowups_;
      std::fprintf(stderr, "tick %lld: %s\n", static_cast<long long>(e.tick), e.message.c_str());
      if (e.robot >= 0 && e.robot < numRobots()) robots_[e.robot]->sensors->reset(*world_);
    }
  }
}

void Runner::captureOverview() {
  if (cameras_) cameras_->captureOverview(*world_);
}

void Runner::publishSensors(int64_t tick, int64_t t_us) {
  for (auto& rp : robots_) {
    Robot& r = *rp;
    for (sensors::Button b : {sensors::Button::Chest, sensors::Button::HeadFront, sensors::Button::HeadMiddle,
                              sensors::Button::HeadRear})
      r.sensors->setButton(b, r.spec.buttonHeld(b, world_->time()));
    r.sensors->update(*world_);
    sensors::copyToAgent(r.sensors->reading(), r.values);
    for (int j = 0; j < al::kNumJoints; ++j) r.values.joints.stiffnesses[j] = r.latched.joints.stiffnesses[j];
  }
  // Each program's clock first: reading tick k's packet, it reads tick k's time.
  for (size_t i = 0; i < robots_.size(); ++i) programs_->driver(static_cast<int>(i)).publishTime(tick);
  for (auto& r : robots_) r->body->publishSensors(r->values, t_us, tick);
}

// What the body side posted, answered through the robot's driver (inline:
// its step runs here); the watchdog ends the run if no answer comes.
void Runner::awaitAnswer(int i, bool motion) {
  using Step = programs::ProgramDriver::Step;
  programs::ProgramDriver& d = programs_->driver(i);
  const Step step = motion ? Step::Motion : Step::Perception;
  d.posted(step, world_->tick());
  while (!d.await(step, watchdogWait()))
    if (watchdogArmed()) watchdogFail(i, motion ? "motion" : "perception");
}

void Runner::awaitMotion() {
  for (size_t i = 0; i < robots_.size(); ++i) {
    Robot& r = *robots_[i];
    const bool answered = !r.attached && programs_->driver(static_cast<int>(i)).attach();
    if (!answered && r.body->sync() == SyncMode::LockStep) awaitAnswer(static_cast<int>(i), true);
    if (!r.attached) {
      r.attached = true;
      r.perception = r.body->hasPerception();
    }
  }
}

void Runner::latchActuators() {
  for (auto& r : robots_) {
    r->latched = r->body->readActuators();
    r->placed = false;
  }
}

void Runner::updateFalls() {
  const double now = world_->time();  // s
  for (const LinkContact& c : world_->contacts())
    if (c.other == GeomTag::RobotLink && c.other_robot != c.robot && c.robot >= 0 &&
        c.robot < static_cast<int>(robots_.size()))
      robots_[c.robot]->last_robot_contact_s = now;
  for (size_t i = 0; i < robots_.size(); ++i) {
    Robot& r = *robots_[i];
    const bool contact = now - r.last_robot_contact_s <= FallDetector::kContactWindow;
    r.fall.update(world_->robot(static_cast<int>(i)).torsoPose().z, contact);  // torso origin height, m
  }
}

void Runner::cameraFrame(int64_t t_us) {
  // Integer arithmetic: frame k is due once t_us * 30 / 1e6 reaches k.
  const int64_t frame = t_us * common::nao::kCameraFramesPerSecond / 1000000;
  if (frame <= last_frame_) return;
  last_frame_ = frame;
  al::CameraFrame f{};
  f.sim_time_us = t_us;
  f.frame_index = frame;
  f.num_observations = 0;
  bool any = false;
  for (size_t i = 0; i < robots_.size(); ++i) {
    Robot& r = *robots_[i];
    al::CameraFrame fr = f;  // images_valid and observations are per robot
    if (r.perception) vision_->fill(*world_, static_cast<int>(i), fr);  // both cameras (sim/vision)
    renderFrame(frame, t_us, fr, r, static_cast<int>(i));
    if (r.perception) {
      r.body->publishFrame(fr);
      any = true;
    }
  }
  for (size_t i = 0; i < robots_.size(); ++i)
    if (robots_[i]->v4l2) publishV4l2(static_cast<int>(i), frame, t_us);
  if (any)
    for (size_t i = 0; i < robots_.size(); ++i)
      if (robots_[i]->perception) awaitAnswer(static_cast<int>(i), false);
  for (size_t i = 0; i < robots_.size(); ++i)
    if (robots_[i]->v4l2) awaitV4l2(static_cast<int>(i));
}

bool Runner::servesV4l2(const RobotSpec& spec) const {
  using Mode = RobotSpec::CameraDevices::Mode;
  // A launched program's, and an external one's (started by hand: the
  // block named by its robot); a builtin program reads its images in process.
  if (spec.v4l2.mode == Mode::Off || spec.program != RobotSpec::Program::External) return false;
  if (spec.v4l2.mode == Mode::Default) return camerasAvailable();
  if (!camerasAvailable())
    throw RunnerError("robot " + al::robotTag(spec.team, spec.player) + " (scenario " + scenario_.source + ":" +
                      std::to_string(spec.line) + "): v4l2: its cameras need rendering, but this simswift was "
                      "built without cameras (-DSIMSWIFT_CAMERAS=OFF)");
  return true;
}

// The cameras robot i's program streams (with a buffer queued), rendered at
// the size it set and published; the others cost nothing.
void Runner::publishV4l2(int i, int64_t frame, int64_t t_us) {
  Robot& r = *robots_[i];
  const auto requests = r.v4l2->requests();
  for (int c = 0; c < al::kNumCameras; ++c) {
    if (!requests[c].publish) continue;
    cameras_->renderCamera(*world_, i, c, requests[c].size, r.v4l2->image(c));
    r.v4l2->publish(c, frame, t_us, requests[c].size);
  }
}

// The lock-step: the run goes on once robot i's program has dequeued every
// frame just published (or stopped streaming), in watchdog slices; a
// program that ended is an error at once.
void Runner::awaitV4l2(int i) {
  constexpr double kSlice = 0.05;  // s, wall clock
  double waited = 0;
  while (!robots_[i]->v4l2->waitTaken(kSlice)) {
    programs_->driver(i).checkRunning();
    waited += kSlice;
    if (waited >= watchdogWait()) {
      if (watchdogArmed()) watchdogFail(i, "camera");
      waited = 0;
    }
  }
}

void Runner::captureViews(int64_t t_us) {
  if (findball_view_config_) captureFindBallView(t_us);
}

void Runner::tick() {
  start();  // idempotent; rethrows a failed start
  if (stopped_) throw RunnerError("tick after shutdown");
  applyCommands();
  applyPushes();
  world_->step();
  handleWorldEvents();
  captureOverview();
  const int64_t tick = world_->tick();
  const int64_t t_us = tick * world_->tickUs();  // exact integer time
  publishSensors(tick, t_us);
  awaitMotion();
  latchActuators();
  updateFalls();
  cameraFrame(t_us);
  teamAndGame(t_us);
  captureViews(t_us);
  for (TickObserver* o : observers_) o->observe(*this, t_us);
}

void Runner::captureFindBallView(int64_t t_us) {
  if (!findball_view_) {
    std::vector<std::string> tags;
    std::vector<int> players;
    for (auto& r : robots_) {
      tags.push_back(r->tag);
      players.push_back(r->spec.player);
    }
    findball_view_ = std::make_unique<sim::views::FindBallRecorder>(*findball_view_config_, tags, players);
  }
  // What each robot's program shows of its search (the observer hook).
  std::vector<std::optional<sim::views::FindBallViewData>> views(robots_.size());
  for (size_t i = 0; i < robots_.size(); ++i) {
    sim::views::FindBallViewData d;
    if (programs_->driver(static_cast<int>(i)).findBallView(d)) views[i] = std::move(d);
  }
  findball_view_->maybeCapture(t_us, views);
}

// The robots' own networks (launched programs with a wlan0 each:
// sim/network/RobotLan.hpp): the GameController's packets go into them too.
void Runner::buildRobotLan() {
  lan_ = std::make_unique<network::RobotLan>();
  for (size_t i = 0; i < robots_.size(); ++i) {
    const int fd = programs_->driver(static_cast<int>(i)).takeNetwork();
    if (fd >= 0) lan_->add(static_cast<int>(i), robots_[i]->spec.team, robots_[i]->spec.player, fd);
  }
  if (gc_udp_ && !lan_->empty())
    gc_udp_->alsoSendTo([lan = lan_.get()](const std::vector<uint8_t>& p) { lan->sendGameData(p); });
}

void Runner::teamAndGame(int64_t t_us) {
  // The robots' own networks from the first tick on: at start (t = 0, from
  // buildTeamAndGame) their programs may not have bound their ports yet, so
  // the GameController's first packet waits in the lan (RobotLan::pending_)
  // until the first tick's answers. Read here at start, the lan went live at
  // once and wrote it then: a program launched last (the opponent of
  // tests/nao_v6/test_robot_network.cpp) had not bound 3838 and missed it.
  if (lan_ && !lan_->empty() && world_->tick() > 0) {
    // Read before the exchange: a message read now is sent at t_us.
    lan_->readFrames(t_us, *network_, [this](const uint8_t* b, size_t n) {
      if (gc_udp_) gc_udp_->countReturn(b, n);
    });
    network_->exchange(t_us, links_, [this](const network::Delivery& d) { return lan_->deliver(d); });
  } else {
    network_->exchange(t_us, links_);
  }
  for (const game::GameEvent& e : game_->update(t_us)) {
    Robot& r = *robots_[e.robot];
    if (e.kind == game::GameEvent::Kind::Penalised) {
      placer_->penalise(*world_, e.robot, static_cast<int>(r.spec.colour));
    } else {
      placer_->unpenalise(*world_, e.robot, scenario_.game.on_unpenalise == game::GameConfig::Return::Previous);
    }
    r.sensors->reset(*world_);  // the robot was carried: no velocity spike in the IMU
  }
  for (auto& r : robots_) game_->fill(r->ext->game);
  if (gc_udp_) {
    common::libagent::GameStateBlock b{};
    game_->fill(b);
    gc_udp_->update(t_us, b);
  }
}

RunStats Runner::stats() const {
  RunStats s;
  s.ticks = world_ ? world_->tick() : 0;
  s.sim_s = world_ ? world_->time() : 0;
  s.wall_s = std::chrono::duration<double>(Clock::now() - wall_start_).count();
  s.real_time_factor = s.wall_s > 0 ? s.sim_s / s.wall_s : 0;
  s.blowups = blowups_;
  for (size_t i = 0; i < robots_.size(); ++i) {
    s.falls += robots_[i]->fall.falls;
    if (world_ && static_cast<int>(i) < world_->numRobots() && i < scenario_.robots.size()) {
      const RobotBody::TorsoPose t = world_->robot(static_cast<int>(i)).torsoPose();
      s.robots.push_back({scenario_.robots[i].team, scenario_.robots[i].player, t.x, t.y, t.heading,
                          robots_[i]->fall.falls, robots_[i]->fall.fallen, robots_[i]->fall.contact_falls});
    }
    if (robots_[i]->body) s.skipped_cycles += robots_[i]->body->skippedCycles();
    if (world_ && static_cast<int>(i) < world_->numRobots()) {
      const ServoCommandStats& c = world_->robot(static_cast<int>(i)).commandStats();
      s.nan_commands += c.nan_commands;
      s.clamped_angles += c.clamped_angles;
      s.clamped_stiffness += c.clamped_stiffness;
    }
  }
  if (gc_udp_) {
    s.gc_udp_sent = gc_udp_->sent();
    s.gc_udp_failed = gc_udp_->sendErrors();
    for (const game::GameControllerUdp::Returns& c : gc_udp_->returns())
      s.gc_returns.push_back({c.team, c.player, c.packets});
  }
  s.hash = world_ ? world_->stateHash() : 0;
  return s;
}

void Runner::placeRobot(int i, double x, double y, double theta) {
  start();
  if (i < 0 || i >= numRobots()) throw RunnerError("placeRobot: no robot " + std::to_string(i));
  world_->placeRobot(i, x, y, theta, modelPosture(an::postureAngles(an::Posture::Stand)));
  robots_[i]->sensors->reset(*world_);
}

RunStats Runner::run(const RunOptions& opt) {
  if (opt.realtime) setFreeRunning(true);
  start();
  const int64_t total = world_->ticksIn(scenario_.duration);
  const int64_t progress_every =
      opt.progress && opt.progress_every_s > 0 ? std::max<int64_t>(1, world_->ticksIn(opt.progress_every_s)) : 0;
  wall_start_ = Clock::now();
  while (world_->tick() < total) {
    tick();
    const int64_t t = world_->tick();
    // The first tick may have waited for external programs to start: the
    // wall clock (pacing, real-time factor) counts from its end.
    if (t == 1) wall_start_ = Clock::now() - std::chrono::microseconds(world_->tickUs());
    if (opt.print_hash_every > 0 && t % opt.print_hash_every == 0)
      std::printf("tick %lld hash %s\n", static_cast<long long>(t), hashHex(world_->stateHash()).c_str());
    if (progress_every && t % progress_every == 0 && t < total) {
      const RunStats s = stats();
      std::fprintf(stderr, "  sim %.1f / %.1f s | wall %.1f s | %.1fx real time\n", s.sim_s, scenario_.duration,
                   s.wall_s, s.real_time_factor);
    }
    if (opt.realtime) {
      // Pacing only: sleep until the wall clock catches up with simulated time.
      std::this_thread::sleep_until(wall_start_ + std::chrono::microseconds(t * world_->tickUs()));
    }
  }
  const RunStats s = stats();
  shutdown();
  if (!finishOverview().empty()) std::fprintf(stderr, "%s\n", overview_message_.c_str());
  if (findball_view_) std::fprintf(stderr, "%s\n", findball_view_->finish().c_str());
  if (framesDumped() > 0)
    std::fprintf(stderr, "camera frames: %lld PNGs in %s\n", static_cast<long long>(framesDumped()),
                 scenario_.camera.dump_dir.c_str());
  return s;
}

void Runner::shutdown() {
  if (stopped_) return;
  stopped_ = true;
  for (auto& r : robots_) {
    if (r && r->body) r->body->shutdown();
    if (r && r->v4l2) r->v4l2->shutdown();
  }
  // Launched programs stopped and reaped before the hosts remove their
  // objects; builtin threads joined. The drivers stay until the Runner goes
  // (their programs can still be read after run()); they are destroyed
  // before the hosts (member order).
  programs_->shutdown();
}

}  // namespace simswift::runner
