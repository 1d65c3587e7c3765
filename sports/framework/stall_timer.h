// A rule piece: "nothing has happened for too long". A referee restarts it whenever play makes
// progress (a stroke, a touch, a punch); once `limit_s` passes without one, it has expired and
// the sport decides what that means (the side to play loses the point, the fencers are sent back
// to their lines, ...).
#pragma once

namespace olympics::sports {

class StallTimer {
 public:
  explicit StallTimer(double limit_s = 0) : limit_s_(limit_s) {}
  void set_limit(double limit_s) { limit_s_ = limit_s; }
  void restart(double now) { since_ = now; }
  bool expired(double now) const { return now - since_ >= limit_s_; }
  double since() const { return since_; }

 private:
  double limit_s_;
  double since_ = 0;
};

}  // namespace olympics::sports
