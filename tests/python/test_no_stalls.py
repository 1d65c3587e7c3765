"""Errors instead of stalls, against real olympics-server processes: a vector env asking for more
matches than the server admits raises at once with both numbers and the setting to change, and
an env with no server on its LCM URL raises within seconds, naming the URL and how to start one
(they used to wait: FULL answers retried in silence, 60 s of nothing)."""
import os
import signal
import tempfile
import time
import unittest

import numpy as np

from smpl_olympics import CapacityError, MatchError, NoServerError
from smpl_olympics import OlympicsParallelEnv, OlympicsVectorEnv

from server_process import start_server

CONNECT_S = 2.0


class NoStalls(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="olympics-stall-")
        port = 27000 + os.getpid() % 9000
        self.url = f"udpm://239.255.76.67:{port}?ttl=0&recv_buf_size=4194304"
        self.nobody = f"udpm://239.255.76.67:{port + 1}?ttl=0"  # no server listens here
        self.servers = []

    def tearDown(self):
        for s in self.servers:
            s.kill()
            s.wait()

    def serve(self, name, capacity):
        self.servers.append(start_server(self.url, os.path.join(self.dir, f"{name}.db"), name,
                                         os.path.join(self.dir, f"{name}.log"),
                                         "--capacity", str(capacity)))

    def assert_raises_soon(self, error, call):
        start = time.monotonic()
        with self.assertRaises(error) as caught:
            call()
        self.assertLess(time.monotonic() - start, CONNECT_S + 3.0, "it waited before raising")
        return str(caught.exception)

    def test_vector_env_over_the_capacity_raises_with_both_numbers_and_the_setting(self):
        self.serve("small", capacity=3)
        env = OlympicsVectorEnv(5, sport="sandbox", mode="1v1", seed=1, time_limit_s=1.0,
                                lcm_url=self.url, connect_timeout_s=CONNECT_S)
        message = self.assert_raises_soon(CapacityError, env.reset)
        for needed in ("5 matches", "admits 3", "--capacity 5", "'small'", "num_envs <= 3"):
            self.assertIn(needed, message)
        self.assertTrue(issubclass(CapacityError, MatchError))

    def test_vector_env_at_the_capacity_plays(self):
        self.serve("exact", capacity=3)
        env = OlympicsVectorEnv(3, sport="sandbox", mode="1v1", seed=1, time_limit_s=1.0,
                                lcm_url=self.url, connect_timeout_s=CONNECT_S)
        obs, _ = env.reset()
        self.assertEqual(obs.shape[0], 3)
        obs, *_ = env.step(np.zeros((3, 2, env.action_size), np.float32))
        self.assertEqual(obs.shape[0], 3)
        env.close()

    def test_a_vector_env_whose_server_stops_answering_says_to_check_the_server(self):
        self.serve("paused", capacity=2)
        env = OlympicsVectorEnv(1, sport="sandbox", mode="1v1", seed=1, lcm_url=self.url,
                                timeout_s=2.0, connect_timeout_s=CONNECT_S)
        env.reset()
        self.servers[0].send_signal(signal.SIGSTOP)  # alive, but silent
        try:
            with self.assertRaises(MatchError) as caught:
                for _ in range(1000):
                    env.step(np.zeros((1, 2, env.action_size), np.float32))
        finally:
            self.servers[0].send_signal(signal.SIGCONT)
        message = str(caught.exception)
        self.assertTrue(message.startswith("TIMEOUT:"), message)
        self.assertIn(f"olympics-server on {self.url}", message)
        self.assertIn("olympics-server serve --lcm-url", message)

    def test_vector_env_without_a_server_names_the_url_and_how_to_start_one(self):
        env = OlympicsVectorEnv(2, sport="sandbox", mode="1v1", lcm_url=self.nobody,
                                connect_timeout_s=CONNECT_S)
        message = self.assert_raises_soon(NoServerError, env.reset)
        self.assertIn(self.nobody, message)
        self.assertIn("olympics-server serve --lcm-url", message)

    def test_parallel_env_without_a_server_names_the_url_and_how_to_start_one(self):
        env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=self.nobody,
                                  connect_timeout_s=CONNECT_S)
        message = self.assert_raises_soon(NoServerError, lambda: env.reset(seed=1))
        self.assertIn(self.nobody, message)
        self.assertIn("olympics-server serve --lcm-url", message)

    def test_parallel_env_asking_for_another_server_id_says_which_it_heard(self):
        self.serve("here", capacity=4)
        env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=self.url,
                                  server_id="elsewhere", connect_timeout_s=CONNECT_S)
        message = self.assert_raises_soon(NoServerError, lambda: env.reset(seed=1))
        self.assertIn("'elsewhere'", message)
        self.assertIn("heard only: here", message)

    def test_parallel_env_with_a_server_plays(self):
        self.serve("one", capacity=4)
        env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=self.url,
                                  time_limit_s=0.5, connect_timeout_s=CONNECT_S)
        env.reset(seed=2)
        while env.agents:
            env.step({a: np.zeros(env.action_size(), np.float32) for a in env.agents})
        self.assertEqual(env.result["seed"], 2)


if __name__ == "__main__":
    unittest.main()
