// The "ball" observation block of a sport played with an ODE ball (soccer, basketball): its
// layout entry and its writer in one place, so that what describe says and what is written agree.
#pragma once

#include "equipment/ball.h"
#include "framework/heading_frame.h"
#include "framework/observation_writer.h"
#include "sport.h"

namespace olympics::sports {

inline constexpr double kBallSpinLimit = 100;  // rad/s, observation clamp

inline LayoutBlock ball_observation_block() {
  return LayoutBlock::of(
      "ball", "m, m/s, rad/s",
      "the ball's centre relative to the root (3), velocity (3), spin (3), heading frame",
      {{"position", 3}, {"velocity", 3}, {"spin", 3}});
}

inline void write_ball_observation(const equipment::Ball& ball, const HeadingFrame& frame,
                                   ObservationWriter& out) {
  out.begin("ball")
      .field("position")
      .put(frame.point(ball.position()))
      .field("velocity")
      .put(frame.vector(ball.velocity()))
      .field("spin")
      .put_clamped(frame.vector(ball.angular_velocity()), kBallSpinLimit);
}

}  // namespace olympics::sports
