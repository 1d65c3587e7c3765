"""`pip install ./clients/python` into a fresh virtual environment (no network: the build needs
only the system's LCM, OpenSSL and pybind11 headers), then a match played from that Python."""
import json
import os
import sqlite3
import subprocess
import sys
import tempfile
import textwrap
import unittest

from server_process import BIN, start_server

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

PLAY = textwrap.dedent("""
    import json, sys
    import numpy as np
    import olympics                       # the lcm-gen'd message types come with the package
    import smpl_olympics
    from smpl_olympics import OlympicsParallelEnv
    env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=sys.argv[1], time_limit_s=1.0)
    env.reset(seed=3)
    while env.agents:
        env.step({a: np.zeros(69, np.float32) for a in env.agents})
    print(json.dumps({"package": smpl_olympics.__file__, "types": olympics.match_result_t.__name__,
                      "match_id": env.result["match_id"], "ticks": env.result["ticks"]}))
""")


class PipInstall(unittest.TestCase):
    def test_installs_into_a_fresh_venv_and_plays_a_match(self):
        folder = tempfile.mkdtemp(prefix="olympics-venv-")
        venv = os.path.join(folder, "venv")
        # --system-site-packages for numpy only: PyPI is not reachable here.
        subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv], check=True)
        python = os.path.join(venv, "bin", "python")
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        env["OLYMPICS_SERVER"] = os.path.join(BIN, "olympics-server")
        install = subprocess.run([python, "-m", "pip", "install", "--no-build-isolation",
                                  "--no-deps", "--no-index", os.path.join(REPO, "clients", "python")],
                                 env=env, capture_output=True, text=True, cwd=folder)
        self.assertEqual(install.returncode, 0, install.stdout[-3000:] + install.stderr[-3000:])

        url = f"udpm://239.255.76.67:{25000 + os.getpid() % 9000}?ttl=0&recv_buf_size=4194304"
        db = os.path.join(folder, "results.db")
        server = start_server(url, db, "venv", os.path.join(folder, "server.log"))
        try:
            played = subprocess.run([python, "-c", PLAY, url], env=env, capture_output=True,
                                    text=True, cwd=folder, timeout=300)
        finally:
            server.kill()
            server.wait()
        self.assertEqual(played.returncode, 0, played.stderr[-3000:])
        out = json.loads(played.stdout.strip().splitlines()[-1])
        self.assertTrue(out["package"].startswith(venv), out["package"])
        self.assertEqual(out["types"], "match_result_t")
        self.assertGreater(out["ticks"], 0)
        stored = sqlite3.connect(db).execute("SELECT ticks FROM matches WHERE match_id = ?",
                                             (out["match_id"],)).fetchone()
        self.assertEqual(stored, (out["ticks"],))


if __name__ == "__main__":
    unittest.main()
