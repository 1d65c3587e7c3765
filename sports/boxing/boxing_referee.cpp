#include "boxing/boxing_referee.h"

#include <algorithm>

namespace olympics::sports::boxing {

BoxingReferee::BoxingReferee(const BoxingRules& rules) : rules_(rules) {}

void BoxingReferee::punch(int boxer, double) {
  if (phase_ != Phase::Round) return;
  ++punches_round_[boxer];
  ++punches_total_[boxer];
}

double BoxingReferee::phase_time_left(double time) const {
  const double length = phase_ == Phase::Round  ? rules_.round_s
                        : phase_ == Phase::Rest ? rules_.rest_s
                                                : 0;
  return std::max(0.0, phase_start_ + length - time);
}

double BoxingReferee::down_for(int boxer, double time) const {
  return down_since_[boxer] < 0 ? 0 : time - down_since_[boxer];
}

void BoxingReferee::update(double time, const std::array<bool, 2>& down) {
  if (phase_ == Phase::Over) return;
  if (phase_ == Phase::Rest) {
    if (time - phase_start_ >= rules_.rest_s) {
      phase_ = Phase::Round;
      ++round_;
      round_open_ = true;
      phase_start_ = time;
      calls_.push_back({"round_start", -1, time, round_, {}});
    }
    return;
  }
  for (int b = 0; b < 2; ++b) {
    if (down_since_[b] < 0) {
      if (!down[b]) continue;
      down_since_[b] = time;
      up_since_[b] = -1;
      ++knockdowns_round_[b];
      ++knockdowns_total_[b];
      calls_.push_back({"knockdown", b, time, round_, {}});
      continue;
    }
    if (down[b]) {
      up_since_[b] = -1;
    } else if (up_since_[b] < 0) {
      up_since_[b] = time;
    }
    const double mandatory = std::min(rules_.mandatory_count_s, rules_.count_s);
    if (up_since_[b] >= 0 && time - up_since_[b] >= rules_.up_s &&
        time - down_since_[b] >= mandatory) {
      down_since_[b] = -1;
      calls_.push_back({"up", b, time, round_, {}});
    }
  }
  std::array<bool, 2> out{};
  for (int b = 0; b < 2; ++b)
    out[b] = down_since_[b] >= 0 && time - down_since_[b] >= rules_.count_s;
  if (out[0] || out[1]) {
    for (int b = 0; b < 2; ++b)
      if (out[b]) calls_.push_back({"knockout", b, time, round_, {}});
    phase_ = Phase::Over;
    winner_ = out[0] && out[1] ? -1 : (out[0] ? 1 : 0);
    reason_ = out[0] && out[1] ? "double_knockout" : "knockout";
    return;
  }
  if (time - phase_start_ >= rules_.round_s) end_round(time);
}

std::array<int, 2> BoxingReferee::card_of_round() const {
  std::array<int, 2> card{10, 10};
  if (punches_round_[0] != punches_round_[1])
    card[punches_round_[0] < punches_round_[1] ? 0 : 1] = 9;
  for (int b = 0; b < 2; ++b) card[b] = std::max(6, card[b] - knockdowns_round_[b]);
  return card;
}

void BoxingReferee::end_round_card(double time) {
  const auto card = card_of_round();
  cards_.push_back(card);
  round_open_ = false;
  calls_.push_back({"round_end", -1, time, round_, card});
}

void BoxingReferee::end_round(double time) {
  end_round_card(time);
  punches_round_ = {0, 0};
  knockdowns_round_ = {0, 0};
  down_since_ = {-1, -1};  // the bell ends a count
  if (round_ >= rules_.rounds) return decide(time);
  phase_start_ = time;
  phase_ = rules_.rest_s > 0 ? Phase::Rest : Phase::Round;
  if (phase_ == Phase::Round) {
    ++round_;
    round_open_ = true;
    calls_.push_back({"round_start", -1, time, round_, {}});
  }
}

std::array<int, 2> BoxingReferee::totals() const {
  std::array<int, 2> t{0, 0};
  for (const auto& c : cards_) t[0] += c[0], t[1] += c[1];
  if (round_open_) {
    const auto now = card_of_round();
    t[0] += now[0], t[1] += now[1];
  }
  return t;
}

void BoxingReferee::decide(double) {
  const auto t = totals();
  phase_ = Phase::Over;
  winner_ = t[0] == t[1] ? -1 : (t[0] > t[1] ? 0 : 1);
  reason_ = winner_ < 0 ? "decision_draw" : "decision";
}

void BoxingReferee::decide_now(double time) {
  if (phase_ == Phase::Over) return;
  if (round_open_) end_round_card(time);
  decide(time);
}

std::vector<BoutCall> BoxingReferee::take_calls() {
  std::vector<BoutCall> out;
  out.swap(calls_);
  return out;
}

}  // namespace olympics::sports::boxing
