// The lock-step runner: one World, per robot a SensorSuite and its body side
// (sim/bridge/BodySide.hpp: libagent for a V5, LoLA for a V6), and
// per robot the driver of whatever runs its body (sim/programs/
// ProgramDriver.hpp, the one seam to the robot program: builtin in this
// process, on its threads or inline; external, attached by name, started by
// hand or launched by the runner; the public API's controller). The Runner
// knows nothing of the robot program beyond that interface and reads none
// of its state. Each tick (World::tickUs, the robots' body cycle: 10 ms on the
// V5, 12 ms on the V6; sim/runner/Bodies.hpp) runs these stages, in this
// order (Runner::tick; this is the one place the order is written down):
//   1. applyCommands      every robot's command latched last tick goes to its
//                         servos (and sonar mode): a command written during
//                         tick k acts during k+1, as the DCM sends Motion's
//                         output on its next cycle
//   2. applyPushes        scenario pushes due by now (World::applyImpulse)
//   3. World::step        physics advances one tick (its own substeps: World.hpp)
//   4. handleWorldEvents  blow-ups: counted, the robot's sensors restarted
//   5. captureOverview    the overview camera's frame, if one is due
//   6. publishSensors     scenario buttons, sensors read from the new state,
//                         each program's clock page set to the tick's time
//                         (docs/shim.md), each robot's slot written and its tick posted
//                         (the body side: sim/bridge/BodySide.hpp)
//   7. awaitMotion        every robot's Motion answers through its driver
//                         (inline: a builtin program's Motion step runs
//                         here, robot by robot, on this thread; the first
//                         tick attaches: external programs are waited for
//                         up to attach_timeout; then the wall-clock
//                         watchdog; free-running external robots are not
//                         waited for)
//   8. latchActuators     each robot's command (or libagent's own: limp, the
//                         sit), applied in stage 1 of the next tick
//   9. updateFalls        fall bookkeeping (statistics only)
//  10. cameraFrame        at 30 Hz of simulated time every robot with a
//                         Perception thread gets its frame (observations,
//                         images if rendered) and the runner waits for it
//                         (inline: runs its Perception step, robot by robot);
//                         a launched program's V4L2 cameras it streams are
//                         rendered and published, and the runner waits
//                         until it has dequeued them (common/v4l2/DeviceBlock.hpp)
//  11. teamAndGame        team network and GameController: the robots' own
//                         networks read (non-blocking, robot order:
//                         sim/network/RobotLan.hpp), outboxes drained,
//                         due packets delivered, game state advanced (robots
//                         penalised to the sideline and back) and written;
//                         with game: {udp: on} the SPL GameController packet
//                         sent every 500 ms and robots' return packets
//                         counted (never acted on: sim/game/GameControllerUdp)
//  12. captureViews       FindBall view frames, if asked (drawing only; the
//                         data from each driver's observer hook)
//  13. observe           each TickObserver (sim/runner/TickObserver.hpp)
//                         reads the finished tick: the recorder (sim/record)
// Robot threads run only inside stages 6-7 and 10, and the runner reads
// nothing of theirs until all have answered, so the outcome does not depend
// on thread timing: the same scenario and seed give the same state hash.
// Builtin programs run either on their own named threads (the default; gdb,
// `simswift run`) or inline (programs().setThreading: no threads, no
// hand-over; the experiment and the benchmarks): the same steps in the same order, the
// same hash (tests/runner/test_determinism.cpp).
//
// A robot program answers a tick the way libagent's clients do (it writes a
// joint command and sets actuators_latest; see sim/bridge/BodyHost.hpp), so
// an unchanged libagent program runs in lock-step. The first tick waits up
// to the scenario's attach_timeout for each robot's first answer (an
// external program may start before or after the simulator); after that a
// robot thread that does not answer within the watchdog (wall clock) stops
// the run with a WatchdogError naming the robot and the thread.
//
// Free-running (setFreeRunning, `simswift run --realtime`): external robot
// programs are not waited for after their first answer; they may miss
// cycles as on a NAO (counted as skipped; after 50 in a row the body sits
// down). Builtin programs stay in lock-step.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/libagent/SimExtensions.hpp"
#include "common/nao/NaoFacts.hpp"
#include "sim/bridge/BodyHost.hpp"
#include "sim/bridge/V4l2Devices.hpp"
#include "sim/game/GameController.hpp"
#include "sim/game/GameControllerUdp.hpp"
#include "sim/network/RobotLan.hpp"
#include "sim/game/Sideline.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/network/TeamNetwork.hpp"
#include "sim/runner/Errors.hpp"
#include "sim/runner/FallDetector.hpp"
#include "sim/runner/RunCameras.hpp"
#include "sim/runner/RunStats.hpp"
#include "sim/runner/Scenario.hpp"
#include "sim/runner/TickObserver.hpp"
#include "sim/sensors/SensorSuite.hpp"
#include "sim/views/FindBallRecorder.hpp"
#include "sim/world/World.hpp"

