#include "racket/racket_sport.h"

#include <stdexcept>

namespace olympics::sports::racket {
namespace {

RacketMode racket_mode(const std::string& mode) {
  if (mode == "ball_return") return RacketMode::BallReturn;
  return mode == "1v1" ? RacketMode::Singles : RacketMode::Doubles;
}

}  // namespace

RacketSport::RacketSport(bool table_tennis)
    : table_tennis_(table_tennis),
      modes_(name(), {{"ball_return", {0}, "one player returns balls launched from the far side"},
                      {"1v1", {0, 1}, "singles"},
                      {"2v2", {0, 0, 1, 1}, "doubles"}}) {}

std::string RacketSport::summary() const {
  return table_tennis_ ? "paddle, table, ball with drag; games to 11, win by 2"
                       : "racket, court, ball with drag; points, games, tie-break sets";
}

std::vector<SettingSpec> RacketSport::settings() const {
  const auto stall = SettingSpec::number(
      "max_rally_s", 10.0, "no stroke for this long: the side to play loses the point", 1, 60);
  const auto feed = SettingSpec::choice(
      "feed", "to_player",
      "each point's first ball: \"to_player\" at the receiver, landing deep (the seed's "
      "feed), or \"anywhere\" on the receiving half",
      {"to_player", "anywhere"});
  const auto start = SettingSpec::choice(
      "start", "feed",
      "1v1 / 2v2: each point's first ball is \"feed\" (fed to the serving side, which plays the "
      "first shot) or \"serve\" (tossed for the server, who must serve it into the diagonal "
      "service box, or in table tennis onto its own court and then the receiver's)",
      {"feed", "serve"});
  // Table tennis: the seed's table, net, ball and paddle are ITTF's; "official" changes nothing.
  if (table_tennis_)
    return {SettingSpec::rules_preset(),
            SettingSpec::number("games_to_win", 1, "games that win the match (best of 2n-1)", 1, 4),
            SettingSpec::number("points_per_game", 11, "points that win a game, by 2", 1, 21),
            stall,
            feed,
            start};
  return {
      SettingSpec::rules_preset(),
      SettingSpec::number("net_height", 1.0,
                          "m; the seed's 1.0 (a real net is 0.914 at the centre)", 0.5, 1.5)
          .with_official(0.914),  // ITF Rules of Tennis, rule 1
      SettingSpec::choice("format", "sets", "\"tiebreak\": every set is one tie-break game",
                          {"sets", "tiebreak"}),
      SettingSpec::number("sets_to_win", 1, "sets that win the match (best of 2n-1)", 1, 3),
      SettingSpec::number("games_per_set", 6, "games that win a set, by 2; tie-break at n-n", 1, 6),
      SettingSpec::number("tiebreak_points", 7, "points that win a tie-break game, by 2", 1, 10),
      stall,
      feed,
      start};
}

RacketMatchConfig RacketSport::config(const std::string& mode,
                                      const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  RacketMatchConfig c;
  c.mode = racket_mode(modes_.at(mode).name);
  c.max_rally_s = s.at("max_rally_s").get<double>();
  c.feed_to_player = s.at("feed") == "to_player";
  c.serve = s.at("start") == "serve";
  if (c.serve && c.mode == RacketMode::BallReturn)
    throw std::invalid_argument(
        name() +
        " ball_return: start \"serve\" needs a scoreboard and a server; ball_return "
        "feeds every ball. Use mode 1v1 or 2v2 to serve, or drop the start setting");
  if (table_tennis_) {
    c.game = table_tennis_game();
    c.table_tennis.games_to_win = s.at("games_to_win");
    c.table_tennis.points_per_game = s.at("points_per_game");
    return c;
  }
  c.game = tennis_game(s.at("net_height").get<double>());
  c.tennis.tiebreak_only = s.at("format") == "tiebreak";
  c.tennis.sets_to_win = s.at("sets_to_win");
  c.tennis.games_per_set = s.at("games_per_set");
  c.tennis.tiebreak_points = s.at("tiebreak_points");
  return c;
}

std::unique_ptr<SportMatch> RacketSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  if (s.time_limit_s <= 0) s.time_limit_s = default_time_limit_s();
  return std::make_unique<RacketMatch>(config(s.mode, s.options), modes_.at(s.mode), layout(s.mode),
                                       s);
}

Layout RacketSport::layout(const std::string& mode) const {
  return smpl_layout(racket_task_layout(modes_.at(mode).slot_count()), racket_rewards(),
                     racket_calls());
}

}  // namespace olympics::sports::racket

namespace olympics::sports {
std::unique_ptr<Sport> make_tennis() {
  return std::make_unique<racket::RacketSport>(/*table_tennis=*/false);
}
std::unique_ptr<Sport> make_table_tennis() {
  return std::make_unique<racket::RacketSport>(/*table_tennis=*/true);
}
}  // namespace olympics::sports
