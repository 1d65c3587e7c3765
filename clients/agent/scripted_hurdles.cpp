#include "scripted_hurdles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {
namespace {

constexpr double kAhead_m = 2.0;       // m: it walks toward its lane's centre line this far ahead
constexpr double kLean_rad = 0.3;      // forward, per trunk joint (torso, spine, chest)
constexpr double kLeanWithin_m = 0.7;  // m to a standing hurdle's top bar

}  // namespace

void ScriptedHurdlesPolicy::start(const MatchInfo& match) {
  if (match.sport != "hurdles")
    throw std::invalid_argument("the scripted hurdles policy runs the hurdles, not " + match.sport);
  goal_ = match.observation.offset("goal", "position");
  first_ = match.observation.offset("hurdles", "hurdle_0");
  legs_.emplace(StepGains{}, match.control_dt);
}

void ScriptedHurdlesPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedHurdlesPolicy: act() before start()");
  std::fill(a.begin(), a.end(), 0.0f);
  // The lane's centre line runs through the goal (the finish line's point on it) and the first
  // hurdle's top bar (standing, or lying where it fell forward: still on the line across): it
  // walks toward the point on that line kAhead_m past its own, so a drift off the centre is
  // walked back, and it turns to face along the line.
  const Eigen::Vector2d goal(o[goal_], o[goal_ + 1]), first(o[first_], o[first_ + 1]);
  const Eigen::Vector2d along = (goal - first).normalized();
  const Eigen::Vector2d target = first + along * (-first.dot(along) + kAhead_m);
  const double turn = std::atan2(along.y(), along.x());
  legs_->act(o, target, turn, a);
  // Close to a standing hurdle it leans its trunk forward, so that the chest meets the top bar
  // and pushes it over; upright, the bar meets the lower trunk, whose round front lifts it, and
  // the walker carries the hurdle along instead (seeds 1-2, tuning: leaning 0.15 rad per joint
  // or none, the hurdle is carried; 0.3 tips it over within 0.7 m).
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector3d h(o[first_ + 3 * i], o[first_ + 3 * i + 1], o[first_ + 3 * i + 2]);
    if (h.x() > 0 && h.x() < kLeanWithin_m && h.z() > 0) {
      for (int body : {int{smpl::kTorso}, 10, int{smpl::kChest}})
        smpl::set_joint(a, body, 1, kLean_rad);
      break;
    }
  }
}

std::unique_ptr<Policy> make_scripted_hurdles() {
  return std::make_unique<ScriptedHurdlesPolicy>();
}

}  // namespace olympics::client
