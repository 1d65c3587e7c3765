#include "framework/scene_view.h"

namespace olympics::sports {
namespace {

nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
nlohmann::json quat(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

}  // namespace

int SceneBuilder::add_body(const std::string& name, int slot, const std::string& role) {
  bodies_.push_back({{"name", name}, {"slot", slot}, {"role", role}});
  return body_count() - 1;
}

void SceneBuilder::add_shape(int body, const std::string& type, const Eigen::Vector3d& size,
                             const Eigen::Vector3d& pos, const Eigen::Quaterniond& q,
                             const std::string& role, const std::string& color) {
  nlohmann::json s = {{"body", body},    {"type", type},    {"size", vec(size)},
                      {"pos", vec(pos)}, {"quat", quat(q)}, {"role", role}};
  if (!color.empty()) s["color"] = color;
  shapes_.push_back(std::move(s));
}

void SceneBuilder::add_box(int body, const Eigen::Vector3d& centre, const Eigen::Vector3d& half,
                           const std::string& role, const std::string& color,
                           const Eigen::Quaterniond& q) {
  add_shape(body, "box", half, centre, q, role, color);
}

void SceneBuilder::add_sphere(int body, const Eigen::Vector3d& centre, double radius,
                              const std::string& role, const std::string& color) {
  add_shape(body, "sphere", {radius, 0, 0}, centre, Eigen::Quaterniond::Identity(), role, color);
}

void SceneBuilder::add_segment(int body, const std::string& type, const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b, double radius, const std::string& role,
                               const std::string& color) {
  const Eigen::Vector3d axis = b - a;
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis);
  add_shape(body, type, {radius, axis.norm() / 2, 0}, (a + b) / 2, q, role, color);
}

void SceneBuilder::add_geom(int body, const core::GeomSpec& g, const std::string& role) {
  switch (g.shape) {
    case core::GeomShape::Sphere:
      add_shape(body, "sphere", {g.radius, 0, 0}, g.pos, g.quat, role, "");
      break;
    case core::GeomShape::Capsule:
      add_shape(body, "capsule", {g.radius, g.half_length, 0}, g.pos, g.quat, role, "");
      break;
    case core::GeomShape::Cylinder:
      add_shape(body, "cylinder", {g.radius, g.half_length, 0}, g.pos, g.quat, role, "");
      break;
    case core::GeomShape::Box:
      add_shape(body, "box", g.half_extents, g.pos, g.quat, role, "");
      break;
  }
}

void SceneBuilder::add_line(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const std::string& role) {
  lines_.push_back({{"a", vec(a)}, {"b", vec(b)}, {"role", role}});
}

void SceneBuilder::add_ground_rect(double x_lo, double x_hi, double y_lo, double y_hi,
                                   const std::string& role, double z) {
  add_line({x_lo, y_lo, z}, {x_hi, y_lo, z}, role);
  add_line({x_hi, y_lo, z}, {x_hi, y_hi, z}, role);
  add_line({x_hi, y_hi, z}, {x_lo, y_hi, z}, role);
  add_line({x_lo, y_hi, z}, {x_lo, y_lo, z}, role);
}

void SceneBuilder::set_ground(double half_x, double half_y, const std::string& color) {
  ground_ = {{"half", {half_x, half_y}}, {"color", color}};
}

nlohmann::json SceneBuilder::json() const {
  return {{"version", 1},
          {"bodies", bodies_},
          {"shapes", shapes_},
          {"lines", lines_},
          {"ground", ground_}};
}

void append_pose(std::vector<float>& out, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  const float v[7] = {static_cast<float>(p.x()), static_cast<float>(p.y()),
                      static_cast<float>(p.z()), static_cast<float>(q.w()),
                      static_cast<float>(q.x()), static_cast<float>(q.y()),
                      static_cast<float>(q.z())};
  out.insert(out.end(), v, v + 7);
}

}  // namespace olympics::sports
