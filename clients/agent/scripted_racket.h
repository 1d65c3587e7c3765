// The scripted baseline for tennis and table tennis: the yardstick that learned policies must
// beat. It plays from the observation alone, with the control toolkit (control/):
//
// - prediction: the ball's path is stepped forward with the server's own flight model (drag,
//   bounces off the court or table and the net) from the observed ball;
// - the stroke: on that path it picks the point to meet the ball (after its bounce on the own
//   side, within the racket arm's reach, or where the legs can take the body in time) and plans
//   the shot to a point deep in the middle of the far half: the outgoing velocity that clears the
//   net, and the face normal and speed along a level swing that give it (control/stroke_plan.h);
// - the arm: the face is drawn back along that level line and swung through the meeting point at
//   the planned speed, timed to the ball (tennis: an arc turned about the shoulder, at a speed
//   the arm can deliver, the face's normal solved for that speed; once the ball is within reach
//   swung in joint space, scripted_tennis_swing.h); each tick the arm's joints come
//   from inverse kinematics of the face's pose (control/limb_control.h), with gravity compensation
//   and velocity feed-forward as PD-target offsets (control/drive_target.h), the root's motion
//   allowed for;
// - the legs: a StepController walks toward where the ball will be met, then stands balancing
//   the centre of mass (control/body_model.h) while the arm swings; between balls it walks home.
// In doubles, table-tennis partners strike in turn (a point's first stroke by the partner on
// whose side the ball lands) and tennis partners take the nearer ball.
// With the racket sports' `start: "serve"` it serves the toss legally (control/serve_plan.h).
// docs/racket-sports.md has its figures.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "control/ball_path.h"
#include "control/body_model.h"
#include "control/limb_control.h"
#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedRacketPolicy : public Policy {
 public:
  ScriptedRacketPolicy();
  ~ScriptedRacketPolicy() override;
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

  // Where the observation's fields it reads start (match_info.h: found by name).
  struct Blocks {
    int ball = 0, ball_velocity = 0, court_x = 0, court_y = 0, heading_cos = 0, heading_sin = 0,
        struck = 0, coming = 0, bounces = 0, landing = 0;
  };
  // The stroke being played (court frame), for tests and tuning.
  struct Stroke {
    double time_to_hit = 0;     // s from this tick
    Eigen::Vector3d ball_at;    // ball centre at contact
    Eigen::Vector3d normal;     // face normal
    Eigen::Vector3d direction;  // the swing's line
    double speed = 0;           // face speed along it
    bool reachable = false;     // from where the player stands now
    Eigen::Vector3d stance;     // where the root should be to meet it at the sweet spot
    // An arc swing turns about the vertical through here; none: a straight swing.
    std::optional<Eigen::Vector3d> pivot;
    bool serve = false;  // the serve's (its swing holds the turn's load, the free arm against it)
  };
  const std::optional<Stroke>& stroke() const { return stroke_; }
  // The legs (none before the first act()), for tests.
  const std::optional<StepController>& legs() const { return legs_; }

 private:
  struct Sport;
  void plan(std::span<const float> o, const control::CourtFrame& court,
            const control::BodyPose& pose);
  // `start: "serve"`: is the ball a toss for this player? Then the serve is planned (or kept)
  // by the stroke planner (control/serve_plan.h).
  bool plan_serve(std::span<const float> o, const control::CourtFrame& court,
                  const control::BodyPose& pose);
  // `legs_walking`: this tick the legs were asked to walk somewhere (Play::swing_once_settled).
  void drive_arm(const control::CourtFrame& court, const control::BodyPose& pose, bool legs_walking,
                 std::span<float> a);
  // How far from the racket shoulder a rally ball is met: the arm's share of its reach and the
  // trunk's lean (m).
  double rally_reach() const;

  // Doubles: is it this player's ball (its side of the court in tennis, its turn at the table)?
  bool my_ball(const control::CourtFrame& court, const Eigen::Vector3d& partner,
               const Eigen::Vector3d& ball, const Eigen::Vector3d& landing, bool team_coming,
               bool new_point);

  Blocks blocks_;
  std::vector<int> others_;  // the other players' root positions ("others"; none in ball return)
  bool doubles_ = false;
  // Table-tennis doubles' turn: did this player strike while the ball was its team's, and is it
  // its turn (unknown at a point's first stroke: the player nearer the ball takes it).
  bool struck_this_turn_ = false, was_coming_ = false;
  int my_turn_ = -1;                                     // 1 yes, 0 no, -1 unknown
  Eigen::Vector3d last_ball_ = Eigen::Vector3d::Zero();  // court frame, the last tick's
  // The ball now coming was swung at and passed the racket (Play::let_go_missed).
  bool missed_ = false;
  std::unique_ptr<Sport> sport_;
  double control_dt_ = 0;
  std::optional<StepController> legs_;
  std::optional<Stroke> stroke_;
  Eigen::Vector3d root_velocity_ = Eigen::Vector3d::Zero();  // heading frame, this tick
  double since_stroke_s_ = 1e9;                              // time since the last planned contact
};

}  // namespace olympics::client
