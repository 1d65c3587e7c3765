"""PettingZoo's own conformance tests (the pinned pettingzoo of clients/python/test-requirements.txt,
installed by deploy/install-python-test-deps.sh) against real matches on a real olympics-server,
for the catalog's sports: parallel_api_test on every mode, parallel_seed_test and api_test on the
env turned into an AEC env by parallel_to_aec on every kind of mode (a competition's smallest and
largest field). A warning from PettingZoo's checks fails the
test too (they warn, for instance, when a live agent is not given a reward)."""
import os
import re
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


def every_kind_of_mode():
    """Every mode but the middle sizes of a competition: competition_3 .. competition_7 run the
    same env code as competition_2 and competition_8 with another number of agents, and PettingZoo's
    seed and AEC checks of all 35 athletics competitions took a third of this test's time.
    parallel_api_test still plays every mode."""
    def middle_size(mode):
        size = re.fullmatch(r"competition_(\d+)", mode)
        return size is not None and 2 < int(size.group(1)) < 8
    return [(s, m) for s, m in every_mode() if not middle_size(m)]


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
        # The trimmed checks still see both ends of every competition.
        kinds = set(every_kind_of_mode())
        for sport, mode in every_mode():
            if mode.startswith("competition_"):
                self.assertIn((sport, "competition_2"), kinds)
                self.assertIn((sport, "competition_8"), kinds)

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

    def test_parallel_seed_test_every_kind_of_mode(self):
        for sport, mode in every_kind_of_mode():
            with self.subTest(sport=sport, mode=mode), warnings.catch_warnings(record=True) as w:
                warnings.simplefilter("always")
                parallel_seed_test(lambda: self.env(sport, mode), num_cycles=CYCLES)
                self.assert_no_pettingzoo_warnings(w, "parallel_seed_test")

    def test_api_test_through_parallel_to_aec_every_kind_of_mode(self):
        for sport, mode in every_kind_of_mode():
            with self.subTest(sport=sport, mode=mode), warnings.catch_warnings(record=True) as w:
                warnings.simplefilter("always")
                api_test(parallel_to_aec(self.env(sport, mode)), num_cycles=CYCLES)
                self.assert_no_pettingzoo_warnings(w, "api_test")


if __name__ == "__main__":
    unittest.main()
