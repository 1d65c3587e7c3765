// Scene data for viewers: what a match looks like, described once, and where its moving bodies
// are each tick. Derived from the simulation, never fed back into it (replays stay bit for bit).
//
// The description is JSON (docs/viewer.md, "Scene data"):
//   bodies: [{name, slot, role}]            moving bodies; slot -1 for equipment not a player's
//   shapes: [{body, type, size, pos, quat, role, color?}]
//       body -1: static, pos/quat in the world; otherwise in that body's frame
//       type box (size = half extents), sphere (size[0] = r), capsule / cylinder (size[0] = r,
//       size[1] = half length of the straight part, along local z)
//   lines:  [{a, b, role}]                  court markings on or above the ground
//   ground: {half: [x, y], color}          the floor drawn under the arena
// Poses are 7 floats per moving body, in `bodies` order: position (m), quaternion (w, x, y, z).
#pragma once

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/model_spec.h"

namespace olympics::sports {

class SceneBuilder {
 public:
  // A moving body; returns its index (its place in every frame's poses).
  int add_body(const std::string& name, int slot, const std::string& role);
  // A shape on a body (or static with body -1), in that body's frame (or the world's).
  void add_box(int body, const Eigen::Vector3d& centre, const Eigen::Vector3d& half,
               const std::string& role, const std::string& color = "",
               const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity());
  void add_sphere(int body, const Eigen::Vector3d& centre, double radius, const std::string& role,
                  const std::string& color = "");
  // A capsule or cylinder from `a` to `b` (in the body's frame, or the world's).
  void add_segment(int body, const std::string& type, const Eigen::Vector3d& a,
                   const Eigen::Vector3d& b, double radius, const std::string& role,
                   const std::string& color = "");
  void add_geom(int body, const core::GeomSpec& geom, const std::string& role);
  void add_line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const std::string& role);
  // The lines of an axis-aligned rectangle on the ground (z slightly above it).
  void add_ground_rect(double x_lo, double x_hi, double y_lo, double y_hi, const std::string& role,
                       double z = 0.002);
  void set_ground(double half_x, double half_y, const std::string& color);
  int body_count() const { return static_cast<int>(bodies_.size()); }
  nlohmann::json json() const;

 private:
  void add_shape(int body, const std::string& type, const Eigen::Vector3d& size,
                 const Eigen::Vector3d& pos, const Eigen::Quaterniond& q, const std::string& role,
                 const std::string& color);
  nlohmann::json bodies_ = nlohmann::json::array();
  nlohmann::json shapes_ = nlohmann::json::array();
  nlohmann::json lines_ = nlohmann::json::array();
  nlohmann::json ground_ = {{"half", {20, 20}}, {"color", "#5d7d4a"}};
};

// Appends one pose (7 floats) to a frame.
void append_pose(std::vector<float>& out, const Eigen::Vector3d& p, const Eigen::Quaterniond& q);

}  // namespace olympics::sports
