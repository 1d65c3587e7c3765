// The javelin's runway, arc and landing sector on the ground, and the measurement, as pure
// geometry (TR 32.9-32.10, 32.20): the arc is a circle of `radius` about a centre on the runway's
// axis, its inner edge at the end of the runway; the sector's lines run from that centre at
// +-half the sector's angle (28.96 degrees in all, so they pass through the arc's ends on the
// runway lines); a throw is measured from where the tip first touched to the arc's inner edge,
// along the line to the centre, rounded down to the centimetre.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace olympics::sports::javelin {

struct ThrowingArea {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // the arc's centre (world x, y)
  double radius = 8.0;
  double half_angle = 0;           // rad, half the sector's angle
  double runway_half_width = 2.0;  // m, from the axis to a runway line's inner edge

  double from_centre(const Eigen::Vector3d& p) const { return (p.head<2>() - centre).norm(); }
  // Touching the arc (its inner edge or beyond) in front of the centre.
  bool beyond_arc(const Eigen::Vector3d& p) const {
    return p.x() > centre.x() && from_centre(p) >= radius;
  }
  // Touching a runway line or the ground outside them (behind the arc).
  bool outside_runway(const Eigen::Vector3d& p) const {
    return std::abs(p.y() - centre.y()) >= runway_half_width;
  }
  // Beyond the arc and strictly inside the sector lines' inner edges.
  bool in_sector(const Eigen::Vector3d& p) const {
    const Eigen::Vector2d d = p.head<2>() - centre;
    return d.norm() > radius && std::abs(std::atan2(d.y(), d.x())) < half_angle;
  }
  // The mark (m): the distance to the arc's inner edge along the line to the centre, rounded
  // down to the whole centimetre (TR 32.20).
  double mark(const Eigen::Vector3d& p) const {
    return std::floor((from_centre(p) - radius) * 100.0 + 1e-9) / 100.0;
  }
};

}  // namespace olympics::sports::javelin
