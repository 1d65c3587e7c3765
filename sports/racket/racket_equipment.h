// What tennis and table-tennis players hold (HUMANOID.md section 1.2).
#pragma once

#include "equipment/equipment.h"

namespace olympics::sports::racket {

// Racket: handle cylinder r 0.016 from the wrist to 0.35 m along -y (rho 500, 0.14 kg), head
// disc r 0.15, 0.04 thick at y = -0.35 (rho 150, 0.42 kg); e 0.8, mu 0.8.
equipment::EquipmentSpec tennis_racket();
// Paddle: disc r 0.08, 0.02 thick at y = -0.12 (rho 200, 0.08 kg) replacing the hand box; e 0.2
// is the paddle's own value in the original, but a real blade with rubber returns a table-tennis
// ball with e of about 0.85, so the face uses that (docs/physics.md).
equipment::EquipmentSpec table_tennis_paddle();

}  // namespace olympics::sports::racket
