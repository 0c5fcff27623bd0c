#include "sim/game/GameController.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace simswift::game {

namespace al = common::libagent;

namespace {
constexpr double kReadySeconds = 45;  // SPL: READY lasts at most 45 s
int64_t toUs(double s) { return static_cast<int64_t>(std::llround(s * 1e6)); }

struct Named { const char* name; int value; };
constexpr Named kStates[] = {{"initial", 0}, {"ready", 1}, {"set", 2}, {"playing", 3}, {"finished", 4}};
constexpr Named kPenalties[] = {
    {"none", 0},           {"illegal_ball_contact", 1}, {"player_pushing", 2},
    {"illegal_motion_in_set", 3}, {"inactive_player", 4}, {"illegal_defender", 5},
    {"leaving_the_field", 6}, {"kick_off_goal", 7},     {"request_for_pickup", 8},
    {"substitute", 14},    {"manual", 15}};
}  // namespace

const char* stateName(GameStateValue s) {
  for (const Named& n : kStates)
    if (n.value == static_cast<int>(s)) return n.name;
  return "unknown";
}
const char* penaltyName(Penalty p) {
  for (const Named& n : kPenalties)
    if (n.value == static_cast<int>(p)) return n.name;
  return "unknown";
}
bool parseState(const std::string& name, GameStateValue* out) {
  for (const Named& n : kStates)
    if (name == n.name) {
      *out = static_cast<GameStateValue>(n.value);
      return true;
    }
  return false;
}
bool parsePenalty(const std::string& name, Penalty* out) {
  for (const Named& n : kPenalties)
    if (name == n.name) {
      *out = static_cast<Penalty>(n.value);
      return true;
    }
  return false;
}
std::vector<std::string> stateNames() {
  std::vector<std::string> v;
  for (const Named& n : kStates) v.push_back(n.name);
  return v;
}
std::vector<std::string> penaltyNames() {
  std::vector<std::string> v;
  for (const Named& n : kPenalties) v.push_back(n.name);
  return v;
}

GameController::GameController(GameConfig config, std::vector<RobotId> robots)
    : config_(std::move(config)), state_(config_.initial_state), kickoff_team_(config_.kickoff_team) {
  for (const RobotId& r : robots) robots_.push_back({r, Penalty::None, -1});
  for (const GameConfig::PenaltyEvent& p : config_.penalties)
    if (p.robot < 0 || p.robot >= static_cast<int>(robots_.size()))
      throw std::invalid_argument("game controller: no robot " + std::to_string(p.robot));
}

std::vector<GameEvent> GameController::update(int64_t t_us) {
  std::vector<GameEvent> events;
  const int64_t dt = now_us_ < 0 ? 0 : t_us - now_us_;
  if (state_ == GameStateValue::Playing && dt > 0) played_us_ += dt;
  now_us_ = t_us;
  ++updates_;

  // 1. State changes due by now (in timeline order).
  while (next_change_ < config_.timeline.size() && toUs(config_.timeline[next_change_].t_s) <= t_us) {
    const GameConfig::StateChange& c = config_.timeline[next_change_++];
    if (c.state != state_) state_since_us_ = toUs(c.t_s);
    state_ = c.state;
    secondary_ = c.secondary;
    if (c.kickoff_team >= 0) kickoff_team_ = c.kickoff_team;
  }
  // 2. Penalty timers that ran out (robot index order).
  for (size_t i = 0; i < robots_.size(); ++i) {
    RobotState& r = robots_[i];
    if (r.penalty != Penalty::None && r.until_us >= 0 && t_us >= r.until_us) {
      events.push_back({GameEvent::Kind::Unpenalised, static_cast<int>(i), r.penalty});
      r.penalty = Penalty::None;
      r.until_us = -1;
    }
  }
  // 3. Scenario penalties due by now (in list order).
  while (next_penalty_ < config_.penalties.size() && toUs(config_.penalties[next_penalty_].t_s) <= t_us) {
    const GameConfig::PenaltyEvent& p = config_.penalties[next_penalty_++];
    RobotState& r = robots_[p.robot];
    if (p.penalty == Penalty::None) {
      if (r.penalty != Penalty::None) events.push_back({GameEvent::Kind::Unpenalised, p.robot, r.penalty});
      r.penalty = Penalty::None;
      r.until_us = -1;
      continue;
    }
    const bool was = r.penalty != Penalty::None;
    r.penalty = p.penalty;
    r.until_us = p.duration_s < 0 ? -1 : toUs(p.t_s + p.duration_s);
    if (!was) events.push_back({GameEvent::Kind::Penalised, p.robot, p.penalty});
  }
  return events;
}

double GameController::secsRemaining() const {
  return std::max(0.0, config_.half_duration_s - played_us_ * 1e-6);
}

double GameController::secsTillUnpenalised(int robot) const {
  const RobotState& r = robots_.at(robot);
  if (r.penalty == Penalty::None || r.until_us < 0) return 0;
  return std::max<double>(0.0, (r.until_us - now_us_) * 1e-6);
}

int GameController::teamNumber(int side) const {
  for (const RobotState& r : robots_)
    if (r.id.team == side && r.id.team_number >= 0) return r.id.team_number;
  return side;  // no robot gave a number: the side index stands in
}

void GameController::fill(al::GameStateBlock& b) const {
  b.magic = al::kGameStateMagic;
  b.updates = updates_;
  b.sim_time_us = now_us_ < 0 ? 0 : now_us_;
  b.state = static_cast<uint8_t>(state_);
  b.secondary_state = static_cast<uint8_t>(secondary_);
  b.first_half = config_.first_half ? 1 : 0;
  // As the GameController sends it: the kick-off team's SPL number (255 = drop ball).
  b.kickoff_team = kickoff_team_ == 0 || kickoff_team_ == 1 ? static_cast<uint8_t>(teamNumber(kickoff_team_))
                                                            : static_cast<uint8_t>(kickoff_team_);
  b.secs_remaining = static_cast<uint16_t>(std::ceil(secsRemaining() - 1e-9));
  b.secondary_time = 0;
  if (state_ == GameStateValue::Ready) {
    const double left = kReadySeconds - (std::max<int64_t>(0, now_us_ - state_since_us_)) * 1e-6;
    b.secondary_time = static_cast<uint16_t>(std::max(0.0, std::ceil(left - 1e-9)));
  }
  for (int t = 0; t < 2; ++t) {
    al::GameTeamInfo& team = b.teams[t];
    team = al::GameTeamInfo{};
    team.team_number = static_cast<uint8_t>(teamNumber(t));
    team.team_colour = static_cast<uint8_t>(t);
  }
  for (size_t i = 0; i < robots_.size(); ++i) {
    const RobotState& r = robots_[i];
    if (r.id.team < 0 || r.id.team > 1 || r.id.player < 1 || r.id.player > al::kGameMaxPlayers) continue;
    al::GamePlayerInfo& p = b.teams[r.id.team].players[r.id.player - 1];
    p.penalty = static_cast<uint8_t>(r.penalty);
    const double s = secsTillUnpenalised(static_cast<int>(i));
    p.secs_till_unpenalised = static_cast<uint8_t>(std::min(255.0, std::ceil(s - 1e-9)));
  }
}

}  // namespace simswift::game
