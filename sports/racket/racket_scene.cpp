#include "racket/racket_scene.h"

namespace olympics::sports::racket {
namespace {

// A tennis court's lines: both sidelines of singles and doubles, baselines, service lines
// 6.40 m from the net and the centre service line.
void tennis_lines(const RacketGame& g, SceneBuilder& scene) {
  const double L = g.half_length, ws = g.half_width_singles, wd = g.half_width_doubles;
  scene.add_ground_rect(-L, L, -wd, wd, "line");
  scene.add_line({-L, -ws, 0.002}, {L, -ws, 0.002}, "line");
  scene.add_line({-L, ws, 0.002}, {L, ws, 0.002}, "line");
  const double service = 6.40;
  scene.add_line({-service, -ws, 0.002}, {-service, ws, 0.002}, "line");
  scene.add_line({service, -ws, 0.002}, {service, ws, 0.002}, "line");
  scene.add_line({-service, 0, 0.002}, {service, 0, 0.002}, "line");
}

void table(const RacketGame& g, SceneBuilder& scene) {
  const double L = g.half_length, w = g.half_width_singles, top = g.surface_height;
  const double z = top + 0.001;
  scene.add_ground_rect(-L, L, -w, w, "line", z);
  scene.add_line({-L, 0, z}, {L, 0, z}, "line");
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0})
      scene.add_box(-1, {sx * (L - 0.15), sy * (w - 0.15), (top - g.table_thickness) / 2},
                    {0.03, 0.03, (top - g.table_thickness) / 2}, "arena", "#333333");
}

}  // namespace

void describe_racket_arena(const RacketGame& game, SceneBuilder& scene) {
  if (game.on_table) {
    scene.set_ground(8, 5, "#8a6f55");
    table(game, scene);
  } else {
    scene.set_ground(game.half_length + 6, game.half_width_doubles + 4, "#3d7a57");
    tennis_lines(game, scene);
  }
  for (const auto& box : game.arena()) {
    const bool net = box.id == kNet;
    scene.add_box(-1, (box.lo + box.hi) / 2, (box.hi - box.lo) / 2, net ? "net" : "table",
                  net ? "#eeeeee" : "#1d6b45");
  }
}

}  // namespace olympics::sports::racket
