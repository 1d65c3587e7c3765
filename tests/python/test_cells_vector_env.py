"""CellsVectorEnv against real olympics-servers, one per cell (each on its own LCM URL, as each
cell's relay gives it on a learner's host): a cell whose server is killed has its environments
moved to the cell left and its matches reported lost; with no cell left, a clear error."""
import os
import signal
import tempfile
import time
import unittest

import numpy as np

from smpl_olympics._client import MatchError
from smpl_olympics.cells_vector_env import CellsVectorEnv
from smpl_olympics.private_server import private_url

from server_process import start_server


class CellsVectorEnvTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="olympics-cells-")
        self.servers = {}

    def tearDown(self):
        for s in self.servers.values():
            if s.poll() is None:
                s.kill()
            s.wait()

    def cell(self, name, capacity):
        url = private_url()
        self.servers[name] = start_server(url, os.path.join(self.dir, f"{name}.db"), name,
                                          os.path.join(self.dir, f"{name}.log"),
                                          "--capacity", str(capacity))
        return url

    def env(self, urls):
        # Tennis: a match lasts its time limit, so every step is a step of the same match.
        return CellsVectorEnv(urls, 2, seed=3, sport="tennis", mode="1v1", time_limit_s=600,
                              timeout_s=30)

    def step_until_lost(self, env, actions, limit_s=60):
        give_up = time.monotonic() + limit_s
        while time.monotonic() < give_up:
            stepped = env.step(actions)
            if stepped[-1]["lost"]:
                return stepped
        self.fail("no loss reported")

    def test_a_lost_cell_moves_its_environments_to_the_cell_left_and_reports_its_matches(self):
        a, b = self.cell("cell_a", 4), self.cell("cell_b", 2)
        env = self.env([a, b])
        obs, info = env.reset()
        self.assertEqual(obs.shape, env.observation_space.shape)
        self.assertEqual(env.action_space.shape, (4, env.num_agents, env.action_size))
        b_matches = info["match_ids"][2:]
        self.assertTrue(all(m.startswith("cell_b") for m in b_matches), info["match_ids"])
        actions = np.zeros((4, env.num_agents, env.action_size), np.float32)
        for _ in range(20):
            env.step(actions)
        self.servers["cell_b"].send_signal(signal.SIGKILL)
        obs, reward, _, truncated, infos = self.step_until_lost(env, actions)
        lost = infos["lost"]
        self.assertEqual([m["env"] for m in lost], [2, 3])
        self.assertEqual([m["match_id"] for m in lost], b_matches)
        self.assertTrue(all(m["cell"] == b and m["error"].startswith("SERVER_GONE") for m in lost),
                        lost)
        self.assertEqual(infos["episode_over"].tolist(), [False, False, True, True])
        self.assertTrue(truncated[2:].all() and not truncated[:2].any(), truncated)
        self.assertTrue(obs[2:].any(), "the moved environments' first observations")
        self.assertEqual(env.env_cells(), [a] * 4)
        self.assertEqual(env.lost_matches(), lost)
        ticks_before = None
        for _ in range(20):
            infos = env.step(actions)[-1]
            self.assertEqual(infos["lost"], [])
            ticks_before = ticks_before if ticks_before is not None else infos["tick"].copy()
        self.assertTrue((infos["tick"] > ticks_before).all(), infos["tick"])
        env.close()

    def test_losing_the_last_cell_raises_naming_it(self):
        a = self.cell("cell_a", 2)
        env = self.env([a])
        env.reset()
        actions = np.zeros((2, env.num_agents, env.action_size), np.float32)
        env.step(actions)
        self.servers["cell_a"].send_signal(signal.SIGKILL)
        with self.assertRaises(MatchError) as caught:
            for _ in range(100000):
                env.step(actions)
        self.assertIn("every cell of this env is lost or full", str(caught.exception))
        self.assertIn(a, str(caught.exception))

    def test_a_lost_cell_whose_environments_find_no_room_raises_saying_so(self):
        a, b = self.cell("cell_a", 2), self.cell("cell_b", 2)
        env = self.env([a, b])
        env.reset()
        actions = np.zeros((4, env.num_agents, env.action_size), np.float32)
        env.step(actions)
        self.servers["cell_b"].send_signal(signal.SIGKILL)
        with self.assertRaises(MatchError) as caught:
            for _ in range(100000):
                env.step(actions)
        self.assertIn("no room for the lost environments on " + a, str(caught.exception))

    def test_bad_counts_are_refused_saying_what_is_wanted(self):
        with self.assertRaisesRegex(ValueError, "one count >= 1 per cell"):
            CellsVectorEnv(["udpm://239.255.76.67:7701?ttl=0"], [1, 2])


if __name__ == "__main__":
    unittest.main()
