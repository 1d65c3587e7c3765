// What a golfer holds: a club as held equipment (equipment/equipment.h), gripped in the right
// hand like a racket, its shaft running on along the hand's -y axis (where the arm points) to a
// box head. The head is an ODE geom: a golf ball rests on the ground and is struck by the solver's
// contact with the head, unlike a racket's ball, which BallFlight sweeps against a face disc.
//
// Hand frame: with the arm hanging straight down (rotated from the T-pose about the x axis), the
// hand's x is the body's forward and its z the body's right-to-left: the head's face looks along
// the hand's +x, its toe-heel length runs along z, and the loft tilts the face up by turning the
// head about z.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "equipment/equipment.h"

namespace olympics::sports::golf {

struct ClubSpec {
  std::string name;
  double length = 0;    // m from the hand's origin (the grip) to the head's centre
  double loft_deg = 0;  // the face's tilt up from vertical
  Eigen::Vector3d head_half = Eigen::Vector3d::Zero();  // hand frame: face depth, height, toe-heel
  double head_mass = 0;                                 // kg
  double shaft_mass = 0;   // kg (grip and shaft, a capsule of radius 8 mm)
  double restitution = 0;  // of the head against a ball (its coefficient of restitution)
  double friction = 0.8;   // of the face against a ball
};

// A putter (USGA/R&A Equipment Rules: no length limit for a putter, >= 18 in overall): a 0.10 m
// blade, 0.33 kg, 3 degrees of loft; e 0.8 (the original's club restitution). Its length is
// that of a face-on putter held with the arm hanging: the head skims the green.
ClubSpec putter();
// A driver: 1.14 m to the head (the original's shaft), 10.5 degrees of loft, 0.20 kg head,
// e 0.83 (the Equipment Rules' limit on the spring-like effect).
ClubSpec driver();
// The seed's club: a 0.05 x 0.025 x 0.02 m head 1.14 m from the hand (SMPLOlympics'
// paddle_to_hand offset (0, -1.14, 0)), e 0.8, friction 0.8.
ClubSpec seed_club();

inline constexpr const char* kClubHeadGeom = "club_head";

// The club as equipment in the right hand: shaft capsule and head box.
equipment::EquipmentSpec club_equipment(const ClubSpec& club);

// The head's centre in the hand frame.
inline Eigen::Vector3d club_head_offset(const ClubSpec& club) { return {0, -club.length, 0}; }

// The head's orientation in the hand frame. Loft: the face (+x) turned up, about the toe-heel
// axis (z), towards the hand (+y).
inline Eigen::Quaterniond club_head_orientation(const ClubSpec& club) {
  return Eigen::Quaterniond(
      Eigen::AngleAxisd(club.loft_deg * M_PI / 180, Eigen::Vector3d::UnitZ()));
}

}  // namespace olympics::sports::golf
