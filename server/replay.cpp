#include "replay.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "registry.h"

namespace olympics::server {
namespace {
constexpr const char* kMagic = "OLYMPICS-REPLAY 1";
}

std::string write_replay(const std::string& path, const Replay& r) {
  // Never over another replay: a taken name gets a numbered suffix.
  std::string where = path;
  for (int n = 1; std::filesystem::exists(where); ++n) where = path + "." + std::to_string(n);
  std::ofstream out(where, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write replay " + where);
  nlohmann::json header = r.header;
  header["slot_count"] = r.slot_count;
  header["action_size"] = r.action_size;
  header["ticks_recorded"] = r.ticks();
  out << kMagic << "\n" << header.dump() << "\n";
  out.write(reinterpret_cast<const char*>(r.actions.data()),
            static_cast<std::streamsize>(r.actions.size() * sizeof(float)));
  if (!out) throw std::runtime_error("writing replay " + where + " failed (disk full?)");
  return where;
}

Replay read_replay(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open replay " + path);
  std::string magic, header_line;
  std::getline(in, magic);
  if (magic != kMagic)
    throw std::runtime_error(path + " is not a replay file (no \"" + kMagic + "\" line)");
  std::getline(in, header_line);
  Replay r;
  try {
    r.header = nlohmann::json::parse(header_line);
    r.slot_count = r.header.at("slot_count");
    r.action_size = r.header.at("action_size");
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": the header line is damaged: " + e.what());
  }
  std::stringstream rest;
  rest << in.rdbuf();
  std::string bytes = rest.str();
  const size_t per_tick = static_cast<size_t>(r.slot_count) * r.action_size * sizeof(float);
  const int ticks = r.header.value("ticks_recorded", -1);
  if (per_tick == 0 || bytes.size() % per_tick != 0 ||
      static_cast<int>(bytes.size() / per_tick) != ticks)
    throw std::runtime_error(path + ": truncated: " + std::to_string(bytes.size()) +
                             " bytes of actions do not make the " + std::to_string(ticks) +
                             " ticks the header announces");
  r.actions.resize(bytes.size() / sizeof(float));
  std::memcpy(r.actions.data(), bytes.data(), bytes.size());
  return r;
}

std::unique_ptr<sports::SportMatch> rerun_replay(
    const Replay& r, const std::function<void(const sports::SportMatch&)>& on_tick) {
  const auto& h = r.header;
  const sports::Sport& sport = sports::sport_or_throw(h.at("sport"));
  sports::MatchSettings settings{h.at("mode"), h.at("seed").get<std::uint64_t>(),
                                 h.at("time_limit_s"),
                                 h.value("options", nlohmann::json::object())};
  auto match = sport.create(settings);
  if (match->slot_count() != r.slot_count || match->action_size() != r.action_size)
    throw std::runtime_error("the replay's slots or action size do not match the sport's");
  if (on_tick) on_tick(*match);
  const int forfeit_tick = h.contains("forfeit") ? h["forfeit"].at("tick").get<int>() : -1;
  std::vector<std::span<const float>> actions(r.slot_count);
  for (int t = 0; t < r.ticks() && !match->outcome().match_over; ++t) {
    for (int s = 0; s < r.slot_count; ++s)
      actions[s] = std::span<const float>(
          r.actions.data() + (static_cast<size_t>(t) * r.slot_count + s) * r.action_size,
          r.action_size);
    match->step(actions);
    if (on_tick) on_tick(*match);
  }
  if (forfeit_tick >= 0 && match->tick() == forfeit_tick) {
    match->forfeit(h["forfeit"].at("team"), h["forfeit"].at("reason"));
    if (on_tick) on_tick(*match);
  }
  return match;
}

ReplayCheck verify_replay(const Replay& r) {
  std::unique_ptr<sports::SportMatch> match;
  try {
    match = rerun_replay(r, nullptr);
  } catch (const std::runtime_error& e) {
    return {false, e.what()};
  }
  const auto& want = r.header.at("result");
  const auto& got = match->outcome();
  std::vector<double> got_scores(got.scores.begin(), got.scores.end());
  std::ostringstream report;
  bool same = true;
  auto compare = [&](const char* what, const auto& recorded, const auto& rerun) {
    bool eq = recorded == rerun;
    same = same && eq;
    report << what << ": recorded " << nlohmann::json(recorded).dump() << ", re-run "
           << nlohmann::json(rerun).dump() << (eq ? "" : "  <-- differs") << "\n";
  };
  compare("ticks", want.at("ticks").get<int>(), match->tick());
  compare("reason", want.at("reason").get<std::string>(), got.reason);
  compare("winner_team", want.at("winner_team").get<int>(), got.winner_team);
  compare("scores", want.at("scores").get<std::vector<double>>(), got_scores);
  compare("state_hash", want.at("state_hash").get<std::uint64_t>(), match->state_hash());
  return {same, report.str()};
}

}  // namespace olympics::server