namespace simswift::vision {
class VisionOracle;
}

namespace simswift::programs {
class Programs;
}

namespace simswift::runner {

struct RunOptions {
  bool realtime = false;        // pace with the wall clock; external robots free-running
  int64_t print_hash_every = 0; // ticks; 0 = never (stdout)
  double progress_every_s = 5;  // simulated s between progress lines (stderr); <= 0 = never
  bool progress = true;
};


class Runner {
 public:
  explicit Runner(Scenario scenario);
  ~Runner();  // shuts robot programs down, joins builtin threads
  Runner(const Runner&) = delete;
  Runner& operator=(const Runner&) = delete;

  // The program side (sim/programs/Programs.hpp): what runs each robot's
  // body. Before start(): a builtin robot's test overrides (Motion step,
  // behaviour, Motion configuration, Perception step, step hook), threading
  // and the public API's controllers; after: each builtin robot's
  // RobotProgram (tests and benchmarks read its Blackboard between ticks)
  // and the launched programs' logs.
  programs::Programs& programs() { return *programs_; }
  const programs::Programs& programs() const { return *programs_; }
  // Builds the world, the robots' hosts and programs, the game and team
  // network, the cameras and the vision oracle (the build stages below).
  void start();
  // External robots free-running (see above); RunOptions::realtime sets it.
  void setFreeRunning(bool on);
  // One tick (World::tickUs). Throws WatchdogError.
  void tick();
  // start() if needed, then ticks until the scenario's duration.
  RunStats run(const RunOptions& options = {});
  // Stops robot programs (also done by the destructor).
  void shutdown();

  const Scenario& scenario() const { return scenario_; }
  World& world() { return *world_; }
  const World& world() const { return *world_; }
  int numRobots() const { return static_cast<int>(robots_.size()); }
  // Robot i's body side; host(i): the same as libagent's BodyHost (throws
  // RunnerError for a robot with another body interface).
  bridge::BodySide& body(int i) { return *robots_[i]->body; }
  bridge::BodyHost& host(int i);
  const sensors::SensorSuite& sensors(int i) const { return *robots_[i]->sensors; }
  int64_t ticks() const { return world_ ? world_->tick() : 0; }
  RunStats stats() const;  // so far
  // Robot i's sensor values as published this tick (what its program read).
  const common::libagent::SensorValues& lastSensors(int i) const { return robots_[i]->values; }
  // Robot i's command latched this tick (tick stage 8), applied to its
  // servos at the start of the next: what its program sent, unless libagent
  // acted on its own (limp, the sit after a lost contact); before the first
  // tick, what the body gets before any command.
  const common::libagent::ActuatorCommand& lastCommand(int i) const { return robots_[i]->latched; }
  // Robot i's fall bookkeeping (statistics only).
  const FallDetector& robotFall(int i) const { return robots_[i]->fall; }
  // The vision oracle (after start()): what each robot was shown in the
  // last camera frame (the experiment's found rule reads its ball sightings).
  const vision::VisionOracle& visionOracle() const { return *vision_; }
  // The robots' camera lens (one kind of robot per world: the scenario
  // refuses robots whose ticks differ), the V5's if there are no robots.
  common::nao::CameraLens camerasLens() const;
  int64_t lastFrame() const { return last_frame_; }  // index of the last camera frame (-1: none yet)
  // Teleports robot i, standing, to (x, y) m facing theta rad (field frame)
  // and restarts its sensors from rest (the experiment's sideline rule).
  void placeRobot(int i, double x, double y, double theta);

