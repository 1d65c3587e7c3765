#include "javelin/javelin_aero.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace olympics::sports::javelin {

double diameter_at(const JavelinSpec& spec, double from_tip) {
  const double shaft = 2.0 * spec.radius;
  return from_tip >= spec.head_length ? shaft : shaft * std::max(from_tip, 0.0) / spec.head_length;
}

AeroLoad crossflow_load(const JavelinSpec& spec, const Eigen::Vector3d& axis,
                        const Eigen::Vector3d& velocity, const Eigen::Vector3d& spin) {
  AeroLoad load;
  const double ds = spec.length / kSlices;
  for (int i = 0; i < kSlices; ++i) {
    const double from_tip = (i + 0.5) * ds;
    const Eigen::Vector3d r = (spec.tip_to_com - from_tip) * axis;  // from the centre of mass
    const Eigen::Vector3d v = velocity + spin.cross(r);
    const Eigen::Vector3d v_axial = v.dot(axis) * axis;
    const Eigen::Vector3d v_normal = v - v_axial;
    const double d = diameter_at(spec, from_tip);
    const Eigen::Vector3d f = -0.5 * kAirDensity * ds * d *
                              (kCrossflowDrag * v_normal.norm() * v_normal +
                               kSkinFriction * M_PI * v_axial.norm() * v_axial);
    load.force += f;
    load.torque += r.cross(f);
  }
  return load;
}

}  // namespace olympics::sports::javelin
