#include "ball_aim.h"

#include <cmath>

#include "equipment/ball.h"

namespace olympics::client {
namespace {

constexpr double kGravity = 9.81;
constexpr double kAirDensity = 1.2;  // kg/m^3
constexpr double kMaxSpeed = 40;

}  // namespace

double drag_per_mass(double radius_m, double mass_kg, double drag_coefficient) {
  return 0.5 * kAirDensity * drag_coefficient * M_PI * radius_m * radius_m / mass_kg;
}

double basketball_drag_per_mass() {
  const sports::equipment::BallSpec ball = sports::equipment::basketball();
  return drag_per_mass(ball.radius, ball.mass, ball.drag_coefficient);
}

double carry_to_height(double speed, double elevation, double rise, double drag, double step_s) {
  double x = 0, z = 0, vx = speed * std::cos(elevation), vz = speed * std::sin(elevation);
  for (double t = 0; t < 20; t += step_s) {
    const double v = std::hypot(vx, vz);
    vx += -drag * v * vx * step_s;
    vz += (-kGravity - drag * v * vz) * step_s;
    const double last_z = z, last_x = x;
    x += vx * step_s;
    z += vz * step_s;
    if (vz < 0 && z < rise) {
      if (last_z < rise) return -1;  // already below the height at the apex: never reached it
      return last_x + (x - last_x) * (last_z - rise) / (last_z - z);
    }
  }
  return -1;
}

double launch_speed_for(double carry, double rise, double elevation, double drag, double step_s) {
  if (carry_to_height(kMaxSpeed, elevation, rise, drag, step_s) < carry) return 0;
  // At a fixed elevation the carry grows with the speed; a speed whose path never reaches the
  // height counts as too short (carry_to_height < 0). So bisect.
  double low = 0, high = kMaxSpeed;
  while (high - low > 1e-3) {
    const double mid = 0.5 * (low + high);
    (carry_to_height(mid, elevation, rise, drag, step_s) < carry ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace olympics::client
