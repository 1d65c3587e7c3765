// Mass properties of a model's bodies from their geoms, as ODE computes them: the server builds
// its rigid bodies from these, and a client's own model of its body (clients/agent/control) uses
// the same numbers, so the two never disagree about a mass or a centre of mass.
#pragma once

#include <ode/ode.h>

#include "core/model_spec.h"

namespace olympics::core {

// One geom's mass (density x volume, or its given mass), in its body's frame.
dMass geom_mass(const GeomSpec& geom);
// A body's mass: the sum of its geoms' (massless-only geoms included, e.g. a racket face).
dMass body_mass(const BodySpec& body);

}  // namespace olympics::core
