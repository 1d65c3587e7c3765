// Equipment held in a hand (HUMANOID.md section 1.2): geoms added to (or replacing) the hand
// body's, and, for rackets and paddles, a striking face as a disc for ball collision. Each sport
// keeps its own catalogue (sports/racket/racket_equipment.h, ...).
//
// A striking face is not an ODE geom: balls are simulated by BallFlight with continuous collision
// against the face's swept disc. Other equipment geoms (a racket handle, a sword) are ODE geoms,
// so they meet the ground and other bodies like any limb.
#pragma once

#include <string>
#include <vector>

#include "core/humanoid.h"
#include "core/model_spec.h"
#include "equipment/swept_ball.h"

namespace olympics::sports::equipment {

struct EquipmentSpec {
  std::string name;
  std::string hand = "R_Hand";
  bool replaces_hand_geoms = false;   // e.g. the paddle takes the place of the hand box
  std::vector<core::GeomSpec> geoms;  // in the hand frame
  Disc face;                          // the striking disc; its axis is the hand's local z
  Eigen::Vector3d face_centre = Eigen::Vector3d::Zero();  // in the hand frame
  double restitution = 0.8;
  double friction = 0.8;
};

// Adds a striking disc at y = `centre_y` in the hand frame (axis: the hand's z) to `e`: a
// mass-only geom (a ball meets it through BallFlight, not ODE), and the face the ball is swept
// against.
void add_striking_face(EquipmentSpec& e, const char* name, double radius, double half_thickness,
                       double centre_y, double density);

// Adds the equipment's geoms to its hand body (throws std::invalid_argument when the model has
// no such body).
void attach_equipment(core::ModelSpec& spec, const EquipmentSpec& equipment);

// The face's pose in the world for a humanoid holding the equipment.
Pose equipment_face_pose(const core::Humanoid& humanoid, int hand_body,
                         const EquipmentSpec& equipment);

}  // namespace olympics::sports::equipment