  // Cameras (scenario camera:, --dump-frames, --overview). Rendering needs a
  // build with cameras (RunCameras.hpp); start() throws RunnerError otherwise.
  static bool camerasAvailable();
  // Robot i's images block (null unless its cameras are rendered).
  const common::libagent::CameraImages* images(int i) const { return robots_[i]->images; }
  int64_t framesDumped() const;     // PNGs written by --dump-frames
  int64_t overviewFrames() const;   // overview PNGs written

  // Team communication and game states (after start()). Robot i's extension
  // objects beside its libagent block: the game state and the team link
  // (see common/libagent/SimExtensions.hpp). The runner touches them only in
  // tick stage 11 (teamAndGame), while no robot thread runs.
  common::libagent::SimExtensions* extensions(int i) { return robots_[i]->ext; }
  const network::TeamNetwork& teamNetwork() const { return *network_; }
  const game::GameController& gameController() const { return *game_; }
  // The UDP GameController (null unless the scenario's game: has udp: on).
  const game::GameControllerUdp* gameControllerUdp() const { return gc_udp_.get(); }
  // The robots' own networks (launched programs with wlan0); null before start.
  const network::RobotLan* robotLan() const { return lan_.get(); }
  // FindBall view frames (`--findball-view DIR`): every robot whose program
  // shows a search (ProgramDriver::findBallView, the observer hook) gets a
  // PNG per 1/rate_hz s of simulated time; run() assembles the videos.
  void setFindBallView(const sim::views::FindBallRecorderConfig& c) { findball_view_config_ = c; }
  // Observers called at the end of every tick (stage 13), in the order
  // added; not owned (they must outlive the run's ticks).
  void addObserver(TickObserver* observer) { observers_.push_back(observer); }
  void removeObserver(TickObserver* observer) {
    observers_.erase(std::remove(observers_.begin(), observers_.end(), observer), observers_.end());
  }
  // Robot i's scenario pushes applied so far (stage 2).
  int pushesApplied(int i) const { return static_cast<int>(robots_[i]->next_push); }
  // After run(): the overview video line (empty if no overview).
  const std::string& overviewMessage() const { return overview_message_; }
  // Ends the overview (assembles the video) and returns its message; run() calls it.
  std::string finishOverview();

 private:
  struct Robot {
    RobotSpec spec;
    std::string tag;
    std::unique_ptr<bridge::BodySide> body;
    std::unique_ptr<sensors::SensorSuite> sensors;
    // Camera images (set up by the host when rendering).
    common::libagent::CameraImages* images = nullptr;
    common::libagent::SensorValues values{};
    common::libagent::ActuatorCommand latched;
    bool perception = false;
    bool attached = false;  // has answered its first tick
    // Until its body's first command is latched (tick 1, stage 8), the robot
    // is held in its start posture (Runner::settleRobots): the hand that
    // placed it lets go once its program has read it.
    bool placed = true;
    FallDetector fall;  // torso-height fall bookkeeping (statistics only)
    double last_robot_contact_s = -1e9;  // s (world time) this robot last touched another robot
    size_t next_push = 0;  // next of spec.pushes to apply
    common::libagent::SimExtensions* ext = nullptr;  // the host's extension: game state + team link
    std::unique_ptr<bridge::V4l2Devices> v4l2;  // its cameras as V4L2 devices (a launched program's), or none
  };

