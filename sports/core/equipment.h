// Equipment held in the right hand (HUMANOID.md section 1.2): a tennis racket or a table-tennis
// paddle, added to the hand body's mass, and its striking face as a disc for ball collision.
//
// The striking face is not an ODE geom: balls are simulated by BallFlight with continuous
// collision against the face's swept disc. The racket handle is an ODE capsule, so it meets the
// ground and other bodies like any limb.
#pragma once

#include <string>
#include <vector>

#include "core/humanoid.h"
#include "core/model_spec.h"
#include "core/swept_ball.h"

namespace olympics::core {

struct EquipmentSpec {
  std::string name;
  std::string hand = "R_Hand";
  bool replaces_hand_geoms = false;  // the paddle takes the place of the hand box
  std::vector<GeomSpec> geoms;       // in the hand frame
  Disc face;                         // the striking disc; its axis is the hand's local z
  Eigen::Vector3d face_centre = Eigen::Vector3d::Zero();  // in the hand frame
  double restitution = 0.8;
  double friction = 0.8;
};

// Racket: handle cylinder r 0.016 from the wrist to 0.35 m along -y (rho 500, 0.14 kg), head
// disc r 0.15, 0.04 thick at y = -0.35 (rho 150, 0.42 kg); e 0.8, mu 0.8.
EquipmentSpec tennis_racket();
// Paddle: disc r 0.08, 0.02 thick at y = -0.12 (rho 200, 0.08 kg) replacing the hand box; e 0.2
// is the paddle's own value in the original, but a real blade with rubber returns a table-tennis
// ball with e of about 0.85, so the face uses that (docs/physics.md).
EquipmentSpec table_tennis_paddle();

// Adds the equipment's geoms to its hand body (throws std::invalid_argument when the model has
// no such body).
void attach_equipment(ModelSpec& spec, const EquipmentSpec& equipment);

// The face's pose in the world for a humanoid holding the equipment.
Pose equipment_face_pose(const Humanoid& humanoid, int hand_body, const EquipmentSpec& equipment);

}  // namespace olympics::core
