// The basketball court: the half court of FIBA 3x3 (15 m wide, 11 m deep) with one basket, or
// (`full`) the whole 28 m court with a basket at each end; and the geometric rules: what is a
// basket and where the arcs are.
//
// Frame: the origin is on the floor under the (first) rim's centre, the court lies towards -x,
// the baseline is at x = +kRimToBaseline. The full court's second basket is the first turned
// half round about the court's centre (x = kRimToBaseline - 14). The rim is real collision
// geometry, a ring of thin capsules (a ball can roll round it and bounce out), on a backboard (1.8
// x 1.05 m, its face 0.15 m behind the rim's inner edge, its lower edge at 2.9 m) held by a pole
// behind the baseline.
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
  bool full = false;                 // the whole court, a basket at each end

  static constexpr double kRimRod = 0.01;          // m, the rim's rod radius
  static constexpr double kRimToBoard = 0.15;      // inner edge of the rim to the board's face
  static constexpr double kRimToBaseline = 1.575;  // FIBA: the board's face 1.2 m inside
  static constexpr double kBoardWidth = 1.8, kBoardHeight = 1.05, kBoardBottom = 2.9;
  static constexpr double kBoardHalfThickness = 0.025;
  static constexpr int kRimSegments = 24;
  static constexpr double kFullLength = 28;  // FIBA

  int baskets() const { return full ? 2 : 1; }
  double length() const { return full ? kFullLength : depth; }
  Eigen::Vector3d rim_centre(int basket = 0) const;
  double board_face_x() const { return rim_radius + kRimToBoard; }
  double baseline_x() const { return kRimToBaseline; }
  double far_line_x() const { return kRimToBaseline - length(); }
  double centre_x() const { return kRimToBaseline - kFullLength / 2; }  // full court: halfway
  double free_throw_line_x() const { return board_face_x() - free_throw_distance; }
  // A point of basket 0's half as seen from `basket` (the same for basket 0; the point turned
  // half round about the court's centre for basket 1): the arcs and restart spots of basket 0
  // serve both.
  Eigen::Vector2d from_basket(const Eigen::Vector2d& p, int basket) const;
  // A point on the floor behind `basket`'s arc (a shot released there is worth 2; 3 on the full
  // court).
  bool behind_arc(const Eigen::Vector2d& p, int basket = 0) const {
    return beyond_arc(p, basket) > 0;
  }
  // How far a point is beyond `basket`'s arc (its curve or the straight corner lines), negative
  // inside.
  double beyond_arc(const Eigen::Vector2d& p, int basket = 0) const;
  // Is the point (x, y) on the court (inside the lines)?
  bool inside(const Eigen::Vector2d& p) const;
  // Did a ball whose centre went from `before` to `after` in one physics step pass downward
  // through a rim's plane inside the rim (centre within the inner radius where it crossed)?
  // Which basket (0, 1), else -1.
  int basket_through(const Eigen::Vector3d& before, const Eigen::Vector3d& after) const;
  // Did it pass upward through a rim's plane inside the rim (entering the basket from below, a
  // violation: FIBA Official Rules art. 31.2.4 and 3x3 likewise)? Which basket, else -1.
  int basket_from_below(const Eigen::Vector3d& before, const Eigen::Vector3d& after) const;

  struct Part {
    enum Kind { Rim, Board, Pole } kind;
    Eigen::Vector3d a, b;  // capsule: ends; box: centre and half extents
    double radius = 0;
  };
  std::vector<Part> parts() const;  // every basket's
  void build(core::PhysicsWorld& world) const;
  // Floor, lines (sidelines, baseline, far line, arc, free-throw line and lane), basket.
  void describe(SceneBuilder& scene) const;

 private:
  std::vector<Part> one_basket() const;  // basket 0's rim, bracket, board and pole
  // The basket whose rim's plane the segment crosses inside the rim, else -1.
  int rim_crossed(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;
};

}  // namespace olympics::sports::basketball
