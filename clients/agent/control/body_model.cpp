#include "control/body_model.h"

#include <stdexcept>

#include "core/body_mass.h"
#include "equipment/equipment.h"
#include "smpl_observation.h"
#include "smplx_observation.h"

namespace olympics::client::control {

namespace {
constexpr double kGravity = 9.81;
}

BodyModel::BodyModel(const core::ModelSpec& spec) {
  for (const core::BodySpec& b : spec.bodies) {
    if (!b.quat.isApprox(Eigen::Quaterniond::Identity()))
      throw std::invalid_argument(spec.source + ": body \"" + b.name +
                                  "\" is turned from its parent at rest; the control model "
                                  "expects the SMPL convention of aligned frames");
    ModelBody m;
    m.name = b.name;
    m.parent = b.parent;
    m.offset = b.pos;
    const dMass mass = core::body_mass(b);
    m.mass = mass.mass;
    m.com = {mass.c[0], mass.c[1], mass.c[2]};
    for (size_t h = 0; h < b.hinges.size() && h < 3; ++h) {
      m.kp[h] = b.hinges[h].kp;
      m.kd[h] = b.hinges[h].kd;
    }
    total_mass_ += m.mass;
    bodies_.push_back(m);
  }
  subtree_.resize(bodies_.size());
  for (int i = size() - 1; i >= 0; --i) {
    subtree_[i].insert(subtree_[i].begin(), i);
    if (const int p = bodies_[i].parent; p >= 0)
      subtree_[p].insert(subtree_[p].end(), subtree_[i].begin(), subtree_[i].end());
  }
}

BodyModel BodyModel::humanoid(core::HumanoidKind kind,
                              const sports::equipment::EquipmentSpec* equipment) {
  core::ModelSpec spec = core::load_humanoid(kind);
  if (equipment) sports::equipment::attach_equipment(spec, *equipment);
  return BodyModel(spec);
}

bool BodyModel::in_subtree(int body, int ancestor) const {
  for (int b = body; b >= 0; b = bodies_[b].parent)
    if (b == ancestor) return true;
  return false;
}

BodyPose BodyModel::pose_from_observation(std::span<const float> o) const {
  const bool smplx = size() == smplx::kBodies;
  if (size() != smpl::kBodies && !smplx)
    throw std::invalid_argument(
        "pose_from_observation reads the SMPL or SMPL-X self observation (24 or 52 bodies)");
  BodyPose pose;
  for (int i = 0; i < size(); ++i) {
    pose.position.push_back(smplx ? smplx::body_position(o, i) : smpl::body_position(o, i));
    pose.rotation.push_back(smplx ? smplx::body_rotation(o, i) : smpl::body_rotation(o, i));
  }
  return pose;
}

BodyPose BodyModel::forward(const std::vector<Eigen::Matrix3d>& relative) const {
  BodyPose pose;
  pose.position.resize(size());
  pose.rotation.resize(size());
  for (int i = 0; i < size(); ++i) {
    const int p = bodies_[i].parent;
    if (p < 0) {
      pose.position[i].setZero();
      pose.rotation[i] = relative[i];
      continue;
    }
    pose.position[i] = pose.position[p] + pose.rotation[p] * bodies_[i].offset;
    pose.rotation[i] = pose.rotation[p] * relative[i];
  }
  return pose;
}

std::vector<Eigen::Matrix3d> BodyModel::relative_rotations(const BodyPose& pose) const {
  std::vector<Eigen::Matrix3d> r(size());
  for (int i = 0; i < size(); ++i) {
    const int p = bodies_[i].parent;
    r[i] =
        p < 0 ? pose.rotation[i] : Eigen::Matrix3d(pose.rotation[p].transpose() * pose.rotation[i]);
  }
  return r;
}

Eigen::Vector3d BodyModel::centre_of_mass(const BodyPose& pose) const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < size(); ++i) sum += bodies_[i].mass * body_com(pose, i);
  return sum / total_mass_;
}

Eigen::Vector3d BodyModel::gravity_torque(const BodyPose& pose, int body) const {
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  for (int b : subtree_[body]) torque += weight_torque(pose, b, pose.position[body]);
  return in_parent_frame(pose, body, torque);
}

Eigen::Vector3d BodyModel::turning_torque(const BodyPose& pose, int body,
                                          const Eigen::Vector3d& pivot, double rate,
                                          double acceleration) const {
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  for (int b : subtree_[body]) {
    const Eigen::Vector3d com = body_com(pose, b);
    Eigen::Vector3d out = com - pivot;
    out.z() = 0;
    const Eigen::Vector3d accel =
        acceleration * Eigen::Vector3d::UnitZ().cross(out) - rate * rate * out;
    torque += (com - pose.position[body]).cross(Eigen::Vector3d(-bodies_[b].mass * accel));
  }
  return in_parent_frame(pose, body, torque);
}

Eigen::Vector3d BodyModel::gravity_torque_above(const BodyPose& pose, int body) const {
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  for (int b = 0; b < size(); ++b)
    if (!in_subtree(b, body)) torque += weight_torque(pose, b, pose.position[body]);
  return in_parent_frame(pose, body, torque);
}

Eigen::Vector3d BodyModel::body_com(const BodyPose& pose, int b) const {
  return pose.position[b] + pose.rotation[b] * bodies_[b].com;
}

Eigen::Vector3d BodyModel::in_parent_frame(const BodyPose& pose, int body,
                                           const Eigen::Vector3d& torque) const {
  const int parent = bodies_[body].parent;
  return parent < 0 ? torque : Eigen::Vector3d(pose.rotation[parent].transpose() * torque);
}

Eigen::Vector3d BodyModel::weight_torque(const BodyPose& pose, int b,
                                         const Eigen::Vector3d& about) const {
  return (body_com(pose, b) - about).cross(Eigen::Vector3d(0, 0, -kGravity * bodies_[b].mass));
}

}  // namespace olympics::client::control
