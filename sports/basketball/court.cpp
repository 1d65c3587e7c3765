#include "basketball/court.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::basketball {
namespace {

// A steel rim rings; the glass board is lively too; the pole is padded.
constexpr double kRimRestitution = 0.6, kBoardRestitution = 0.7, kPoleRestitution = 0.3;
constexpr double kPoleBehindBaseline = 1.0, kPoleRadius = 0.1;
constexpr double kLaneHalfWidth = 2.45;  // FIBA's restricted area: 4.9 m wide

}  // namespace

double Court::beyond_arc(const Eigen::Vector2d& p) const {
  return std::max(p.norm() - arc_radius, std::abs(p.y()) - corner_line);
}

bool Court::inside(const Eigen::Vector2d& p) const {
  return p.x() <= baseline_x() && p.x() >= far_line_x() && std::abs(p.y()) <= width / 2;
}

bool Court::basket(const Eigen::Vector3d& before, const Eigen::Vector3d& after) const {
  if (!(before.z() >= rim_height && after.z() < rim_height)) return false;
  const double f = (before.z() - rim_height) / (before.z() - after.z());
  const Eigen::Vector2d at = before.head<2>() + f * (after - before).head<2>();
  return at.norm() < rim_radius;
}

std::vector<Court::Part> Court::parts() const {
  std::vector<Part> out;
  const double ring = rim_radius + kRimRod;  // the rod's centre line
  for (int i = 0; i < kRimSegments; ++i) {
    const double a0 = 2 * M_PI * i / kRimSegments, a1 = 2 * M_PI * (i + 1) / kRimSegments;
    out.push_back({Part::Rim,
                   {ring * std::cos(a0), ring * std::sin(a0), rim_height},
                   {ring * std::cos(a1), ring * std::sin(a1), rim_height},
                   kRimRod});
  }
  // The bracket from the rim's back to the board.
  out.push_back({Part::Rim, {ring, 0, rim_height}, {board_face_x(), 0, rim_height}, kRimRod});
  const double board_x = board_face_x() + kBoardHalfThickness;
  out.push_back({Part::Board,
                 {board_x, 0, kBoardBottom + kBoardHeight / 2},
                 {kBoardHalfThickness, kBoardWidth / 2, kBoardHeight / 2}});
  const double pole_x = baseline_x() + kPoleBehindBaseline;
  const double top = kBoardBottom + kBoardHeight / 2;
  out.push_back({Part::Pole, {pole_x, 0, 0}, {pole_x, 0, top}, kPoleRadius});
  out.push_back({Part::Pole, {pole_x, 0, top}, {board_x + kBoardHalfThickness, 0, top}, 0.05});
  return out;
}

void Court::build(core::PhysicsWorld& world) const {
  for (const Part& p : parts()) {
    if (p.kind == Part::Board)
      world.add_static_box(p.a, p.b, 0.5, kBoardRestitution);
    else
      world.add_static_capsule(p.a, p.b, p.radius, 0.6,
                               p.kind == Part::Rim ? kRimRestitution : kPoleRestitution);
  }
}

void Court::describe(SceneBuilder& scene) const {
  const double x0 = far_line_x(), x1 = baseline_x(), W = width / 2;
  scene.set_ground(depth + 1, W + 3, "#c9955c");
  scene.add_ground_rect(x0, x1, -W, W, "line");
  constexpr int kArcs = 48;
  const double start = std::asin(corner_line / arc_radius);  // where the arc meets the corners
  const double corner_x = arc_radius * std::cos(start);
  for (double side : {-1.0, 1.0})
    scene.add_line({x1, side * corner_line, 0.002}, {-corner_x, side * corner_line, 0.002}, "line");
  for (int i = 0; i < kArcs; ++i) {
    const double a0 = -start + 2 * start * i / kArcs, a1 = -start + 2 * start * (i + 1) / kArcs;
    scene.add_line({-arc_radius * std::cos(a0), arc_radius * std::sin(a0), 0.002},
                   {-arc_radius * std::cos(a1), arc_radius * std::sin(a1), 0.002}, "line");
  }
  scene.add_ground_rect(free_throw_line_x(), x1, -kLaneHalfWidth, kLaneHalfWidth, "line");
  for (const Part& p : parts()) {
    if (p.kind == Part::Board)
      scene.add_box(-1, p.a, p.b, "arena", "#e8eef2");
    else
      scene.add_segment(-1, "capsule", p.a, p.b, p.radius, "arena",
                        p.kind == Part::Rim ? "#e0602a" : "#5a5a5a");
  }
}

}  // namespace olympics::sports::basketball
