#include "soccer/field.h"

#include <cmath>

namespace olympics::sports::soccer {
namespace {

// Posts and bar ring (an aluminium frame); the net gives (it is cloth: no bounce, much grip);
// walls are padded boards.
constexpr double kPostRestitution = 0.6, kNetRestitution = 0.0, kWallRestitution = 0.5;

}  // namespace

Eigen::Vector3d Field::goal_centre(int end) const {
  return {end * half_length(), 0, goal_height / 2};
}

Crossed Field::crossed(const Eigen::Vector3d& p, double r, int* end) const {
  if (std::abs(p.x()) > goal_line_outer() + r) {
    if (end) *end = p.x() > 0 ? 1 : -1;
    const bool between_posts = std::abs(p.y()) < goal_width / 2 && p.z() < goal_height;
    return between_posts ? Crossed::Goal : Crossed::GoalLine;
  }
  if (std::abs(p.y()) > half_width() + r) return Crossed::TouchLine;
  return Crossed::None;
}

std::vector<Field::Part> Field::parts() const {
  std::vector<Part> out;
  const double w = goal_width / 2 + post_radius, h = goal_height + post_radius;
  const double t = kNetHalfThickness;
  for (int end : {-1, 1}) {
    const double x = end * (half_length() + post_radius);
    for (double side : {-1.0, 1.0}) out.push_back({Part::Post, {x, side * w, 0}, {x, side * w, h}});
    out.push_back({Part::Post, {x, -w, h}, {x, w, h}});
    // Net: back, sides and roof, from the posts' back edge to net_depth behind the line.
    const double x0 = end * (half_length() + 2 * post_radius);
    const double x1 = end * (half_length() + net_depth);
    const double mid = 0.5 * (x0 + x1), half_depth = 0.5 * std::abs(x1 - x0);
    out.push_back({Part::Net, {x1 + end * t, 0, h / 2}, {t, w + t, h / 2}});
    for (double side : {-1.0, 1.0})
      out.push_back({Part::Net, {mid, side * (w + t), h / 2}, {half_depth, t, h / 2}});
    out.push_back({Part::Net, {mid, 0, h + t}, {half_depth, w + t, t}});
  }
  if (walls) {
    const double X = half_length() + wall_margin, Y = half_width() + wall_margin;
    const double z = wall_height / 2, th = 0.1;
    for (double s : {-1.0, 1.0}) {
      out.push_back({Part::Wall, {s * (X + th), 0, z}, {th, Y + 2 * th, z}});
      out.push_back({Part::Wall, {0, s * (Y + th), z}, {X, th, z}});
    }
  }
  return out;
}

void Field::build(core::PhysicsWorld& world) const {
  for (const Part& p : parts()) {
    if (p.kind == Part::Post)
      world.add_static_capsule(p.a, p.b, post_radius, 0.5, kPostRestitution);
    else if (p.kind == Part::Wall)
      world.add_static_box(p.a, p.b, 1.0, kWallRestitution);
    else  // the net swallows the ball's bounce
      static_cast<core::GeomTag*>(
          dGeomGetData(world.add_static_box(p.a, p.b, 1.0, kNetRestitution)))
          ->absorbs = true;
  }
}

void Field::describe(SceneBuilder& scene) const {
  const double L = half_length(), W = half_width();
  scene.set_ground(L + wall_margin + 2, W + wall_margin + 2, "#3f7f3a");
  scene.add_ground_rect(-L, L, -W, W, "line");
  scene.add_line({0, -W, 0.002}, {0, W, 0.002}, "line");
  constexpr int kArcs = 32;
  for (int i = 0; i < kArcs; ++i) {
    const double a0 = 2 * M_PI * i / kArcs, a1 = 2 * M_PI * (i + 1) / kArcs;
    scene.add_line({kCentreCircle * std::cos(a0), kCentreCircle * std::sin(a0), 0.002},
                   {kCentreCircle * std::cos(a1), kCentreCircle * std::sin(a1), 0.002}, "line");
  }
  for (int end : {-1, 1}) {
    const double x = end * L, xi = end * (L - kGoalArea);
    const double y = goal_width / 2 + kGoalArea;
    scene.add_ground_rect(std::min(x, xi), std::max(x, xi), -y, y, "line");
  }
  for (const Part& p : parts()) {
    if (p.kind == Part::Post)
      scene.add_segment(-1, "capsule", p.a, p.b, post_radius, "arena", "#f4f4f4");
    else
      scene.add_box(-1, p.a, p.b, p.kind == Part::Net ? "net" : "arena",
                    p.kind == Part::Net ? "#dddddd" : "#6b5b45");
  }
}

}  // namespace olympics::sports::soccer
