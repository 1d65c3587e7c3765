"""Gymnasium's own env checker (the pinned gymnasium of clients/python/test-requirements.txt)
against the single-agent env of every one-slot mode, made by gymnasium.make from its registered
id and playing real matches on a real olympics-server. A warning from the checker fails the test
too, except its advice that infinite observation bounds are "probably too high" (the task
blocks are unclamped by design: docs/clients.md)."""
import os
import tempfile
import unittest
import warnings

import numpy as np

try:
    import gymnasium
    from gymnasium.utils.env_checker import check_env
except ImportError as missing:
    raise ImportError("the Python tests need the pinned pettingzoo and gymnasium: run "
                      "bash deploy/install-python-test-deps.sh") from missing

import smpl_olympics  # noqa: F401  (registers the ids)
from smpl_olympics.gym_env import OlympicsGymEnv, env_id, one_slot_modes

from server_process import start_server


class GymnasiumConformance(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="olympics-gym-")
        cls.url = f"udpm://239.255.76.67:{31000 + os.getpid() % 9000}?ttl=0&recv_buf_size=4194304"
        # The checker resets without playing the matches it started: room for those.
        cls.server = start_server(cls.url, os.path.join(cls.dir, "results.db"), "gym",
                                  os.path.join(cls.dir, "server.log"), "--capacity", "1000")

    @classmethod
    def tearDownClass(cls):
        cls.server.kill()
        cls.server.wait()

    def test_the_one_slot_modes_are_registered(self):
        ids = {env_id(s, m) for s, m in one_slot_modes()}
        for expected in ("smpl_olympics/TableTennisBallReturn-v0",
                         "smpl_olympics/TennisBallReturn-v0", "smpl_olympics/SoccerPenaltyKick-v0",
                         "smpl_olympics/BasketballFreeThrow-v0"):
            self.assertIn(expected, ids)
            self.assertIn(expected, gymnasium.registry)

    def test_check_env_passes_for_every_one_slot_mode(self):
        for sport, mode in one_slot_modes():
            with self.subTest(sport=sport, mode=mode), warnings.catch_warnings(record=True) as w:
                warnings.simplefilter("always")
                env = gymnasium.make(env_id(sport, mode), lcm_url=self.url, time_limit_s=1.0)
                self.assertIsInstance(env.unwrapped, OlympicsGymEnv)
                # The unwrapped env, as check_env asks; it carries the spec, so the checker also
                # asserts that reset(seed=123) twice gives the same observation.
                self.assertIsNotNone(env.unwrapped.spec)
                check_env(env.unwrapped)
                complaints = [str(x.message) for x in w
                              if not ("space" in str(x.message) and "infinity" in str(x.message))]
                self.assertEqual(complaints, [], "gymnasium's checker warned")
                env.close()

    def test_an_episode_ends_and_a_seed_replays_it(self):
        env = gymnasium.make("smpl_olympics/TableTennisBallReturn-v0", lcm_url=self.url,
                             time_limit_s=1.0)
        episodes = []
        for seed in (7, 7):
            observation, info = env.reset(seed=seed)
            rewards, over, steps = [], False, 0
            while not over:
                observation, reward, terminated, truncated, info = env.step(
                    np.tanh(observation[:env.action_space.shape[0]]))
                self.assertIn(observation, env.observation_space)
                rewards.append(reward)
                over, steps = terminated or truncated, steps + 1
            self.assertLess(steps, 100, "a 1 s match at 30 Hz")
            self.assertIsNotNone(env.unwrapped.result)
            episodes.append((steps, rewards, observation.tobytes()))
        self.assertEqual(episodes[0], episodes[1], "the same seed and actions played otherwise")

    def test_a_mode_with_more_slots_is_refused_naming_the_one_slot_modes(self):
        with self.assertRaises(ValueError) as caught:
            OlympicsGymEnv(sport="tennis", mode="1v1", lcm_url=self.url)
        self.assertIn("table_tennis/ball_return", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
