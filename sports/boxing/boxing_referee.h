// The referee of a boxing bout (SPORTS.md, Boxing; amateur rules where the seed stops), as
// logic alone: told of scoring punches and who is down, it runs the rounds, the count and the
// judges' cards. It keeps no physics, so it is tested with made-up sequences.
//
// - Rounds of `round_s` with `rest_s` between them (the match puts both boxers back in their
//   corners at the start of a rest and of a round).
// - A knock-down: a boxer down (any body but the feet on the canvas) during a round. The count
//   starts; the boxer beats it by being up (not down) for `up_s` in a row, and never before the
//   mandatory count of eight (`mandatory_count_s`: a knocked-down boxer is counted to eight even
//   if up at once, AIBA's and the professional rules alike). Still not up `count_s` after going
//   down: knock-out, the bout is over.
// - Punches landed on a boxer who is down do not score (the match does not report them).
// - Each round is scored 10-point-must: the boxer with more scoring punches 10, the other 9,
//   both 10 when level; every knock-down suffered in the round costs a point (never below 6).
// - After the last round: the decision on the cards' totals (level: a draw).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace olympics::sports::boxing {

struct BoxingRules {
  int rounds = 3;
  double round_s = 60, rest_s = 10;
  double count_s = 10, up_s = 1;
  double mandatory_count_s = 8;  // the count goes on at least this long (capped at count_s)
};

// Something the referee called, for the match to log.
struct BoutCall {
  std::string call;  // "knockdown", "up", "knockout", "round_end", "round_start"
  int boxer = -1;    // -1: both / none
  double time = 0;
  int round = 0;
  std::array<int, 2> card{};  // round_end: the round's card
};

class BoxingReferee {
 public:
  explicit BoxingReferee(const BoxingRules& rules);

  // A scoring punch by `boxer` at `time`.
  void punch(int boxer, double time);
  // Every tick: the clock, and who is down.
  void update(double time, const std::array<bool, 2>& down);

  bool in_round() const { return phase_ == Phase::Round; }
  bool resting() const { return phase_ == Phase::Rest; }
  bool over() const { return phase_ == Phase::Over; }
  int winner() const { return winner_; }                 // -1: a draw, or not over
  const std::string& reason() const { return reason_; }  // "knockout", "decision", ...
  int round() const { return round_; }                   // 1-based
  double phase_time_left(double time) const;             // of the round or the rest, s
  bool counting(int boxer) const { return down_since_[boxer] >= 0; }
  double down_for(int boxer, double time) const;  // s since the knock-down, 0 when up
  const std::array<int, 2>& punches_this_round() const { return punches_round_; }
  const std::array<int, 2>& punches() const { return punches_total_; }
  const std::array<int, 2>& knockdowns() const { return knockdowns_total_; }
  const std::vector<std::array<int, 2>>& cards() const { return cards_; }
  // The cards' totals, a round under way (or stopped by a knock-out) scored as it stands.
  std::array<int, 2> totals() const;
  // The calls since the last take.
  std::vector<BoutCall> take_calls();
  // Ends the bout now on the cards so far (the match's time limit).
  void decide_now(double time);

 private:
  enum class Phase { Round, Rest, Over };
  std::array<int, 2> card_of_round() const;
  void end_round(double time);
  void end_round_card(double time);
  void decide(double time);

  BoxingRules rules_;
  Phase phase_ = Phase::Round;
  int round_ = 1;
  bool round_open_ = true;  // a round is under way (or was stopped) and not on the cards yet
  double phase_start_ = 0;
  std::array<int, 2> punches_round_{}, punches_total_{};
  std::array<int, 2> knockdowns_round_{}, knockdowns_total_{};
  std::array<double, 2> down_since_{-1, -1};  // the count's start, -1: not counting
  std::array<double, 2> up_since_{-1, -1};    // while counting: up since, -1: down
  std::vector<std::array<int, 2>> cards_;
  int winner_ = -1;
  std::string reason_;
  std::vector<BoutCall> calls_;
};

}  // namespace olympics::sports::boxing
