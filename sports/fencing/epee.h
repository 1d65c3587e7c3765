// The épée, rigidly held in the right hand (HUMANOID.md section 1.2: the blade points along the
// hand's -y, its tip 0.98 m from the hand), as real collision geometry so blades parry and are
// parried. Mass as a real épée's (at most 770 g), placed as its parts are:
//
//   grip and pommel  mass only, in the hand      0.20 kg
//   guard            disc r 0.05, at y = -0.11   0.25 kg  (a collision geom)
//   blade            capsule r 0.007, y -0.12 .. -0.95    0.30 kg  (a collision geom)
//   tip              sphere r 0.012 ending at y = -0.98   0.02 kg  (a SENSOR geom: touches)
//
// The original's sword weighs nothing (density 1); a real one loads the wrist with about 2 N m,
// which its drive holds within 0.01 rad.
#pragma once

#include "equipment/equipment.h"

namespace olympics::sports::fencing {

equipment::EquipmentSpec epee();

// The tip point in the hand frame: where the strike reward and the observation measure from.
inline const Eigen::Vector3d kTipInHand(0, -0.98, 0);

// Geoms of the hand body that are part of the épée (a tip touching them is no touch): its
// geoms follow the hand's own in the hand body's list.
int epee_geom_count();

}  // namespace olympics::sports::fencing
