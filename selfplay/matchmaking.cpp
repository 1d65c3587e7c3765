#include "matchmaking.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <stdexcept>

namespace olympics::selfplay {
namespace {

// A uniform draw in [0, 1) from the raw bits: the same on every platform (see pfsp_sample).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

std::pair<std::string, std::string> split_strategy(const std::string& s) {
  auto colon = s.find(':');
  return {s.substr(0, colon), colon == std::string::npos ? "" : s.substr(colon + 1)};
}

}  // namespace

nlohmann::json SelfplayOptions::to_json() const {
  return {{"snapshots_dir", snapshots_dir},
          {"window", window},
          {"strategy", strategy},
          {"bot_share", bot_share},
          {"matches", matches},
          {"lag", lag},
          {"learner", learner}};
}

SelfplayOptions SelfplayOptions::from_json(const std::string& text) {
  auto j = nlohmann::json::parse(text);
  SelfplayOptions o;
  o.snapshots_dir = j.at("snapshots_dir"), o.window = j.at("window"), o.strategy = j.at("strategy");
  o.bot_share = j.at("bot_share"), o.matches = j.at("matches"), o.lag = j.at("lag");
  o.learner = j.value("learner", "");  // runs stored before live learners had none
  return o;
}

int snapshot_version(const std::string& name) {
  static const std::regex pattern(R"(v(\d+)\.safetensors$)");
  std::smatch m;
  if (!std::regex_search(name, m, pattern)) return -1;
  return std::stoi(m[1]);
}

int choose_opponent(const SelfplayOptions& o, const Roster& r, const PayoffMatrix& payoff, int game,
                    std::uint64_t seed, const std::vector<Game>& games) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(game));
  if (!r.bots.empty() && uniform(rng) < o.bot_share)
    return r.bots[static_cast<size_t>(uniform(rng) * static_cast<double>(r.bots.size()))];
  auto [name, arg] = split_strategy(o.strategy);
  if (name == "latest") return r.mirror;
  if (name == "alternating") {
    const int block = std::max(1, arg.empty() ? 250 : std::stoi(arg));
    const int first = game - game % block;
    if (first < game && first < static_cast<int>(games.size()))  // the block's frozen opponent
      return games[first].home == r.latest ? games[first].away : games[first].home;
    return r.mirror;  // a new block: freeze the current latest
  }
  if (name == "mlagents") {
    const double ratio = arg.empty() ? 0.5 : std::stod(arg);
    if (r.window.empty() || uniform(rng) < ratio) return r.mirror;
    return r.window[static_cast<size_t>(uniform(rng) * static_cast<double>(r.window.size()))];
  }
  if (name == "pfsp") {
    std::vector<int> candidates = r.window;
    candidates.insert(candidates.end(), r.bots.begin(), r.bots.end());
    if (candidates.empty()) return r.mirror;
    return pfsp_sample(payoff, r.latest, candidates, parse_weighting(arg.empty() ? "hard" : arg),
                       rng);
  }
  throw std::invalid_argument(
      "unknown matchmaking strategy \"" + o.strategy +
      "\"; known: latest, alternating:E, mlagents:R, pfsp[:hard|variance|linear|even|capped]");
}

void SelfplayScheduler::scan_snapshots(TournamentSpec& spec) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(options_.snapshots_dir)) return;
  std::map<int, std::string> found;  // version -> path
  for (const auto& entry : fs::directory_iterator(options_.snapshots_dir)) {
    int v = snapshot_version(entry.path().filename().string());
    if (v >= 0) found[v] = entry.path().string();
  }
  for (const auto& [version, path] : found) {
    const std::string policy = "mlp:" + path;
    if (std::none_of(spec.entrants.begin(), spec.entrants.end(),
                     [&](const Entrant& e) { return e.policy == policy; })) {
      std::string stem = fs::path(path).stem().string();
      spec.entrants.push_back({"mlp-" + stem, policy, 0});
    }
  }
}

Scheduler::Verdict SelfplayScheduler::schedule(TournamentSpec& spec, const std::vector<Game>& games,
                                               std::vector<Pairing>& out) {
  const int game = static_cast<int>(games.size());
  if (game >= options_.matches) return Verdict::Finished;
  // Decide only on results every run would have: games at least `lag` before this one.
  for (const auto& g : games) {
    if (g.index > game - options_.lag) break;
    if (g.status != GameStatus::Done) return Verdict::Wait;
  }
  // Every decision sees every snapshot published so far: a learner publishes one per update,
  // and a short game can end within a fraction of a second of the last look.
  scan_snapshots(spec);
  PayoffMatrix payoff(static_cast<int>(spec.entrants.size()));
  for (const auto& g : games)
    if (g.index <= game - options_.lag && g.away >= 0 && g.home != g.away)
      payoff.record(g.home, g.away, g.home_score);

  Roster roster;
  int live = -1;
  std::vector<std::pair<int, int>> snapshots;  // version, entrant
  for (int i = 0; i < static_cast<int>(spec.entrants.size()); ++i) {
    const auto& e = spec.entrants[i];
    if (e.policy.rfind("mlp:", 0) == 0)
      snapshots.emplace_back(snapshot_version(e.policy), i);
    else if (e.is_live())
      live = i;
    else
      roster.bots.push_back(i);
  }
  std::sort(snapshots.rbegin(), snapshots.rend());
  // The latest snapshot plays and the older ones are its window; a live learner plays and every
  // snapshot (its newest first) is its window.
  const size_t first_opponent = live >= 0 ? 0 : 1;
  if (live < 0 && snapshots.empty()) return Verdict::Wait;  // nothing published yet
  roster.latest = live >= 0 ? live : snapshots[0].second;
  roster.mirror = live >= 0 ? (snapshots.empty() ? -1 : snapshots[0].second) : roster.latest;
  for (size_t k = first_opponent;
       k < snapshots.size() && static_cast<int>(roster.window.size()) < options_.window; ++k)
    roster.window.push_back(snapshots[k].second);
  const int opponent = choose_opponent(options_, roster, payoff, game, spec.seed, games);
  if (opponent < 0) return Verdict::Wait;  // a live learner with no snapshot to meet yet
  // The learner plays either side, alternately.
  if (game % 2 == 0)
    out.push_back({game, roster.latest, opponent});
  else
    out.push_back({game, opponent, roster.latest});
  return Verdict::Added;
}

}  // namespace olympics::selfplay
