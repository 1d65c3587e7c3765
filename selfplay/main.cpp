// olympics-league: tournaments among policies over olympics-servers, with ratings.
//
//   olympics-league run   --db league.db --name cup --format round-robin
//                         --entrants zero,random:1,random:2,zero [--servers a,b] [--parallel 2]
//   olympics-league run   --db league.db --name final --sport long_jump --mode competition_8
//                         --entrants zero,random:1,...   (heats of 8 ranked by places)
//   olympics-league table --db league.db --name cup [--svg ratings.svg] [--json]
//   olympics-league list  --db league.db
//
// run resumes a tournament of that name if the database has it (after a crash or kill -9).
// Across machines (docs/deploy.md): run --fleet / selfplay --fleet queue the games in PostgreSQL
// and `olympics-league cell` plays them on each host.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "cell_command.h"
#include "fixture_queue.h"
#include "fleet_snapshots.h"
#include "heats.h"
#include "leaderboard.h"
#include "league_store.h"
#include "matchmaking.h"
#include "process.h"
#include "selfplay_fleet.h"
#include "tournament_runner.h"

namespace {

using namespace olympics::selfplay;

// "zero,random:3,mlp:runs/v7.safetensors,zero" -> zero, random-3, mlp-v7, zero-2: the policy
// olympics-agent plays (a bot, or a frozen snapshot) and its seed.
std::vector<Entrant> parse_entrants(const std::vector<std::string>& specs, size_t at_least) {
  std::vector<Entrant> out;
  std::map<std::string, int> seen;
  for (const auto& spec : specs) {
    Entrant e;
    auto colon = spec.find(':');
    e.policy = spec.substr(0, colon);
    if (e.policy == "mlp" && colon != std::string::npos) {
      const std::string file = spec.substr(colon + 1);
      if (!std::ifstream(file)) throw std::invalid_argument("snapshot " + file + " cannot be read");
      e.policy = spec;
      std::string stem = file.substr(file.rfind('/') + 1);
      e.name = "mlp-" + stem.substr(0, stem.find('.'));
    } else if (e.policy == "live" && colon != std::string::npos) {
      e.policy = spec;  // a trainer's own client plays it (olympics-agent --learner, or Python)
      e.name = spec.substr(colon + 1);
    } else if (e.policy == "zero" || e.policy == "random" || e.policy == "scripted") {
      e.seed = colon == std::string::npos ? 1 : std::stoull(spec.substr(colon + 1));
      e.name = colon == std::string::npos ? e.policy : e.policy + "-" + spec.substr(colon + 1);
    } else {
      throw std::invalid_argument(
          "unknown entrant \"" + spec +
          "\"; entrants: zero, random[:seed], scripted[:seed], mlp:<snapshot.safetensors>, "
          "live:<learner>");
    }
    if (int n = ++seen[e.name]; n > 1) e.name += "-" + std::to_string(n);
    out.push_back(e);
  }
  if (out.size() < at_least)
    throw std::invalid_argument("needs at least " + std::to_string(at_least) + " entrants");
  return out;
}

// The settings given on the command line that differ from a stored run's ("sport fencing, not
// tennis; ..."); only flags actually given count.
std::string differences(const TournamentSpec& stored, const TournamentSpec& asked,
                        const CLI::App& cmd, const std::vector<std::string>& entrants) {
  std::string out;
  auto note = [&](const char* flag, const std::string& now, const std::string& was) {
    if (cmd.count(flag) && now != was)
      out += (out.empty() ? "" : "; ") + std::string(flag) + " " + now + ", stored " + was;
  };
  note("--sport", asked.sport, stored.sport);
  note("--mode", asked.mode, stored.mode);
  note("--seed", std::to_string(asked.seed), std::to_string(stored.seed));
  note("--time-limit", std::to_string(asked.time_limit_s), std::to_string(stored.time_limit_s));
  note("--options", asked.sport_options, stored.sport_options);
  if (cmd.get_name() == "run") {
    note("--format", asked.format, stored.format);
    std::string stored_entrants;
    for (const auto& e : stored.entrants)
      stored_entrants += (stored_entrants.empty() ? "" : ",") + e.policy +
                         (e.policy == "zero" || e.policy == "random" || e.policy == "scripted"
                              ? ":" + std::to_string(e.seed)
                              : "");
    std::string given;
    for (const auto& e : parse_entrants(entrants, 0))
      given += (given.empty() ? "" : ",") + e.policy +
               (e.policy == "zero" || e.policy == "random" || e.policy == "scripted"
                    ? ":" + std::to_string(e.seed)
                    : "");
    note("--entrants", given, stored_entrants);
  } else {
    const auto asked_options = nlohmann::json::parse(asked.options);
    const auto stored_options = nlohmann::json::parse(stored.options);
    note("--strategy", asked_options.value("strategy", ""), stored_options.value("strategy", ""));
    note("--learner", asked_options.value("learner", ""), stored_options.value("learner", ""));
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"olympics-league: tournaments and ratings among policies over olympics-servers"};
  app.require_subcommand(1);
  std::string db = "olympics-league.db", name;
  TournamentSpec spec;
  RunnerSettings runner;
  std::vector<std::string> entrants;
  spec.format = "round-robin";
  auto* run = app.add_subcommand("run", "play (or resume) a tournament to its end");
  run->add_option("--db", db, "league state: SQLite file or postgresql:// URL");
  run->add_option("--name", name, "tournament name (resumes it if it exists)")->required();
  run->add_option("--format", spec.format, "round-robin, double-round-robin, swiss, knockout")
      ->check(CLI::IsMember({"round-robin", "double-round-robin", "swiss", "knockout"}));
  run->add_option("--entrants", entrants,
                  "zero, random[:seed], scripted[:seed], mlp:<snapshot>, live:<learner>; comma "
                  "separated")
      ->delimiter(',');
  run->add_option("--sport", spec.sport, "sport");
  run->add_option("--mode", spec.mode,
                  "two-team mode (1v1, 2v2, ...), or competition_N: N entrants ranked in each "
                  "match (athletics; docs/league.md)");
  run->add_option("--seed", spec.seed, "tournament seed (match seeds derive from it)");
  run->add_option("--time-limit", spec.time_limit_s, "seconds per match (0: the sport's default)");
  run->add_option("--options", spec.sport_options,
                  "the sport's settings for every match, JSON (olympics-server describe SPORT)");
  run->add_option("--servers", runner.servers, "server ids to use (default: any)")->delimiter(',');
  run->add_option("--parallel", runner.parallel, "games at once")->check(CLI::PositiveNumber);
  run->add_option("--server-wait-s", runner.server_wait_s,
                  "stop when no usable server has announced itself this long")
      ->check(CLI::PositiveNumber);
  run->add_option("--lcm-url", runner.lcm_url, "LCM provider URL");
  run->add_option("--secret", runner.secret_file,
                  "the deployment's secret file (default $OLYMPICS_SECRET_FILE; docs/security.md)");
  run->add_option("--log-dir", runner.log_dir, "policy workers' logs");
  bool quiet = false, resume_as_stored = false, fleet = false;
  run->add_flag("--quiet", quiet, "no progress bar");
  run->add_flag("--fleet", fleet,
                "queue the games in --db (PostgreSQL) for cells to play (olympics-league cell), "
                "instead of playing them from here");
  run->add_flag("--resume-as-stored", resume_as_stored,
                "resume a tournament of this name as stored even if flags given differ");

  SelfplayOptions selfplay;
  std::vector<std::string> bots;
  auto* sp =
      app.add_subcommand("selfplay", "the learner's snapshots against opponents by a strategy");
  sp->add_option("--db", db, "league state: SQLite file or postgresql:// URL");
  sp->add_option("--name", name, "run name (resumes it if it exists)")->required();
  sp->add_option("--snapshots", selfplay.snapshots_dir,
                 "where the learner writes *v<N>.safetensors")
      ->required();
  sp->add_option("--window", selfplay.window, "past snapshots kept as opponents");
  sp->add_option("--strategy", selfplay.strategy,
                 "latest, alternating:E, mlagents:R, pfsp[:weighting]");
  sp->add_option("--bot-share", selfplay.bot_share, "share of games against a bot");
  sp->add_option("--bots", bots, "bots: zero, random[:seed], scripted[:seed]")->delimiter(',');
  sp->add_option("--matches", selfplay.matches, "games to play")->check(CLI::PositiveNumber);
  sp->add_option("--learner", selfplay.learner,
                 "a live learner plays the learning side (the trainer's client: python3 -m "
                 "smpl_olympics.train --league NAME); its snapshots and the bots are its "
                 "opponents");
  for (auto* cmd : {sp}) {
    cmd->add_option("--sport", spec.sport, "sport");
    cmd->add_option("--mode", spec.mode, "two-team mode: 1v1, 2v2, ...");
    cmd->add_option("--seed", spec.seed, "seed (match seeds and decisions derive from it)");
    cmd->add_option("--time-limit", spec.time_limit_s,
                    "seconds per match (0: the sport's default)");
    cmd->add_option("--options", spec.sport_options,
                    "the sport's settings for every match, JSON (olympics-server describe SPORT)");
    cmd->add_option("--servers", runner.servers, "server ids to use (default: any)")
        ->delimiter(',');
    cmd->add_option("--parallel", runner.parallel, "games at once")->check(CLI::PositiveNumber);
    cmd->add_option("--server-wait-s", runner.server_wait_s,
                    "stop when no usable server has announced itself this long")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--lcm-url", runner.lcm_url, "LCM provider URL");
    cmd->add_option("--secret", runner.secret_file,
                    "the deployment's secret file (default $OLYMPICS_SECRET_FILE)");
    cmd->add_option("--log-dir", runner.log_dir, "policy workers' logs");
    cmd->add_flag("--quiet", quiet, "no progress bar");
    cmd->add_flag("--resume-as-stored", resume_as_stored,
                  "resume a run of this name as stored even if flags given differ");
  }
  sp->add_flag("--fleet", fleet,
               "schedule the run's games in --db (PostgreSQL) for cells to play (olympics-league "
               "cell); this process stays as the run's scheduler until its last game is stored "
               "(docs/deploy.md)");

  CellSettings cell;
  auto* cell_cmd = app.add_subcommand(
      "cell",
      "play the queued tournaments and self-play runs of a fleet on this cell's server "
      "(docs/deploy.md)");
  add_cell_options(*cell_cmd, cell);

  std::string svg;
  bool json = false;
  auto* table = app.add_subcommand("table", "print a tournament's table (and plot its ratings)");
  table->add_option("--db", db, "league database");
  table->add_option("--name", name, "tournament name")->required();
  table->add_option("--svg", svg, "write the ratings over time to this SVG file");
  table->add_flag("--json", json, "JSON instead of a table");
  bool payoff = false;
  table->add_flag("--payoff", payoff, "also print the payoff matrix");
  auto* list = app.add_subcommand("list", "list the tournaments");
  list->add_option("--db", db, "league database");
  CLI11_PARSE(app, argc, argv);

  try {
    if (*cell_cmd) return run_cell(cell);
    if (fleet && db.rfind("postgresql://", 0) != 0 && db.rfind("postgres://", 0) != 0)
      throw std::invalid_argument("--fleet queues games for cells in PostgreSQL; --db " + db +
                                  " is not a postgresql:// URL (one machine needs no fleet)");
    LeagueStore store(db);
    if (*list) {
      for (const auto& n : store.tournament_names()) {
        auto games = store.games(n);
        int done = 0;
        for (const auto& g : games) done += g.status == GameStatus::Done;
        auto t = store.find_tournament(n);
        std::printf("%-20s %-18s %-8s %d/%zu games\n", n.c_str(), t->format.c_str(),
                    t->sport.c_str(), done, games.size());
      }
      return 0;
    }
    if (*run || *sp) {
      spec.name = name;
      if (*sp) {
        spec.format = "selfplay";
        selfplay.lag = runner.parallel;
        spec.options = selfplay.to_json().dump();
      }
      const auto options = nlohmann::json::parse(spec.sport_options, nullptr, false);
      if (!options.is_object())
        throw std::invalid_argument(
            "--options must be a JSON object such as '{\"touches\": 5}', got " +
            spec.sport_options);
      spec.sport_options = options.dump();
      if (auto existing = store.find_tournament(name)) {
        // A resumed run plays as it was stored; settings asked for now that differ are refused
        // unless told to go on as stored.
        const std::string differs = differences(*existing, spec, *run ? *run : *sp, entrants);
        if (!differs.empty() && !resume_as_stored)
          throw std::invalid_argument(
              "\"" + name + "\" exists in " + db + " with other settings (" + differs +
              "); it resumes as stored: drop those flags, pass --resume-as-stored, or choose "
              "another --name");
        std::fprintf(stderr, "resuming %s\n", name.c_str());
        spec = *existing;
      } else {
        if (*sp && !selfplay.learner.empty()) bots.insert(bots.begin(), "live:" + selfplay.learner);
        spec.entrants = *sp ? (bots.empty() ? std::vector<Entrant>{} : parse_entrants(bots, 1))
                            : parse_entrants(entrants, 2);
        if (*sp && ranked_seats(spec.mode) > 2)
          throw std::invalid_argument(
              "self-play pairs the learner with one opponent; --mode " + spec.mode +
              " seats more: rank competitions with olympics-league run --format round-robin");
        if (*run)
          check_ranked_tournament(spec.mode, spec.format, static_cast<int>(spec.entrants.size()));
        store.create_tournament(spec);
      }
      if (fleet && spec.format == "selfplay") {
        if (!SelfplayOptions::from_json(spec.options).learner.empty())
          throw std::invalid_argument(
              "a live learner (--learner) plays on its own host's LCM, which a fleet's cells do "
              "not share; run its self-play on that host without --fleet, or let the fleet play "
              "its snapshots (--snapshots) without --learner");
        SelfplayFleetSettings driver;
        driver.db_url = db;
        driver.fingerprint = secret_fingerprint(runner.secret_file);
        driver.quiet = quiet;
        drive_selfplay_fleet(spec, driver);
        spec = *store.find_tournament(name);
      } else if (fleet) {
        FixtureQueue queue(db, "queue");
        upload_snapshots(queue, spec);  // cells play mlp:FILE entrants from the database
        const auto verdict =
            queue_next_round(store, queue, name, secret_fingerprint(runner.secret_file));
        std::printf(
            "%s: %d games queued in %s%s; cells play them: olympics-league cell --db URL "
            "--name %s\n",
            name.c_str(), queue.unfinished(name), db.c_str(),
            verdict == RoundVerdict::Finished ? " (finished)" : "", name.c_str());
        return 0;
      } else {
        runner.agent_program = olympics::program_beside_this_one("olympics-agent");
        runner.progress = !quiet;
        std::unique_ptr<Scheduler> scheduler;
        if (spec.format == "selfplay") {
          auto options = SelfplayOptions::from_json(spec.options);
          runner.parallel = options.lag;  // decisions depend on it: keep the run's own
          scheduler = std::make_unique<SelfplayScheduler>(options);
        } else {
          scheduler = make_tournament_scheduler();
        }
        TournamentRunner(store, spec, runner, std::move(scheduler)).run();
        spec = *store.find_tournament(name);
      }
    }
    auto t = store.find_tournament(name);
    if (!t) throw std::invalid_argument("no tournament \"" + name + "\" in " + db);
    Leaderboard board = compute_leaderboard(*t, store.games(name));
    if (json) {
      nlohmann::json rows = nlohmann::json::array();
      for (const auto& r : board.rows)
        rows.push_back({{"entrant", r.name},
                        {"points", r.standing.points},
                        {"wins", r.standing.wins},
                        {"draws", r.standing.draws},
                        {"losses", r.standing.losses},
                        {"byes", r.standing.byes},
                        {"mu", r.skill.mu},
                        {"sigma", r.skill.sigma},
                        {"elo", r.elo}});
      std::printf("%s\n", rows.dump(2).c_str());
    } else {
      std::printf("%s", format_table(board).c_str());
      if (payoff) std::printf("\n%s", format_payoff(*t, board).c_str());
    }
    if (!svg.empty()) std::ofstream(svg) << ratings_svg(*t, board);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "olympics-league: %s\n", e.what());
    return 2;
  }
}
