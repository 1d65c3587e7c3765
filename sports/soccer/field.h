// The soccer field (SPORTS.md: the seed's 32 x 20 m, a setting), centred on the origin with its
// length along x: goals 4 m wide and 2 m high centred on the goal lines x = -L/2 and x = +L/2,
// posts and crossbar 12 cm thick as real collision geometry on the goal line (which is as wide as
// the posts are deep, Law 1: it runs from x = L/2 to L/2 + 12 cm), and a net behind
// each goal (back, sides, roof) that stops the ball. Walls around the field (the original's) are
// an option. The geometric rules live here too: what is a goal and what is out of play.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/physics_world.h"
#include "framework/scene_view.h"

namespace olympics::sports::soccer {

// Which line the whole ball has crossed, if any.
enum class Crossed { None, TouchLine, GoalLine, Goal };

struct Field {
  double length = 32, width = 20;
  double goal_width = 4, goal_height = 2;  // inside the posts and under the bar
  double post_radius = 0.06;
  double net_depth = 1.5;
  bool walls = false;
  double wall_margin = 1.5;  // walls this far outside the lines
  double wall_height = 1.0;

  double half_length() const { return length / 2; }
  double half_width() const { return width / 2; }
  // The goal line's far edge, |x|: Law 1 makes the goal line as wide as the posts (12 cm), and
  // the posts stand on it from the field's edge x = L/2 back.
  double goal_line_outer() const { return half_length() + 2 * post_radius; }
  // The centre of the goal mouth at `end` (-1: x = -L/2, +1: x = +L/2), at half its height.
  Eigen::Vector3d goal_centre(int end) const;
  // Where a ball centred at `p` (radius r) is: in play, wholly over a touch line, wholly over a
  // goal line outside the goal, or wholly over a goal line between the posts and under the bar
  // (a goal). "Wholly over a goal line": over the whole of its width (Law 9 and 10), its centre
  // more than r beyond goal_line_outer(). `end` (set when a goal line was crossed): the end whose
  // line it crossed.
  Crossed crossed(const Eigen::Vector3d& p, double r, int* end = nullptr) const;

  // The goals' static boxes and capsules: posts, bar, nets; and the walls when set.
  struct Part {
    enum Kind { Post, Net, Wall } kind;
    Eigen::Vector3d a, b;  // capsule: ends; box: centre and half extents
  };
  std::vector<Part> parts() const;
  void build(core::PhysicsWorld& world) const;
  // The grass, the lines (touch and goal lines, halfway line, centre circle, goal areas, penalty
  // spots), goals and nets, for viewers.
  void describe(SceneBuilder& scene) const;

  static constexpr double kNetHalfThickness = 0.02;
  static constexpr double kCentreCircle = 3.0;  // m, radius (scaled with the field)
  static constexpr double kGoalArea = 2.5;      // m from the goal line: where goal kicks go
};

}  // namespace olympics::sports::soccer
