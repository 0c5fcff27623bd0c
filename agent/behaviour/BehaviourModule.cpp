#include "agent/behaviour/BehaviourModule.hpp"

#include <cmath>
#include <cstring>

#include "agent/perception/PerceptionModules.hpp"

namespace agent::behaviour {

BehaviourInputs BehaviourModule::inputsFrom(const In& board) const {
  const BehaviourModuleConfig& c = c_;
  BehaviourInputs in;
  const blackboard::FrameInfo& frame = board.get<blackboard::FrameInfo>();
  const blackboard::LocalisationEstimate& loc = board.get<blackboard::LocalisationEstimate>();
  const blackboard::BallEstimate& ball = board.get<blackboard::BallEstimate>();
  const blackboard::GameInfo& game = board.get<blackboard::GameInfo>();
  const blackboard::MotionState& motion = board.get<blackboard::MotionState>();
  in.time = frame.time;
  in.player = c.player;
  in.walk = c.walk;

  in.self.pose = {loc.pose.x, loc.pose.y, loc.pose.theta};
  in.self.confidence = loc.confidence;
  in.self.flipped = loc.jumped;
  in.self.fallen = perception::postureIsDown(motion.posture);

  // The tracker's own estimate (when it has no track, x/y hold the team ball).
  in.ball.ever_seen = ball.valid;
  in.ball.seen_now = ball.seen_this_frame;
  in.ball.time_since_seen = ball.time_since_seen;
  if (ball.valid) {
    in.ball.relative = {ball.rr_x, ball.rr_y};
    in.ball.field = {ball.x, ball.y};
  }
  in.team_ball.valid = ball.team_valid;
  in.team_ball.time_since_seen = ball.team_age;
  in.team_ball.field = {ball.team_x, ball.team_y};

  // No game controller (a test field): playing throughout.
  in.game.state = game.known ? static_cast<GameState>(static_cast<int>(game.state)) : GameState::PLAYING;
  in.game.penalised = game.known && game.penalised;

  const blackboard::TeamInfo& team = board.get<blackboard::TeamInfo>();
  for (int p = 1; p <= blackboard::kMaxTeammates; ++p) {
    const blackboard::TeammateReport& r = team.mates[p];
    if (!r.valid || p == c.player) continue;
    Teammate t;
    t.player = p;
    t.pose = {r.x, r.y, r.theta};
    t.fallen = r.fallen;
    t.sees_ball = r.ball_age <= c.behaviour.skills.team_ball_max_age;
    t.time_since_heard = std::max(0.0, frame.time - r.received);
    if (!r.data.empty()) t.search = SearchPayload::fromBytes(r.data);
    in.teammates.push_back(std::move(t));
  }
  return in;
}

void BehaviourModule::update(const In& board, Out& written) {
  BehaviourInputs in = inputsFrom(board);
  // The chest sonars' first echoes (Left0, Right0; m -> mm), this frame.
  const common::libagent::SensorValues& sv = board.get<blackboard::SensorFrame>().values;
  in.sonar = sonar_.update(sv.sonar[0] * 1000.0, sv.sonar[10] * 1000.0);
  BehaviourOutput out = behaviour_.tick(in);
  written.get<blackboard::MotionRequest>() = out.request;

  blackboard::FindBallInfo fb;
  fb.active = true;
  fb.kind = static_cast<int32_t>(c_.behaviour.kind);
  fb.time = in.time;
  std::strncpy(fb.activity, out.activity ? out.activity : "", sizeof fb.activity - 1);
  if (const FindBallResult* r = behaviour_.findBall()) {
    fb.columns = r->distribution.columns();
    fb.rows = r->distribution.rows();
    fb.team = r->distribution.probabilities();
    fb.local = r->local.probabilities();
    // A reset (penalty, flip) makes the local distribution uniform again.
    bool uniform = true;
    for (double p : fb.local) uniform = uniform && std::fabs(p - 1.0 / fb.local.size()) < 1e-9;
    if (uniform && !was_uniform_) ++resets_;
    was_uniform_ = uniform;
  } else {  // 2016: no distribution (the view draws it uniform)
    const PositionalDistribution u = PositionalDistribution::fromConfig(c_.behaviour.grid, c_.behaviour.field);
    fb.columns = u.columns();
    fb.rows = u.rows();
    fb.team = fb.local = u.probabilities();
  }
  fb.resets = resets_;
  fb.segment = behaviour_.searchSegment();
  // A search runs under its kind's name (Searcher::tick).
  const auto running = [&out](BehaviourKind k) {
    return out.activity && std::strcmp(out.activity, behaviourKindName(k)) == 0;
  };
  const bool searching = running(BehaviourKind::FINDBALL_2017) || running(BehaviourKind::FINDBALL_2016);
  if (searching) {
    const Point2 p = behaviour_.searchPoint();
    fb.has_point = std::isfinite(p.x) && std::isfinite(p.y);
    fb.point_x = p.x;
    fb.point_y = p.y;
  } else {
    fb.segment = -1;
  }
  fb.pose_x = in.self.pose.x;
  fb.pose_y = in.self.pose.y;
  fb.pose_theta = in.self.pose.theta;
  for (const Teammate& t : in.teammates) fb.teammates.push_back(findBallTeammate(t));
  if (out.payload) fb.payload = out.payload->toBytes();
  written.get<blackboard::FindBallInfo>() = fb;
}

blackboard::FindBallTeammate findBallTeammate(const Teammate& t) {
  blackboard::FindBallTeammate m;
  m.player = t.player;
  m.x = t.pose.x;
  m.y = t.pose.y;
  m.theta = t.pose.theta;
  if (t.search && t.search->segment >= 0) {
    m.has_target = true;
    m.segment = t.search->segment;
    m.target_x = t.search->point.x;
    m.target_y = t.search->point.y;
  }
  return m;
}

}  // namespace agent::behaviour
