// The basketball half court of FIBA 3x3 (15 m wide, 11 m deep) with one basket, and the
// geometric rules: what is a basket and where the 2-point arc is.
//
// Frame: the origin is on the floor under the rim's centre, the court lies towards -x, the
// baseline is at x = +kRimToBaseline. The rim is real collision geometry, a ring of thin capsules
// (a ball can roll round it and bounce out), on a backboard (1.8 x 1.05 m, its face 0.15 m behind
// the rim's inner edge, its lower edge at 2.9 m) held by a pole behind the baseline.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/physics_world.h"
#include "framework/scene_view.h"

namespace olympics::sports::basketball {

struct Court {
  double width = 15, depth = 11;
  double rim_height = 3.05;          // the original's is 2.8
  double rim_radius = 0.225;         // inside
  double free_throw_distance = 4.6;  // from the backboard's plane to the line
  double arc_radius = 6.75;          // from the point under the rim's centre
  double corner_line = 6.6;          // |y| beyond which a shot is behind the arc (straight part)

  static constexpr double kRimRod = 0.01;          // m, the rim's rod radius
  static constexpr double kRimToBoard = 0.15;      // inner edge of the rim to the board's face
  static constexpr double kRimToBaseline = 1.575;  // FIBA: the board's face 1.2 m inside
  static constexpr double kBoardWidth = 1.8, kBoardHeight = 1.05, kBoardBottom = 2.9;
  static constexpr double kBoardHalfThickness = 0.025;
  static constexpr int kRimSegments = 24;

  Eigen::Vector3d rim_centre() const { return {0, 0, rim_height}; }
  double board_face_x() const { return rim_radius + kRimToBoard; }
  double baseline_x() const { return kRimToBaseline; }
  double far_line_x() const { return kRimToBaseline - depth; }
  double free_throw_line_x() const { return board_face_x() - free_throw_distance; }
  // A point on the floor behind the 2-point arc (a shot released there is worth 2).
  bool behind_arc(const Eigen::Vector2d& p) const { return beyond_arc(p) > 0; }
  // How far a point is beyond the arc (its curve or the straight corner lines), negative inside.
  double beyond_arc(const Eigen::Vector2d& p) const;
  // Is the point (x, y) on the court (inside the lines)?
  bool inside(const Eigen::Vector2d& p) const;
  // Did a ball whose centre went from `before` to `after` in one physics step pass downward
  // through the rim's plane inside the rim (centre within the inner radius where it crossed)?
  bool basket(const Eigen::Vector3d& before, const Eigen::Vector3d& after) const;

  struct Part {
    enum Kind { Rim, Board, Pole } kind;
    Eigen::Vector3d a, b;  // capsule: ends; box: centre and half extents
    double radius = 0;
  };
  std::vector<Part> parts() const;
  void build(core::PhysicsWorld& world) const;
  // Floor, lines (sidelines, baseline, far line, arc, free-throw line and lane), basket.
  void describe(SceneBuilder& scene) const;
};

}  // namespace olympics::sports::basketball
