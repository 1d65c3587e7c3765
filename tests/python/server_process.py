"""An olympics-server process for one test: its own port, results and log.

It is patient with slow clients (a loaded CI machine can stall one for seconds), so that no
result depends on timing, and it is started once its first line is written: tests wait for
conditions, not for clocks."""
import os
import subprocess
import time

BIN = os.environ["OLYMPICS_BIN_DIR"]
PATIENT = ["--action-deadline-ms", "600000", "--max-missed-ticks", "1000",
           "--silent-timeout-s", "3600"]
DEADLINE_FLAGS = ("--action-deadline-ms", "--max-missed-ticks", "--silent-timeout-s")


def start_server(url, results, server_id, log_path, *extra):
    """Patient unless `extra` sets the deadlines itself (a test of forfeits)."""
    patient = [] if any(flag in extra for flag in DEADLINE_FLAGS) else PATIENT
    with open(log_path, "w") as log:
        server = subprocess.Popen([f"{BIN}/olympics-server", "serve", "--lcm-url", url,
                                   "--results", results, "--id", server_id, *patient, *extra],
                                  stdout=log, stderr=subprocess.STDOUT)
    give_up = time.monotonic() + 60
    while time.monotonic() < give_up:
        with open(log_path) as log:
            if "olympics-server" in log.read():
                return server
        if server.poll() is not None:
            break
        time.sleep(0.02)
    server.kill()
    with open(log_path) as log:
        raise RuntimeError(f"olympics-server did not start:\n{log.read()}")
