// The javelin's implement, geometry and rules, as the seed has them ("paper": SMPLOlympics'
// javelin and its standing throw) or World Athletics' (TR 32 and 39, the implement
// specification of TR 32.5 for the men's 800 g javelin); javelin_sport.cpp maps the settings
// onto them.
#pragma once

#include <cmath>

namespace olympics::sports::javelin {

// A javelin as one rigid body: a shaft and a metal head (a cone, modelled as a thin capsule),
// lengths from the tip backwards.
struct JavelinSpec {
  double mass = 0;         // kg
  double length = 0;       // m, tip to tail
  double tip_to_com = 0;   // m, the tip to the centre of mass
  double tip_to_grip = 0;  // m, the tip to the middle of the cord grip
  double head_length = 0;  // m, the metal head (its first contact with the ground is the tip's)
  double radius = 0;       // m, the shaft at its thickest
  double head_radius = 0;  // m, the head's capsule (thinner than the shaft: it is a cone)
  double cord_width = 0;   // m, the cord grip (for viewers; the hand holds its middle)
  // The moment of inertia about a transverse axis through the centre of mass (kg m^2); the
  // axial one is that of a solid cylinder of the shaft's radius.
  double transverse_inertia() const { return mass * length * length / 12.0; }
};

// Men's javelin, TR 32.5 (table 1 of the implement specification): 800 g; overall length
// 2.60-2.70 m (2.65 here); metal head 0.25-0.33 m (0.30); tip to centre of gravity
// 0.90-1.06 m (1.00); cord grip 0.15-0.16 m wide over the centre of gravity; shaft diameter at
// its thickest 25-30 mm (28).
inline JavelinSpec official_javelin() { return {0.8, 2.65, 1.00, 1.00, 0.30, 0.014, 0.008, 0.15}; }

// SMPLOlympics' javelin (HUMANOID-SMPLX.md, "Javelin"): a cylinder r 12.5 mm, 2.39 m, then a
// 0.31 m cone to the point, 2.70 m in all, rho 2000 -> 2.45 kg. Its centre of mass lies 1.45 m
// from the tip (the cylinder's and the cone's volumes), the hand holds the mesh's origin,
// 1.35 m from the tip.
inline JavelinSpec paper_javelin() { return {2.45, 2.70, 1.45, 1.35, 0.31, 0.0125, 0.008, 0.15}; }

struct JavelinRules {
  bool official = false;  // the official referee (tip first, sector, arc), else the seed's
  JavelinSpec javelin = paper_javelin();
  bool aerodynamics = false;  // crossflow lift, drag and pitching (javelin_aero.h), else none
  // Field, x from the athlete's start mark along the runway, y across (lane centre 0).
  double run_up = 2.0;         // m from the start mark to the arc's inner edge on the axis
  double arc_radius = 8.0;     // m (TR 32.9, fig. 32.9: an arc of 8 m radius)
  double sector_deg = 28.96;   // the landing sector's angle (TR 32.10)
  double runway_width = 4.0;   // m between the runway lines' inner edges (TR 32.9)
  int attempts = 1;            // per athlete (the seed's episode; TR 25.5: 3 rounds)
  double attempt_s = 10.0;     // s per attempt (TR 25.17: 1 minute)
  double present_s = 0.5;      // s the grip holds whatever the fingers do, so they can close
  double grip_closed = 0.15;   // rad: the fingers' mean flexion that holds the javelin
  double lane_spacing = 60.0;  // m between athletes' runways: sectors never overlap < 115 m
  // The seed (SMPLOlympics' task code): its stages' ends in control ticks, its target, where a
  // javelin "comes down", and how near the hand a thrown javelin must not come back.
  int hold_ticks = 20, throw_ticks = 40;
  double target_x = 50.0;
  double landing_z = 0.3;   // m: paper's mark is the javelin's x where it drops below this
  double hand_near = 0.3;   // m: in flight, a javelin this close to the hand ends the episode
  double stray_deg = 45.0;  // hold/throw: the javelin's attitude this far off the default ends it
  double default_pitch_deg = 30.0;  // the seed's default pose: forward, tilted 30 degrees up

  double half_sector_rad() const { return 0.5 * sector_deg * M_PI / 180.0; }
};

}  // namespace olympics::sports::javelin
