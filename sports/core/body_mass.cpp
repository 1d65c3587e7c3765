#include "core/body_mass.h"

namespace olympics::core {

dMass geom_mass(const GeomSpec& g) {
  dMass m;
  switch (g.shape) {
    case GeomShape::Sphere:
      dMassSetSphere(&m, g.density, g.radius);
      break;
    case GeomShape::Capsule:
      dMassSetCapsule(&m, g.density, 3, g.radius, 2 * g.half_length);
      break;
    case GeomShape::Cylinder:
      dMassSetCylinder(&m, g.density, 3, g.radius, 2 * g.half_length);
      break;
    case GeomShape::Box:
      dMassSetBox(&m, g.density, 2 * g.half_extents.x(), 2 * g.half_extents.y(),
                  2 * g.half_extents.z());
      break;
  }
  if (g.mass) dMassAdjust(&m, *g.mass);
  dMatrix3 r;
  dQuaternion q = {g.quat.w(), g.quat.x(), g.quat.y(), g.quat.z()};
  dQtoR(q, r);
  dMassRotate(&m, r);
  dMassTranslate(&m, g.pos.x(), g.pos.y(), g.pos.z());
  return m;
}

dMass body_mass(const BodySpec& body) {
  dMass total;
  dMassSetZero(&total);
  for (const GeomSpec& g : body.geoms) {
    dMass m = geom_mass(g);
    dMassAdd(&total, &m);
  }
  return total;
}

}  // namespace olympics::core
