#include "javelin/throwing_hand.h"

#include <Eigen/Geometry>
#include <stdexcept>
#include <string>

namespace olympics::sports::javelin {

ThrowingHand::ThrowingHand(const core::Humanoid& humanoid) {
  const auto& bodies = humanoid.spec().bodies;
  for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
    const std::string& name = bodies[b].name;
    if (name == "R_Wrist") palm_ = b;
    if (name.rfind("R_", 0) != 0) continue;
    const bool finger =
        name.find("Index") != std::string::npos || name.find("Middle") != std::string::npos ||
        name.find("Ring") != std::string::npos || name.find("Pinky") != std::string::npos;
    if (finger) fingers_.push_back(b);
    if (finger || name.find("Thumb") != std::string::npos) hand_bodies_.push_back(b);
  }
  if (palm_ < 0 || fingers_.size() != 12)
    throw std::invalid_argument(
        "javelin: the athlete's model has no right hand with fingers (R_Wrist and its twelve "
        "finger links); the javelin needs the SMPL-X humanoid");
  hand_bodies_.push_back(palm_);
}

Eigen::Vector3d ThrowingHand::cord_point(const core::Humanoid& h) const {
  const core::BodyState palm = h.body_state(palm_);
  return palm.position + palm.orientation * cord_in_palm();
}

std::vector<dGeomID> ThrowingHand::geoms(const core::Humanoid& h) const {
  std::vector<dGeomID> out;
  for (int b : hand_bodies_)
    for (dGeomID g = dBodyGetFirstGeom(h.ode_body(b)); g; g = dBodyGetNextGeom(g)) out.push_back(g);
  return out;
}

double ThrowingHand::finger_flexion(const core::Humanoid& h) const {
  const auto& bodies = h.spec().bodies;
  double sum = 0;
  for (int b : fingers_) {
    const Eigen::Quaterniond parent = h.body_state(bodies[b].parent).orientation;
    const Eigen::Quaterniond relative = parent.conjugate() * h.body_state(b).orientation;
    const Eigen::AngleAxisd aa(relative);
    sum += (aa.angle() * aa.axis()).x();  // the right hand closes about +x
  }
  return sum / static_cast<double>(fingers_.size());
}

}  // namespace olympics::sports::javelin
