// Tennis and table tennis as sports of the registry: modes ball_return, 1v1, 2v2; settings (a
// match request's options) for the net height, the match format and the rally limit.
#pragma once

#include "racket/racket_match.h"
#include "sport.h"

namespace olympics::sports::racket {

class RacketSport : public Sport {
 public:
  explicit RacketSport(bool table_tennis);
  std::string name() const override { return table_tennis_ ? "table_tennis" : "tennis"; }
  std::string summary() const override;
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return table_tennis_ ? 600 : 1800; }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;

  // The match configuration a request's mode and options give (throws std::invalid_argument).
  RacketMatchConfig config(const std::string& mode, const nlohmann::json& options) const;

 private:
  bool table_tennis_;
  ModeTable modes_;
};

}  // namespace olympics::sports::racket