  // Build stages (start(), in this order).
  void buildWorld();        // model, field, World, ball
  void buildHosts();        // per robot: World body, SensorSuite, body side (Bodies.hpp)
  void settleRobots();      // the robots at rest in their start postures before their programs first read them
  void holdStartPosture(int i);  // robot i's servos commanded to its start posture, stiffness 1
  // Ticks of physics the robots settle for before the run's first tick: a
  // placed robot sinks into its contacts for about two ticks (issue 45);
  // after them it still sways a little (first reading's accelerometer z
  // within about 0.6 m/s^2 of gravity, tests/nao_v6).
  static constexpr int kSettleTicks = 50;
  void attachPrograms();    // per robot: its program driver (sim/programs), from the scenario
  void buildTeamAndGame();  // TeamNetwork, GameController (and its UDP sender), the t = 0 game state
  void buildRobotLan();     // the launched programs' own networks (their wlan0s)
  void startCameras();      // if the scenario renders
  void buildVision();       // the vision oracle
  sensors::SensorConfig sensorConfig() const;

  std::vector<double> modelPosture(const common::nao::JointArray& angles) const;
  // Robot i's answer to what its body side posted (a tick or a camera
  // frame), through its driver: the watchdog ends the run if none comes.
  void awaitAnswer(int i, bool motion);
  // The V4L2 cameras (RobotSpec::v4l2): whether robot `spec` has them, its
  // frame published to the cameras its program streams, and the lock-step
  // wait until it has taken them (common/v4l2/DeviceBlock.hpp).
  bool servesV4l2(const RobotSpec& spec) const;
  void publishV4l2(int i, int64_t frame, int64_t t_us);
  void awaitV4l2(int i);
  [[noreturn]] void watchdogFail(int i, const char* thread) const;
  double watchdogWait() const;  // s per wait
  bool watchdogArmed() const;   // on, and no debugger attached

  Scenario scenario_;
  std::shared_ptr<const RobotModel> model_;
  std::unique_ptr<NaoBinding> nao_;  // the model's libagent joints (checked in buildHosts)
  std::unique_ptr<World> world_;
  std::vector<std::unique_ptr<Robot>> robots_;
  std::unique_ptr<programs::Programs> programs_;  // one driver per robot (destroyed before robots_)
  bool started_ = false;
  std::exception_ptr start_error_;  // what a failed start() threw (rethrown by start() and tick())
  bool stopped_ = false;
  int64_t last_frame_ = -1;
  std::unique_ptr<vision::VisionOracle> vision_;  // observations in every camera frame
  std::unique_ptr<RunCameras> cameras_;  // null unless the scenario renders
  std::string overview_message_;
  bool free_running_ = false;
  void renderFrame(int64_t frame, int64_t t_us, common::libagent::CameraFrame& f, Robot& r, int index);
  int blowups_ = 0;
  std::unique_ptr<network::TeamNetwork> network_;
  std::unique_ptr<game::GameController> game_;
  std::unique_ptr<game::PenaltyPlacer> placer_;
  std::unique_ptr<game::GameControllerUdp> gc_udp_;
  std::unique_ptr<network::RobotLan> lan_;  // the robots' own networks (after gc_udp_: it refers to them)
  std::vector<common::libagent::TeamLink*> links_;  // by robot index, for the network
  // Tick stages (see the top of this file).
  void applyCommands();
  void applyPushes();
  void handleWorldEvents();
  void captureOverview();
  void publishSensors(int64_t tick, int64_t t_us);
  void awaitMotion();
  void latchActuators();
  void updateFalls();
  void cameraFrame(int64_t t_us);
  void teamAndGame(int64_t t_us);
  void captureViews(int64_t t_us);
  std::vector<TickObserver*> observers_;
  std::optional<sim::views::FindBallRecorderConfig> findball_view_config_;
  std::unique_ptr<sim::views::FindBallRecorder> findball_view_;
  void captureFindBallView(int64_t t_us);
  std::chrono::steady_clock::time_point wall_start_;
};

}  // namespace simswift::runner
