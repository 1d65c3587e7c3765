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

Eigen::Vector2d Court::from_basket(const Eigen::Vector2d& p, int basket) const {
  return basket == 0 ? p : Eigen::Vector2d(2 * centre_x() - p.x(), -p.y());
}

Eigen::Vector3d Court::rim_centre(int basket) const {
  const Eigen::Vector2d at = from_basket(Eigen::Vector2d::Zero(), basket);
  return {at.x(), at.y(), rim_height};
}

double Court::beyond_arc(const Eigen::Vector2d& p, int basket) const {
  const Eigen::Vector2d q = from_basket(p, basket);
  return std::max(q.norm() - arc_radius, std::abs(q.y()) - corner_line);
}

bool Court::inside(const Eigen::Vector2d& p) const {
  return p.x() <= baseline_x() && p.x() >= far_line_x() && std::abs(p.y()) <= width / 2;
}

int Court::rim_crossed(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
  const double f = (from.z() - rim_height) / (from.z() - to.z());
  const Eigen::Vector2d at = from.head<2>() + f * (to - from).head<2>();
  for (int b = 0; b < baskets(); ++b)
    if ((at - rim_centre(b).head<2>()).norm() < rim_radius) return b;
  return -1;
}

int Court::basket_through(const Eigen::Vector3d& before, const Eigen::Vector3d& after) const {
  if (!(before.z() >= rim_height && after.z() < rim_height)) return -1;
  return rim_crossed(before, after);
}

int Court::basket_from_below(const Eigen::Vector3d& before, const Eigen::Vector3d& after) const {
  if (!(before.z() < rim_height && after.z() >= rim_height)) return -1;
  return rim_crossed(before, after);
}

std::vector<Court::Part> Court::parts() const {
  std::vector<Part> out = one_basket();
  if (!full) return out;
  const size_t n = out.size();
  for (size_t i = 0; i < n; ++i) {  // the second basket: the first turned half round
    Part p = out[i];
    auto turn = [this](const Eigen::Vector3d& v) {
      const Eigen::Vector2d at = from_basket(v.head<2>(), 1);
      return Eigen::Vector3d(at.x(), at.y(), v.z());
    };
    p.a = turn(p.a);
    if (p.kind != Part::Board) p.b = turn(p.b);  // a board's b is its half extents
    out.push_back(p);
  }
  return out;
}

std::vector<Court::Part> Court::one_basket() const {
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
  scene.set_ground(length() + 1, W + 3, "#c9955c");
  scene.add_ground_rect(x0, x1, -W, W, "line");
  constexpr int kArcs = 48;
  const double start = std::asin(corner_line / arc_radius);  // where the arc meets the corners
  const double corner_x = arc_radius * std::cos(start);
  for (int b = 0; b < baskets(); ++b) {
    auto line = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
      const Eigen::Vector2d p = from_basket(from, b), q = from_basket(to, b);
      scene.add_line({p.x(), p.y(), 0.002}, {q.x(), q.y(), 0.002}, "line");
    };
    for (double side : {-1.0, 1.0}) line({x1, side * corner_line}, {-corner_x, side * corner_line});
    for (int i = 0; i < kArcs; ++i) {
      const double a0 = -start + 2 * start * i / kArcs, a1 = -start + 2 * start * (i + 1) / kArcs;
      line({-arc_radius * std::cos(a0), arc_radius * std::sin(a0)},
           {-arc_radius * std::cos(a1), arc_radius * std::sin(a1)});
    }
    const Eigen::Vector2d lane0 = from_basket({free_throw_line_x(), -kLaneHalfWidth}, b),
                          lane1 = from_basket({x1, kLaneHalfWidth}, b);
    scene.add_ground_rect(std::min(lane0.x(), lane1.x()), std::max(lane0.x(), lane1.x()),
                          -kLaneHalfWidth, kLaneHalfWidth, "line");
  }
  if (full) scene.add_line({centre_x(), -W, 0.002}, {centre_x(), W, 0.002}, "line");
  for (const Part& p : parts()) {
    if (p.kind == Part::Board)
      scene.add_box(-1, p.a, p.b, "arena", "#e8eef2");
    else
      scene.add_segment(-1, "capsule", p.a, p.b, p.radius, "arena",
                        p.kind == Part::Rim ? "#e0602a" : "#5a5a5a");
  }
}

}  // namespace olympics::sports::basketball
