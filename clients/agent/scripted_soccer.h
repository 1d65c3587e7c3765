// The scripted baseline for soccer: the yardstick learned players must beat. It reads only the
// observation (blocks by name, in one place: ScriptedSoccerPolicy::see):
//
// - the chaser (in 1v1 and the penalty kick always; in 2v2 whichever of the two is nearer the
//   ball) walks (StepController) to a point behind the ball on the line from its aim through the
//   ball, going round the ball when it stands on the wrong side; lined up, it walks through the
//   ball: its swinging feet knock it on, a dribble that ends in a shot when the feet meet the
//   ball at speed. It aims at the goal's middle, or with a keeper in the goal (or the 2v2 guard in
//   front of it), inside the post away from it. In a match a ball within 11 m of the goal is kicked
//   (SoccerKick), not dribbled, once it lies on the kicking foot's side of the kicker's line (in
//   2v2 within 15 m too while an opponent not down is within 4 m of the ball);
// - in a match a player keeps off a ball an opponent is nearer (3 m, goal-side, beside the
//   opponent's way to the goal): most falls came from players walking into each other, and
//   from nearer, the holder's pushes gave the ball straight to the one keeping off;
// - the goalkeeper (penalty_kick_keeper, the side defending the near goal) stands on its line
//   between the ball and the goal's middle, moves across to where a shot will cross the line
//   and spreads its arms to block;
// - in 2v2 the other player stays between the ball and its own goal;
// - while the other side has a restart to take, both keep back from the ball.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

namespace control {
class BodyModel;
}
class SoccerKick;

class ScriptedSoccerPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

  // The speed a shot is kicked at to roll `distance_m` and still be quick at the goal line.
  static double shot_speed(double distance_m);
  // The direction of the last kick (heading frame) and its speed; for tests.
  const Eigen::Vector2d& kick_direction() const { return kick_direction_; }
  double kick_speed() const { return kick_speed_; }
  // What it did on the last tick: "keeper", "keep_back", "support", "yield" (an opponent has
  // the ball), "approach", "round", "push" (the dribble), "shoot_approach", "kick"; for
  // diagnosis and tests.
  const char* doing() const { return doing_; }
  const SoccerKick& kick() const { return *kick_; }

  // What the player sees, from the observation (heading frame, from the root).
  struct View {
    Eigen::Vector3d ball, ball_velocity;
    Eigen::Vector2d goal, own_goal;  // centres of the goal I attack and the one I defend
    std::optional<Eigen::Vector2d> teammate;
    std::vector<Eigen::Vector2d> opponents;
    std::vector<bool> opponent_down;
    bool theirs_to_take = false;  // the other side has a restart to take
    bool mate_down = false;
  };
  // Where a shot is aimed: the goal's middle, or with an opponent within 6 m of it (a keeper, the
  // 2v2 guard), 1.3 m off the middle on the side away from it (inside the post).
  static Eigen::Vector2d shot_aim(const View& v);
  // Whether a kick may start now, from where its start point is (`start`, from the root), the
  // kick's line `dir`, whether the walk is stepping and the root's velocity (heading frame). A
  // penalty: within 12 cm of the start point, standing, or walking slower than 0.45 m/s (the
  // root's full speed, vertical included, as the fifth round chose it) and swaying as a match
  // kick does (issue 30's penalty sway round). A match kick: up to
  // 25 cm behind it (5 cm past), standing or slower than 0.6 m/s, and swaying toward the kicking
  // (right) foot, faster than 0.05 m/s across the line.
  static bool at_penalty_kick_start(const Eigen::Vector2d& start, const Eigen::Vector2d& dir,
                                    bool stepping, const Eigen::Vector3d& velocity);
  static bool at_match_kick_start(const Eigen::Vector2d& start, const Eigen::Vector2d& dir,
                                  bool stepping, const Eigen::Vector2d& velocity);

 private:
  View see(std::span<const float> o) const;
  void keep_goal(std::span<const float> o, const View& v, std::span<float> a);
  void chase(std::span<const float> o, const View& v, std::span<float> a);
  void kick_chase(std::span<const float> o, const View& v, std::span<float> a);
  void walk(std::span<const float> o, const Eigen::Vector2d& to, double turn, std::span<float> a);

  struct Blocks {  // where the fields it reads start (teammate: the first's position; -1: none)
    int ball = 0, ball_velocity = 0, goal = 0, own_goal = 0, mate = -1, restart = 0;
    std::vector<int> opponents;  // each opponent's position
  };
  Blocks blocks_;
  double control_dt_ = 0;
  bool penalty_ = false;        // penalty_kick or penalty_kick_keeper
  bool keeper_mode_ = false;    // penalty_kick_keeper
  std::optional<bool> keeper_;  // am I the keeper (decided on the first tick)
  std::optional<StepController> legs_;
  std::shared_ptr<control::BodyModel> model_;  // shared: a policy may be copied
  std::shared_ptr<SoccerKick> kick_;
  Eigen::Vector2d kick_direction_{1, 0};  // heading frame
  double kick_speed_ = 0;                 // m/s the ball is kicked at
  const char* doing_ = "";
  bool lined_up_ = false;  // behind the ball and facing the aim: pushing it on
};

}  // namespace olympics::client
