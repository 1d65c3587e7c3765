// A humanoid as read from an MJCF file, before any physics engine sees it.
//
// Everything here is in the z-up, x-forward frame used across the project (the loader converts
// y-up files). Lengths in metres, angles in radians, masses in kg.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace olympics::core {

enum class GeomShape { Sphere, Capsule, Cylinder, Box };

struct GeomSpec {
  std::string name;
  GeomShape shape = GeomShape::Sphere;
  // Centre and orientation in the owning body's frame. Capsules and cylinders lie along local z.
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  Eigen::Quaterniond quat = Eigen::Quaterniond::Identity();
  double radius = 0;       // sphere, capsule, cylinder
  double half_length = 0;  // capsule / cylinder: of the cylinder part
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();  // box
  double density = 1000;
  std::optional<double> mass;  // overrides density when given
  double friction = 1.0;
  bool collides = true;  // false: mass only, no ODE geom (e.g. a racket face, see equipment.h)
  bool sensor = false;   // its contacts are reported with their forces (a sword tip, a glove)
  bool held = false;     // equipment held in a hand, not part of the body (drawn as such)
};

struct HingeSpec {
  std::string name;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // in the body frame, unit length
  double range_lo = 0, range_hi = 0;                // radians; both 0 when the file gives none
  double kp = 0, kd = 0;                            // PD gains (N·m/rad, N·m·s/rad)
  double armature = 0;                              // kg·m²
};

struct BodySpec {
  std::string name;
  int parent = -1;                                // index into ModelSpec::bodies; -1 for the root
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();  // in the parent frame
  Eigen::Quaterniond quat = Eigen::Quaterniond::Identity();
  bool free_root = false;
  // Hinges at the body origin, applied in order (MuJoCo semantics): rest-to-child rotation
  // R = R(axis0, q0) R(axis1, q1) R(axis2, q2).
  std::vector<HingeSpec> hinges;
  std::vector<GeomSpec> geoms;
};

struct ModelSpec {
  std::string source;  // file path, for messages
  std::vector<BodySpec> bodies;
  std::vector<std::pair<int, int>> contact_excludes;  // body index pairs
  double timestep = 0.002;                            // <option timestep>, MuJoCo's default

  int body_index(const std::string& name) const;  // -1 when absent
  int dof_count() const;                          // number of hinges
  std::vector<std::string> hinge_names() const;   // action order
};

}  // namespace olympics::core
