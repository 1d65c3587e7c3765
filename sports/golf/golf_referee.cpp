#include "golf/golf_referee.h"

#include <algorithm>

namespace olympics::sports::golf {

int HoleReferee::score() const {
  if (over_ && !holed_) return rules_.max_strokes;  // picked up: the maximum (Rule 21.2b)
  return std::min(strokes_ + penalties_, rules_.max_strokes);
}

GolfCall HoleReferee::step(const GolfTick& s) {
  if (over_) return GolfCall::None;
  if (s.club_touch) {
    const bool new_stroke = s.club_touch_t - last_touch_ > kOneStrokeS;
    last_touch_ = s.club_touch_t;
    in_motion_ = true;
    slow_since_ = -1;
    if (new_stroke) {
      ++strokes_;
      return GolfCall::Stroke;
    }
  }
  if (s.holed) {
    over_ = holed_ = true;
    in_motion_ = false;
    return GolfCall::Holed;
  }
  if (in_motion_ && s.out_of_bounds) {
    ++penalties_;
    in_motion_ = false;
    if (strokes_ + penalties_ >= rules_.max_strokes) {
      over_ = true;
      picked_up_reason_ = "max_strokes";
      return GolfCall::PickedUp;
    }
    return GolfCall::OutOfBounds;
  }
  if (s.t > rules_.hole_s) {
    over_ = true;
    picked_up_reason_ = "time";
    return GolfCall::PickedUp;
  }
  if (!in_motion_) return GolfCall::None;
  if (s.ball_speed >= kAtRestSpeed) {
    slow_since_ = -1;
    return GolfCall::None;
  }
  if (slow_since_ < 0) slow_since_ = s.t;
  if (s.t - slow_since_ < kAtRestS) return GolfCall::None;
  in_motion_ = false;
  if (strokes_ + penalties_ >= rules_.max_strokes) {
    over_ = true;
    picked_up_reason_ = "max_strokes";
    return GolfCall::PickedUp;
  }
  return GolfCall::AtRest;
}

std::optional<SeedEnding> SeedReferee::end(const std::string& why, double stop_distance) {
  SeedEnding e;
  e.reason = why;
  e.hit = contact_;
  e.stopped = stop_distance >= 0;
  e.stop_distance = e.stopped ? stop_distance : 0;
  ending_ = e;
  return e;
}

std::optional<SeedEnding> SeedReferee::step(const GolfTick& s) {
  if (ending_) return std::nullopt;
  contact_ = contact_ || s.seed_contact;
  if (s.tick <= 1) return std::nullopt;  // the seed's has_failed *= progress_buf > 1
  const double distance = (s.ball - s.target).norm();
  if (contact_ && s.ball_speed < kSeedStopSpeed) return end("ball_stopped", distance);
  if (s.down) return end("fell");
  if (s.body_near_ball) return end("ball_near_body");
  if (contact_ && (s.ball_prev - s.target).norm() < distance) return end("ball_not_closer");
  if (!contact_ && (s.tick > 60 || s.ball.x() < -0.05)) return end("no_contact");
  return std::nullopt;
}

}  // namespace olympics::sports::golf
