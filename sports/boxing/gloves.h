// Boxing gloves (HUMANOID.md section 1.2; the seed): a hand's box becomes a sphere of radius
// 0.08 m, density about 400 (0.86 kg), centred where the hand box was; a SENSOR geom, so its
// contacts come with their forces (scoring punches). The seed gloves only the right hand; both
// are gloved here by default (a setting).
#pragma once

#include <string>

#include "equipment/equipment.h"

namespace olympics::sports::boxing {

// The glove of "L_Hand" or "R_Hand"; `hand_box_centre` is where the model's hand box sits.
equipment::EquipmentSpec glove(const std::string& hand, const Eigen::Vector3d& hand_box_centre);

// The glove's centre in its hand's frame, as in the model (the hand box's centre).
Eigen::Vector3d glove_centre(const core::ModelSpec& spec, int hand_body);

}  // namespace olympics::sports::boxing
