#include "weight_shift_trial.h"

#include <cmath>
#include <cstdio>
#include <memory>

#include "control/body_model.h"
#include "registry.h"

namespace olympics::sports {
namespace {

using client::control::BodyModel;
using client::control::BodyPose;
using client::control::WeightShiftPlan;

constexpr int kAnkle[2] = {3, 7};  // left, right

// The match: SMPL-X players in a basketball 1v1 that runs on for the whole trial (no shot clock's
// restart, a fallen player left down), or the sandbox's solo SMPL humanoid.
std::unique_ptr<SportMatch> shift_match(bool smplx, std::uint64_t seed, double seconds,
                                        const std::string& falls = "report") {
  if (!smplx) return sport_or_throw("sandbox").create({"solo", seed, seconds, {}});
  return sport_or_throw("basketball")
      .create({"1v1", seed, seconds, {{"shot_clock_s", 60}, {"falls", falls}}});
}

}  // namespace

std::vector<ShiftTrial> shift_trials(bool smplx, std::uint64_t seed, WeightShiftPlan plan,
                                     const client::control::LegSupportGains& gains,
                                     bool half_and_half) {
  const double seconds = plan.back_at() + 1.0;
  const std::unique_ptr<SportMatch> m = shift_match(smplx, seed, seconds + 1);
  const BodyModel model =
      BodyModel::humanoid(smplx ? core::HumanoidKind::SmplX : core::HumanoidKind::Smpl);
  const int players = smplx ? 2 : 1;
  std::vector<ShiftTrial> trials(players);
  std::vector<WeightShiftPlan> plans(players, plan);
  if (players == 2) plans[1].onto_left = !plan.onto_left;
  std::vector<double> start_height(players, 0);
  std::vector<int> held_ticks(players, 0);
  std::vector<std::vector<float>> obs(players), act(players);
  const double dt = m->control_dt();
  const int ticks = static_cast<int>(std::lround(seconds / dt));
  for (int tick = 0; tick < ticks; ++tick) {
    const double t = tick * dt;
    for (int s = 0; s < players; ++s) {
      obs[s].assign(m->obs_size(), 0), act[s].assign(m->action_size(), 0);
      m->observe(s, obs[s]);
      const BodyPose pose = model.pose_from_observation(obs[s]);
      client::control::LegSupport support = plans[s].at(t);
      support.half_and_half = half_and_half;
      client::control::hold_on_legs(model, pose,
                                    client::control::centre_of_mass_velocity(model, obs[s]),
                                    support, act[s], gains);
      // The free foot's height over the stance foot, from where it stood at the start.
      const int stance = plans[s].onto_left ? 0 : 1;
      const double height =
          pose.position[kAnkle[1 - stance]].z() - pose.position[kAnkle[stance]].z();
      if (tick == 0) start_height[s] = height;
      ShiftTrial& r = trials[s];
      if (std::abs(t - (plans[s].shifted_at() + plans[s].loaded_s)) < 0.5 * dt) {
        const double com = model.centre_of_mass(pose).y();
        r.off_foot_m = std::abs(com - client::control::foot_centre(model, pose, stance == 0).y());
        r.off_ankle_m = std::abs(com - pose.position[kAnkle[stance]].y());
      }
      if (t >= plans[s].lifted_at() - 0.5 * dt && t <= plans[s].held_until()) {
        const double lift = height - start_height[s];
        r.lift_min_m = held_ticks[s] == 0 ? lift : std::min(r.lift_min_m, lift);
        r.lift_mean_m += (lift - r.lift_mean_m) / ++held_ticks[s];
      }
    }
    std::vector<std::span<const float>> actions(act.begin(), act.end());
    m->step(actions);
    for (const auto& e : m->outcome().info.value("events", nlohmann::json::array()))
      if (e.value("call", "") == "fall") {
        const int s = e.value("slot", 0);
        if (s < players && !trials[s].fell) trials[s].fell = true, trials[s].fell_at_s = t;
      }
    if (m->outcome().match_over) break;
  }
  return trials;
}

Stepping step_in_place(std::uint64_t seed, double seconds,
                       const client::control::SteppingPlan& plan,
                       const client::control::LegSupportGains& gains) {
  const std::unique_ptr<SportMatch> m = shift_match(true, seed, seconds + 1, "stand_up");
  const BodyModel model = BodyModel::humanoid(core::HumanoidKind::SmplX);
  Stepping out;
  double started[2] = {0, 0};
  int lifted[2] = {0, 0};
  std::vector<float> obs[2], act[2];
  const double dt = m->control_dt();
  const int ticks = static_cast<int>(std::lround(seconds / dt));
  for (int tick = 0; tick < ticks; ++tick) {
    const double t = tick * dt;
    for (int s = 0; s < 2; ++s) {
      obs[s].assign(m->obs_size(), 0), act[s].assign(m->action_size(), 0);
      m->observe(s, obs[s]);
      const int now = plan.steps_lifted(t - started[s]);
      out.steps += now - lifted[s];
      lifted[s] = now;
      client::control::hold_on_legs(model, model.pose_from_observation(obs[s]),
                                    client::control::centre_of_mass_velocity(model, obs[s]),
                                    plan.at(t - started[s]), act[s], gains);
    }
    m->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
    for (const auto& e : m->outcome().info.value("events", nlohmann::json::array())) {
      const std::string call = e.value("call", "");
      out.falls += call == "fall";
      if (call == "stood_up") {
        const int s = e.value("slot", 0);
        started[s] = t + dt, lifted[s] = 0;
      }
    }
  }
  out.minutes = 2 * seconds / 60;
  return out;
}

Walking walk_forward(std::uint64_t seed, double seconds, const client::control::SteppingPlan& plan,
                     const client::control::LegSupportGains& gains) {
  const std::unique_ptr<SportMatch> m = sport_or_throw("basketball")
                                            .create({"1v1",
                                                     seed,
                                                     seconds + 1,
                                                     {{"shot_clock_s", 60},
                                                      {"falls", "stand_up"},
                                                      {"court", "full"},
                                                      {"restart_distance", 6}}});
  const BodyModel model = BodyModel::humanoid(core::HumanoidKind::SmplX);
  // Each player's walk since its plan (re)started: how far forward, and as it was at its last
  // lift.
  struct Walk {
    double started = 0, forward = 0, forward_at_lift = 0;
    int lifted = 0;
    bool down = false;  // fallen, until the match stands it up
  } walk[2];
  Walking out;
  out.forward_each_m.assign(2, 0);
  const auto tally = [&](int s, bool fell) {
    const double d = fell ? walk[s].forward_at_lift : walk[s].forward;
    out.forward_m += d, out.forward_each_m[s] += d;
  };
  std::vector<float> obs[2], act[2], poses;
  const auto root = [&](int s) {  // in the scene's poses: each player's bodies, 7 floats each
    const std::size_t at = static_cast<std::size_t>(s) * model.size() * 7;
    return Eigen::Vector2d(poses[at], poses[at + 1]);
  };
  const double dt = m->control_dt();
  const int ticks = static_cast<int>(std::lround(seconds / dt));
  int tick = 0;
  for (; tick < ticks; ++tick) {
    const double t = tick * dt;
    for (int s = 0; s < 2; ++s) {
      obs[s].assign(m->obs_size(), 0), act[s].assign(m->action_size(), 0);
      m->observe(s, obs[s]);
      Walk& w = walk[s];
      const int now = plan.steps_lifted(t - w.started);
      if (now > w.lifted) w.forward_at_lift = w.forward;
      out.steps += now - w.lifted;
      w.lifted = now;
      const Eigen::Vector3d v = client::control::centre_of_mass_velocity(model, obs[s]);
      w.forward += v.x() * dt;
      client::control::hold_on_legs(model, model.pose_from_observation(obs[s]), v,
                                    plan.at(t - w.started), act[s], gains);
    }
    m->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
    bool restart = false;
    for (const auto& e : m->outcome().info.value("events", nlohmann::json::array())) {
      const std::string call = e.value("call", "");
      const int s = e.value("slot", 0);
      if (call == "fall") ++out.falls, tally(s, true), walk[s].down = true;
      if (call == "stood_up") walk[s] = Walk{t + dt, 0, 0, 0, false};
      restart |= call == "restart";
    }
    m->scene_poses(poses);
    if (restart || (root(0) - root(1)).norm() < 1.5) break;
  }
  for (int s = 0; s < 2; ++s)
    if (!walk[s].down) tally(s, false);
  out.minutes = 2 * tick * dt / 60;  // a walk cut short counts up to the tick that cut it
  return out;
}

std::string describe(const ShiftTrial& t) {
  char line[200];
  std::snprintf(line, sizeof line,
                "centre of mass %.3f m off the foot, %.3f off the ankle; lift %.3f m (least "
                "%.3f); %s",
                t.off_foot_m, t.off_ankle_m, t.lift_mean_m, t.lift_min_m, t.fell ? "fell" : "up");
  std::string out = line;
  if (t.fell) out += " at " + std::to_string(t.fell_at_s) + " s";
  return out;
}

}  // namespace olympics::sports
