// A serve planned by the stroke planner (stroke_plan.h), for the `start: "serve"` setting of the
// racket sports: the ball tossed for the server is met on its way down, within the racket arm's
// reach, and sent where a serve must land: tennis into the diagonal service box; table tennis
// onto the server's own court first and from there over the net onto the receiver's (doubles:
// right half to right half).
//
// Frame: the court frame of ball_path.h (own half at negative x, the net along y at x = 0).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "control/ball_path.h"
#include "control/stroke_plan.h"

namespace olympics::client::control {

// Is a ball with this velocity a toss, anyone's: hardly moving across the court (a fed or struck
// ball flies at metres a second).
bool hardly_moving_across(const Eigen::Vector3d& velocity);

// Is the ball a toss for the player at `root`: its side's to play, not bounced, on its half,
// within 1.5 m of it and hardly moving across the court (hardly_moving_across).
bool is_toss(const Eigen::Vector3d& ball, const Eigen::Vector3d& velocity,
             const Eigen::Vector3d& root);

// Where a server standing at `root` aims: diagonally across (tennis: the middle of the service
// box on the other side of the centre line; table tennis: the receiver's court, its own court
// first); a server on the centre line aims down the middle.
struct ServeAim {
  Eigen::Vector2d landing{0, 0};     // where the serve should land on the receiver's side
  Eigen::Vector2d own_bounce{0, 0};  // table tennis: its first bounce on the server's court
  LandingArea box;                   // tennis: the service box, kServeBoxInside within its lines
};
ServeAim serve_aim(const sports::racket::RacketGame& game, const Eigen::Vector3d& root);

// The soonest a serve is met after it is planned: the arm needs that long to draw back and come
// through (tuning seeds 1-40 of table tennis: 0.3 s met 40 of 40 tosses, 0.4 s 9, 0.2 s none).
constexpr double kServeSoonestS = 0.3;

struct ServePlan {
  BallSample contact;  // where and when the ball is met (its centre)
  ShotPlan shot;
};

// Tennis: a serve planned for the ball to land this far inside the service box's lines (m).
constexpr double kServeBoxInside = 0.4;

// On the toss's predicted path, the falling points whose face position (the ball's centre
// `face_back` m back along -x) lies within `reach` of the shoulder, nearest `sweet_spot` (court
// frame, absolute) first and no sooner than `min_time`: the first for which a level swing toward
// the landing sends the ball legally, clearing the net by `net_margin`; nullopt when none does.
std::optional<ServePlan> plan_serve(const BallPath& path, const std::vector<BallSample>& toss,
                                    const Eigen::Vector3d& shoulder, double reach, double face_back,
                                    const Eigen::Vector3d& sweet_spot, const ServeAim& aim,
                                    double net_margin, double min_time);

// Tennis, the serve swung on an arc about the shoulder's vertical (`arc_tangent`): at the same
// meeting points as `plan_serve`, where the arc runs toward the net, the least of `speeds` (m/s of
// face along the arc's tangent, ascending) for which a face normal sends the ball into the service
// box (`plan_shot_at_speed`); the shot's face direction is the tangent. A level swing toward the
// box asks the face for about 9 m/s (a ball at about 12 m/s); the arc is where this arm's face is
// fastest.
std::optional<ServePlan> plan_arc_serve(const BallPath& path, const std::vector<BallSample>& toss,
                                        const Eigen::Vector3d& shoulder, double reach,
                                        double face_back, const Eigen::Vector3d& sweet_spot,
                                        const ServeAim& aim, double net_margin, double min_time,
                                        const std::vector<double>& speeds);

}  // namespace olympics::client::control
