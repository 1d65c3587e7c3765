#include "cell_command.h"

#include <unistd.h>

#include "process.h"

namespace olympics::selfplay {

void add_cell_options(CLI::App& cmd, CellSettings& s) {
  cmd.add_option("--db", s.db_url, "the fleet's database: postgresql:// URL")->required();
  cmd.add_option("--name", s.tournament,
                 "play this tournament and exit when it is done (default: every queued one)");
  cmd.add_option("--cell", s.cell, "this cell's name, unique in the fleet (default: host name)");
  cmd.add_option("--batch", s.batch, "fixtures leased at once")->check(CLI::PositiveNumber);
  cmd.add_option("--lease-s", s.lease_s,
                 "a lease not renewed this long returns its fixtures to the queue")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--parallel", s.runner.parallel, "games at once in this cell")
      ->check(CLI::PositiveNumber);
  cmd.add_flag("--keep-waiting", s.keep_waiting,
               "stay for tournaments queued later when there is no work (a Deployment)");
  cmd.add_flag("--spawn-server", s.spawn_server,
               "start this cell's olympics-server (id: the cell's name) beside this process");
  cmd.add_option("--server-capacity", s.server_capacity,
                 "matches the spawned server hosts at once (default --parallel; more leaves room "
                 "for a remote learner's matches)")
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--health-file", s.health_file,
                 "touched every second while the cell runs (a liveness exec probe)");
  cmd.add_option("--snapshot-cache", s.snapshot_cache,
                 "where the cell keeps its copies of the snapshots it plays, taken from the "
                 "database (default: LOG_DIR/fleet-snapshots-CELL)");
  cmd.add_option("--lcm-url", s.runner.lcm_url,
                 "LCM provider URL inside the cell (the default keeps multicast on the host)");
  cmd.add_option("--secret", s.runner.secret_file,
                 "the deployment's secret file (default $OLYMPICS_SECRET_FILE; docs/security.md)");
  cmd.add_option("--log-dir", s.runner.log_dir, "policy workers' and the server's logs");
  cmd.add_option("--server-wait-s", s.runner.server_wait_s,
                 "stop when the cell's server has not announced itself this long")
      ->check(CLI::PositiveNumber);
  cmd.parse_complete_callback([&s] {
    if (s.cell.empty()) {
      char host[256] = {};
      gethostname(host, sizeof host - 1);
      s.cell = host;
    }
    if (s.spawn_server) s.server_program = program_beside_this_one("olympics-server");
    s.runner.agent_program = program_beside_this_one("olympics-agent");
  });
}

}  // namespace olympics::selfplay
