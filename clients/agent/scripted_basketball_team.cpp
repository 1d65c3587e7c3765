#include "scripted_basketball_team.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ball_aim.h"
#include "control/standing_balance.h"
#include "smplx_observation.h"

namespace olympics::client {

using namespace smplx;

bool ScriptedBasketballTeamPlayer::rim_in_reach(std::span<const float> o) const {
  // From where the strongest swing releases the ball (its measured response), as the shooter
  // aims.
  const SwingResponse& strongest = shot_.swing.back();
  const Eigen::Vector3d ball = vec3(o, ball_), rim = vec3(o, rim_);
  const double carry = (rim - ball).head<2>().norm() - strongest.ahead;
  const double rise = rim.z() - ball.z() - strongest.up;
  const double speed = launch_speed_for(carry, rise, shot_.launch_elevation, shot_.ball_drag);
  return speed > 0 && speed <= strongest.speed;
}

void ScriptedBasketballTeamPlayer::start(const MatchInfo& match) {
  if (match.sport != "basketball" || (match.mode != "1v1" && match.mode != "2v2"))
    throw std::invalid_argument(
        "the scripted basketball team player plays basketball 1v1 or 2v2, not " + match.sport +
        " " + match.mode);
  match_ = match;
  ball_ = match.observation.offset("ball", "position");
  rim_ = match.observation.offset("rim", "centre");
  presented_ = match.observation.offset("game", "presented_to_me");
  shooter_.reset();
  was_presented_ = false;
  shots_ = heaves_ = throws_out_ = 0;
}

void ScriptedBasketballTeamPlayer::act(std::span<const float> o, std::span<float> a) {
  if (a.size() != kActions || o.size() < static_cast<size_t>(kSelfObservation))
    throw std::invalid_argument("the scripted basketball team player plays the SMPL-X humanoid");
  // A restart presents the ball to me: a new shot, whatever the last one was doing.
  const bool presented = o[presented_] > 0.5f;
  if (presented && !was_presented_) {
    FreeThrowShot shot = shot_;
    const bool in_reach = rim_in_reach(o);
    // Beyond the set shot's reach: the long shot (the collar bones lift the arms too), aimed by
    // the ballistic solution, untrimmed.
    if (!in_reach) shot.long_shot = true, shot.trim_tick = 0;
    // The rim behind me (the ball taken under the basket after the other side scored, to be
    // cleared behind the arc, which I cannot walk to): throw it out over the far line at once,
    // which hands the other side its check ball as the shot clock would, 12 s later.
    const Eigen::Vector3d rim = vec3(o, rim_);
    if (std::abs(std::atan2(rim.y(), rim.x())) > M_PI / 2) {
      shot.long_shot = shot.throw_ahead = true, shot.trim_tick = 0, shot.twist_gain = 0;
      ++throws_out_;
    }
    shooter_.emplace(shot);
    shooter_->start(match_);
    shot_clock_s_ = 0;
    ++shots_;
    heaves_ += !in_reach;
  }
  was_presented_ = presented;
  if (shooter_) {
    shooter_->act(o, a);
    shot_clock_s_ += match_.control_dt;
    // Until the ball has left, the shooter's own stance: its swing was measured on it, and on
    // the balance below (from the cradle on) the ball leaves flat and slow: under 4 m/s towards
    // the rim on seeds 1-5, against 4.5-6.9.
    const bool released = shot_clock_s_ > shot_.shot_s + kRelease_s;
    if (shot_clock_s_ >= kShotPlay_s) shooter_.reset();
    if (!released) return;
  } else {
    std::fill(a.begin(), a.end(), 0.0f);
  }
  control::hold_standing_balance(model_, model_.pose_from_observation(o), vec3(o, kLinVel), a);
}

// Basketball's scripted player: the free-throw shooter at a free throw, the team player in team
// play (the registry in scripted_policy.cpp names this factory).
class ScriptedBasketballPlayer : public Policy {
 public:
  void start(const MatchInfo& match) override {
    if (match.mode == "free_throw")
      policy_ = std::make_unique<ScriptedBasketballPolicy>();
    else
      policy_ = std::make_unique<ScriptedBasketballTeamPlayer>();
    policy_->start(match);
  }
  void act(std::span<const float> observation, std::span<float> action) override {
    if (!policy_) throw std::logic_error("ScriptedBasketballPlayer: act() before start()");
    policy_->act(observation, action);
  }

 private:
  std::unique_ptr<Policy> policy_;
};

std::unique_ptr<Policy> make_scripted_basketball_team() {
  return std::make_unique<ScriptedBasketballPlayer>();
}

}  // namespace olympics::client
