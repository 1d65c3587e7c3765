"""PettingZoo's own conformance tests (the pinned pettingzoo of clients/python/test-requirements.txt,
installed by deploy/install-python-test-deps.sh) against real matches on a real olympics-server,
for every sport and mode of the catalog: parallel_api_test, parallel_seed_test, and api_test on
the env turned into an AEC env by parallel_to_aec. A warning from PettingZoo's checks fails the
test too (they warn, for instance, when a live agent is not given a reward)."""
import os
import tempfile
import unittest
import warnings

from smpl_olympics import OlympicsParallelEnv, catalog

from server_process import start_server

try:
    from pettingzoo import ParallelEnv
    from pettingzoo.test import api_test, parallel_api_test, parallel_seed_test
    from pettingzoo.utils.conversions import parallel_to_aec
except ImportError as missing:
    raise ImportError("the Python tests need the pinned pettingzoo and gymnasium: run "
                      "bash deploy/install-python-test-deps.sh") from missing

# Matches this short end within the cycles played, so the tests see agents finish.
TIME_LIMIT_S = 1.0
CYCLES = 400


def every_mode():
    return [(s, m["name"]) for s in sorted(catalog.catalog()) for m in catalog.sport(s)["modes"]]


class PettingZooConformance(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="olympics-pz-")
        cls.url = f"udpm://239.255.76.67:{25000 + os.getpid() % 9000}?ttl=0&recv_buf_size=4194304"
        # PettingZoo's tests reset without playing the match they started: room for those.
        cls.server = start_server(cls.url, os.path.join(cls.dir, "results.db"), "pz",
                                  os.path.join(cls.dir, "server.log"), "--capacity", "1000")

    @classmethod
    def tearDownClass(cls):
        cls.server.kill()
        cls.server.wait()

    def env(self, sport, mode):
        return OlympicsParallelEnv(sport=sport, mode=mode, lcm_url=self.url,
                                   time_limit_s=TIME_LIMIT_S)

    def assert_no_pettingzoo_warnings(self, caught, what):
        # api_test's one advisory the env answers by design: task blocks (ball position and
        # velocity, ...) are not clamped, so their bounds are infinite (catalog.observation_space).
        complaints = [str(w.message) for w in caught if "pettingzoo" in w.filename
                      and not ("observation space value is" in str(w.message)
                               and "infinity" in str(w.message))]
        self.assertEqual(complaints, [], f"PettingZoo's {what} warned")

    def test_the_catalog_has_every_sport(self):
        sports = {s for s, _ in every_mode()}
        self.assertGreaterEqual(len(sports), 6, sports)

    def test_is_a_pettingzoo_parallel_env(self):
        env = self.env("sandbox", "1v1")
        self.assertIsInstance(env, ParallelEnv)
        self.assertIs(env.unwrapped, env)

    def test_parallel_api_test_every_sport_and_mode(self):
        for sport, mode in every_mode():
            with self.subTest(sport=sport, mode=mode), warnings.catch_warnings(record=True) as w:
                warnings.simplefilter("always")
                env = self.env(sport, mode)
                parallel_api_test(env, num_cycles=CYCLES)
                self.assertFalse(env.agents, "the match did not end within the cycles played")
                self.assert_no_pettingzoo_warnings(w, "parallel_api_test")

    def test_parallel_seed_test_every_sport_and_mode(self):
        for sport, mode in every_mode():
            with self.subTest(sport=sport, mode=mode), warnings.catch_warnings(record=True) as w:
                warnings.simplefilter("always")
                parallel_seed_test(lambda: self.env(sport, mode), num_cycles=CYCLES)
                self.assert_no_pettingzoo_warnings(w, "parallel_seed_test")

    def test_api_test_through_parallel_to_aec_every_sport_and_mode(self):
        for sport, mode in every_mode():
            with self.subTest(sport=sport, mode=mode), warnings.catch_warnings(record=True) as w:
                warnings.simplefilter("always")
                api_test(parallel_to_aec(self.env(sport, mode)), num_cycles=CYCLES)
                self.assert_no_pettingzoo_warnings(w, "api_test")


if __name__ == "__main__":
    unittest.main()
