// A thrown ball's flight as a client can predict it: gravity and quadratic air drag, in the
// vertical plane of the throw. Scripted players aim with it (the free-throw shooter solves for
// the launch speed that carries the ball down through the rim).
#pragma once

namespace olympics::client {

// Drag deceleration per (m/s)^2 of a ball: 1/2 rho Cd A / m (SPORTS.md's balls, air 1.2 kg/m^3).
// The server adds the same force before every physics step (sports/equipment/ball.h).
double drag_per_mass(double radius_m, double mass_kg, double drag_coefficient);
// ...of the basketball the server plays with (sports/equipment/ball.cpp).
double basketball_drag_per_mass();

// The server's physics step (DESIGN.md: 120 Hz). The flight is integrated as ODE does it
// (velocity first, then position with the new velocity; drag from the velocity at the step's
// start), so a prediction follows the server's ball to within a centimetre, not the exact
// parabola (from which a 120 Hz step falls some 5 cm short over a free throw).
inline constexpr double kServerStep_s = 1.0 / 120;

// Launched at `speed` m/s, `elevation` rad above the horizontal: how far the ball has travelled
// horizontally when it comes down through `rise` m above its launch point; negative when its
// path never reaches that height.
double carry_to_height(double speed, double elevation, double rise, double drag,
                       double step_s = kServerStep_s);

// The launch speed at `elevation` whose path comes down through `rise` m above the launch point
// `carry` m away horizontally (bisection on carry_to_height, to 1 mm/s); 0 when no speed up to
// 40 m/s reaches so far.
double launch_speed_for(double carry, double rise, double elevation, double drag,
                        double step_s = kServerStep_s);

}  // namespace olympics::client
