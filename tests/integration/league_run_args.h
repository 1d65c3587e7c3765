// The command line of one `olympics-league run` tournament against a test's server, for the
// integration tests that play ranked heats (competition_N) through the league.
#pragma once

#include <string>
#include <vector>

#include "test_programs.h"

namespace olympics::testing {

struct LeagueRun {
  std::string db, name, sport, mode, options;
  std::string format;  // empty: the league's default
  std::string entrants;
  int seed = 0;
  std::vector<std::string> more = {};  // further options, e.g. {"--parallel", "1"}
};

// `olympics-league run` for `run`, talking to the server at `lcm_url`, its workers' logs in
// `log_dir`, quiet.
inline std::vector<std::string> league_run_args(const LeagueRun& run, const std::string& lcm_url,
                                                const std::string& log_dir) {
  std::vector<std::string> argv = {program("olympics-league"),
                                   "run",
                                   "--db",
                                   run.db,
                                   "--name",
                                   run.name,
                                   "--sport",
                                   run.sport,
                                   "--mode",
                                   run.mode,
                                   "--options",
                                   run.options};
  if (!run.format.empty()) argv.insert(argv.end(), {"--format", run.format});
  argv.insert(argv.end(), {"--entrants", run.entrants, "--seed", std::to_string(run.seed)});
  argv.insert(argv.end(), run.more.begin(), run.more.end());
  argv.insert(argv.end(), {"--lcm-url", lcm_url, "--log-dir", log_dir, "--quiet"});
  return argv;
}

}  // namespace olympics::testing
