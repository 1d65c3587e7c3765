// What one physics step shows of an athlete for a field event's referee: where its foremost
// part is, where it touched the ground, and where it touched a sensing surface (a sand pit, a
// landing mat). Read only: nothing here changes the simulation.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/humanoid.h"
#include "core/physics_world.h"

namespace olympics::sports::athletics {

// An axis-aligned rectangle on the ground (a pit's, a mat's footprint).
struct Footprint {
  double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
  bool contains(const Eigen::Vector3d& p) const {
    return p.x() >= x_lo && p.x() <= x_hi && p.y() >= y_lo && p.y() <= y_hi;
  }
};

// Contacts of one athlete in the last step.
struct AthleteContacts {
  bool on_ground = false;        // touched the ground plane outside `surface_area`
  double ground_front_x = -1e9;  // the foremost such ground contact point
  bool on_surface = false;       // touched the surface (or the ground under it)
  double surface_near_x = 1e9;   // the surface contact point nearest to -x (the line)
  double surface_far_x = -1e9;   // and the farthest
};

// The athlete `entity`'s contacts: with the ground, and with the sensor geom whose tag is
// `surface` (its contacts are the world's sensed contacts; a point of the ground plane inside
// `surface_area` counts as the surface's: under sand the plane is the pit's floor).
AthleteContacts athlete_contacts(const core::PhysicsWorld& world, int entity,
                                 const core::GeomTag* surface, const Footprint& surface_area);

// The largest x any of the humanoid's geoms reaches (their bounding boxes): "any part past the
// line".
double foremost_x(const core::Humanoid& humanoid);

// The humanoid's foot bodies (ankles, toes) and the largest x of their origins.
std::vector<int> foot_bodies(const core::Humanoid& humanoid);
double feet_front_x(const core::Humanoid& humanoid, const std::vector<int>& feet);

// The mean position of all the humanoid's bodies (SMPLOlympics' long-jump measure).
Eigen::Vector3d mean_body_position(const core::Humanoid& humanoid);

}  // namespace olympics::sports::athletics
