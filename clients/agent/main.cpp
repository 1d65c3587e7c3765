// olympics-agent: joins a match and plays it with a named policy, then prints the result.
//
//   olympics-agent --request-id demo --sport sandbox --mode 1v1 --slots 0 --policy zero
//   olympics-agent --match SERVER-7 --slots 1 --policy random
//   olympics-agent --learner alice --games 3 --policy mlp:v7.safetensors   (league entrant
//   live:alice)
//
// Agents given the same --request-id share one match (the server dedupes the request), so two
// processes can meet without passing a match id around.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "call_log.h"
#include "match_client.h"
#include "play_match.h"
#include "policies.h"

namespace {

void play_one(olympics::client::MatchClient& client, const std::string& match_id,
              const std::vector<int>& slots, const std::string& policy_name,
              std::uint64_t policy_seed, const std::string& agent_name, int think_ms,
              double timeout_s, bool json, bool calls) {
  const auto match = client.join(match_id, slots, timeout_s);
  std::fprintf(stderr, "%s joined %s (%s %s) slots", agent_name.c_str(), match.match_id.c_str(),
               match.sport.c_str(), match.mode.c_str());
  for (int s : slots) std::fprintf(stderr, " %d", s);
  std::fprintf(stderr, " with policy %s\n", policy_name.c_str());

  olympics::client::PlayOptions play;
  play.policy = policy_name, play.policy_seed = policy_seed, play.think_ms = think_ms;
  play.timeout_s = timeout_s;
  if (calls)
    play.on_observation = [announced = olympics::client::announced_calls(match.sport, match.mode)](
                              const olympics::client::Observation& obs) {
      for (const auto& line : olympics::client::call_lines(obs.tick, obs.info, announced))
        std::printf("%s\n", line.c_str());
      std::fflush(stdout);
    };
  const auto& r = olympics::client::play_joined_match(client, play);
  if (client.ignored_errors() > 0)  // a server never sends these: someone else on the network did
    std::fprintf(stderr, "%s ignored %ld error(s) naming it for matches it does not hold\n",
                 agent_name.c_str(), client.ignored_errors());
  if (json) {
    nlohmann::json out = {
        {"match_id", r.match_id}, {"sport", r.sport},        {"mode", r.mode},
        {"ticks", r.ticks},       {"reason", r.reason},      {"winner_team", r.winner_team},
        {"scores", r.scores},     {"agents", r.agent_names}, {"slot_team", r.slot_team}};
    std::printf("%s\n", out.dump().c_str());
  } else {
    const double seconds = r.ticks / static_cast<double>(client.match().control_hz);
    std::printf("match %s (%s %s) over after %d ticks (%.1f s simulated): %s\n", r.match_id.c_str(),
                r.sport.c_str(), r.mode.c_str(), r.ticks, seconds, r.reason.c_str());
    for (int t = 0; t < r.num_teams; ++t) {
      std::string names;
      for (int s = 0; s < r.num_slots; ++s)
        if (r.slot_team[s] == t) names += (names.empty() ? "" : ", ") + r.agent_names[s];
      std::printf("  team %d (%s): %.2f%s\n", t, names.c_str(), r.scores[t],
                  r.winner_team == t ? "  WINNER" : "");
    }
    if (r.winner_team < 0) std::printf("  no winner\n");
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace olympics::client;
  CLI::App app{"olympics-agent: play a match with a named policy"};
  ClientOptions options;
  MatchRequest request;
  std::string match_id, policy_name = "zero";
  std::vector<int> slots{0};
  std::uint64_t policy_seed = 1;
  bool json = false;
  double timeout_s = 60;
  int think_ms = 0;
  std::string learner;
  int games = 1;
  app.add_option("--match", match_id, "join this match id (else request one)");
  app.add_option("--request-id", request.request_id,
                 "request id; agents with the same id share a match");
  app.add_option("--sport", request.sport, "sport to request");
  app.add_option("--mode", request.mode, "mode to request (1v1, 2v2, ...)");
  app.add_option("--seed", request.seed, "match seed");
  app.add_option("--time-limit", request.time_limit_s, "seconds (0: the sport's default)");
  app.add_flag("--realtime", request.realtime, "30 Hz clock instead of lockstep");
  app.add_option("--options", request.options,
                 "the sport's settings as JSON, e.g. '{\"format\": \"tiebreak\"}'");
  app.add_option("--server", request.server_id, "ask this server only");
  app.add_option("--slots", slots, "slots to play")->delimiter(',');
  app.add_option("--policy", policy_name, "zero, random, scripted, mlp:<snapshot.safetensors>");
  app.add_option("--policy-seed", policy_seed, "seed of a random policy");
  app.add_option("--name", options.agent_name, "agent name recorded with the result");
  app.add_option("--policy-id", options.policy_id, "policy id recorded with the result");
  app.add_option("--policy-version", options.policy_version,
                 "policy version recorded with the result");
  app.add_option("--lcm-url", options.lcm_url, "LCM provider URL");
  app.add_option("--secret", options.secret_file,
                 "the deployment's secret file (default $OLYMPICS_SECRET_FILE; docs/security.md)");
  app.add_option("--timeout", timeout_s, "give up when the server is silent this long (s)");
  app.add_option("--drop-rate", options.drop_rate, "TEST ONLY: drop this share of sent datagrams");
  app.add_option("--drop-seed", options.drop_seed, "TEST ONLY: seed of the drops");
  app.add_option("--learner", learner, "play the matches a league assigns to entrant live:NAME");
  app.add_option("--games", games, "with --learner: how many assigned matches to play")
      ->check(CLI::PositiveNumber);
  app.add_option("--think-ms", think_ms, "sleep this long before each action (a slow policy)");
  app.add_flag("--json", json, "print the result as JSON");
  bool calls = false;
  app.add_flag("--calls", calls, "print the referee's decisions and the score as they happen");
  CLI11_PARSE(app, argc, argv);
  if (options.policy_id.empty()) options.policy_id = policy_name;

  try {
    make_policy(policy_name, policy_seed);  // an unknown policy is refused before any match
    if (!learner.empty() && options.agent_name == "agent") options.agent_name = learner;
    MatchClient client(options);
    // One match, or (a live learner) every match the league assigns, `games` of them.
    for (int game = 0; game < (learner.empty() ? 1 : games); ++game) {
      if (!learner.empty()) {
        auto assignment = client.wait_assignment(learner, std::max(timeout_s, 600.0));
        match_id = assignment.match_id;
        slots = assignment.slots;
      }
      if (match_id.empty()) match_id = client.request_match(request, timeout_s).match_id;
      play_one(client, match_id, slots, policy_name, policy_seed, options.agent_name, think_ms,
               timeout_s, json, calls);
      match_id.clear();
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "olympics-agent: %s\n", e.what());
    return 2;
  }
}
