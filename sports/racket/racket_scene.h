// How a tennis court or a table-tennis table looks, for viewers (framework/scene_view.h).
#pragma once

#include "framework/scene_view.h"
#include "racket/racket_game.h"

namespace olympics::sports::racket {

// The floor, the court's lines or the table with its lines and legs, and the net.
void describe_racket_arena(const RacketGame& game, SceneBuilder& scene);

}  // namespace olympics::sports::racket
