// The air's force on a flying javelin, by the crossflow model of slender bodies (Allen and
// Perkins, NACA Report 1048, 1951): along its length, each short slice of diameter d and length
// ds feels
//   - against the flow across it (v_n), the drag of a circular cylinder in crossflow,
//     dF = -1/2 rho C_n d ds |v_n| v_n, C_n = 1.2 (measured for a circular cylinder at the
//     subcritical Reynolds numbers of a javelin's slices, 1e4-1e5: Hoerner, Fluid-Dynamic Drag,
//     1965, ch. 3; the javelin's Re = v d / nu ~ 25 * 0.028 / 1.5e-5 ~ 5e4);
//   - along it (v_a), skin friction on the wetted surface, dF = -1/2 rho C_f pi d ds |v_a| v_a,
//     C_f = 0.0035 (a turbulent flat plate at Re_L ~ 4e6: 0.074 Re^-0.2, Schlichting).
// Each slice's velocity includes the spin (v + w x r), so pitching is damped. The sum gives the
// lift and drag of an inclined javelin and, as the crossflow acts over its side area whose
// centroid lies behind the centre of mass (its centre of pressure), a moment that turns the tip
// down into the flight path: why javelins land tip first, and why the rules fix where the centre
// of mass may lie (TR 32.5). Not modelled: the head's pressure drag, wind, shaft vibration.
#pragma once

#include <Eigen/Core>

#include "javelin/javelin_rules.h"

namespace olympics::sports::javelin {

struct AeroLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, world frame
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // N m about the centre of mass
};

inline constexpr double kAirDensity = 1.2;       // kg/m^3
inline constexpr double kCrossflowDrag = 1.2;    // C_n, circular cylinder, subcritical
inline constexpr double kSkinFriction = 0.0035;  // C_f on the wetted surface
inline constexpr int kSlices = 24;

// The load on `spec` moving at `velocity` (its centre of mass), spinning at `spin`, its tip
// along the unit `axis`.
AeroLoad crossflow_load(const JavelinSpec& spec, const Eigen::Vector3d& axis,
                        const Eigen::Vector3d& velocity, const Eigen::Vector3d& spin);

// The slice diameter `s` metres from the tip: the head a cone to the point, then the shaft.
double diameter_at(const JavelinSpec& spec, double from_tip);

}  // namespace olympics::sports::javelin
