"""OlympicsVectorEnv against a real olympics-server: many matches from one process, the same
results as one match per run, auto-reset, async send/recv, loss, and a vanished opponent."""
import os
import signal
import subprocess
import tempfile
import unittest

import numpy as np

from smpl_olympics import OlympicsParallelEnv, OlympicsVectorEnv

from server_process import BIN, start_server


def policy(obs):
    """Deterministic and observation-driven, so any difference in what a match saw shows."""
    return np.tanh(0.5 * obs[..., :69]).astype(np.float32)


def outcome(result):
    return (result["ticks"], result["reason"], result["winner_team"], tuple(result["scores"]))


class VectorEnv(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="olympics-vec-")
        self.port = 24000 + os.getpid() % 9000
        self.url = f"udpm://239.255.76.67:{self.port}?ttl=0&recv_buf_size=8388608"
        self.servers = []

    def tearDown(self):
        for s in self.servers:
            s.kill()
            s.wait()

    def serve(self, url, name, *flags):
        # Room for the matches a closed vector env leaves behind (each environment's next match
        # starts as soon as its last one ends, and waits out the server's silence timeout).
        self.servers.append(start_server(url, os.path.join(self.dir, f"{name}.db"), name,
                                         os.path.join(self.dir, f"{name}.log"),
                                         "--capacity", "1000", *flags))

    def play_vector(self, url, n, seed, drop_rate=0.0):
        """One episode per environment, stepped in sync; returns (results, final obs) by seed."""
        env = OlympicsVectorEnv(n, sport="sandbox", mode="1v1", seed=seed, time_limit_s=1.0,
                                lcm_url=url, drop_rate=drop_rate)
        obs, _ = env.reset()
        self.assertEqual(obs.shape, (n, 2, env.obs_size))
        self.assertEqual(obs.dtype, np.float32)
        finals, done = {}, np.zeros(n, bool)
        while not done.all():
            obs, rewards, terminations, truncations, infos = env.step(policy(obs))
            self.assertEqual(rewards.shape, (n, 2))
            self.assertEqual(infos["reward_terms"].shape, (n, 2, len(env.term_names)))
            for e in np.flatnonzero(infos["episode_over"] & ~done):
                finals[seed + e] = infos["final_observation"][e].copy()
                self.assertTrue((terminations[e] | truncations[e]).all())
            done |= infos["episode_over"]
        results = {}
        while len(results) < n:  # episode 1 of an environment may end too, later
            for r in env.results():
                if seed <= r["seed"] < seed + n:
                    results[r["seed"]] = outcome(r)
        env.close()
        return results, finals

    def play_single(self, url, seed):
        env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=url, time_limit_s=1.0)
        observations, _ = env.reset(seed=seed)
        last = None
        while env.agents:
            obs = np.stack([observations[a] for a in env.possible_agents])
            last = obs
            observations, *_ = env.step({a: policy(obs)[i] for i, a in enumerate(env.possible_agents)
                                         if a in env.agents})
            if observations:
                last = np.stack([observations[a] for a in env.possible_agents if a in observations])
        return outcome(env.result), last

    def test_64_matches_from_one_process_match_64_single_runs_with_and_without_loss(self):
        self.serve(self.url, "vec")
        vector, finals = self.play_vector(self.url, 64, seed=1000)
        self.assertEqual(sorted(vector), list(range(1000, 1064)))
        for seed in (1000, 1001, 1031, 1063):  # single-match runs of some of the same seeds
            single, last = self.play_single(self.url, seed)
            self.assertEqual(vector[seed], single, f"seed {seed}")
            np.testing.assert_array_equal(finals[seed], last)
        lossy_url = self.url.replace(str(self.port), str(self.port + 1))
        self.serve(lossy_url, "lossy", "--drop-rate", "0.1")
        lossy, lossy_finals = self.play_vector(lossy_url, 16, seed=1000, drop_rate=0.1)
        for seed in range(1000, 1016):
            self.assertEqual(lossy[seed], vector[seed], f"seed {seed} with 10% loss")
            np.testing.assert_array_equal(lossy_finals[seed], finals[seed])

    def test_finished_matches_reset_to_the_next_seed_and_spaces_hold(self):
        self.serve(self.url, "vec")
        env = OlympicsVectorEnv(4, sport="tennis", mode="ball_return", seed=7, time_limit_s=0.5,
                                lcm_url=self.url)
        self.assertEqual(env.observation_space.shape, (4, 1, 384))
        obs, infos = env.reset()
        first_ids = infos["match_ids"]
        seen_over = np.zeros(4, int)
        for _ in range(40):  # 15 ticks a match: every environment ends at least twice
            self.assertTrue(env.single_observation_space.contains(obs[0, 0]))
            obs, rewards, terminations, truncations, infos = env.step(
                np.zeros((4, 1, 69), np.float32))
            seen_over += infos["episode_over"]
        self.assertTrue((seen_over >= 2).all(), seen_over)
        seeds = sorted(r["seed"] for r in env.results())
        self.assertTrue({7, 8, 9, 10, 11, 12, 13, 14} <= set(seeds), seeds)
        self.assertEqual(len(set(first_ids)), 4)

    def test_a_vanished_opponent_forfeits_its_match_and_stalls_no_other(self):
        self.serve(self.url, "vec", "--action-deadline-ms", "1000", "--max-missed-ticks", "3",
                   "--silent-timeout-s", "3")
        n = 4
        opponents = [subprocess.Popen(
            [f"{BIN}/olympics-agent", "--lcm-url", self.url, "--request-id", f"ring-{e}-0",
             "--sport", "sandbox", "--mode", "1v1", "--time-limit", "4", "--slots", "1",
             "--policy", "zero", "--name", f"opponent{e}"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) for e in range(n)]
        try:
            env = OlympicsVectorEnv(n, sport="sandbox", mode="1v1", slots=[0], seed=0,
                                    time_limit_s=4.0, request_prefix="ring", lcm_url=self.url,
                                    timeout_s=600)
            self.assertEqual(env.num_agents, 1)
            obs, _ = env.reset()
            # Async: whichever matches are ready are stepped; the one whose opponent is killed
            # stops being ready for a while and the others go on meanwhile.
            pending, ticks, results = list(range(n)), np.zeros(n, int), {}
            env.send(np.zeros((n, 1, 69), np.float32), pending)
            killed = False
            while len(results) < n:
                ids, obs, rewards, terminations, truncations, infos = env.recv(1, timeout_s=0.5)
                for i, e in enumerate(ids):
                    if not infos["episode_over"][i]:
                        ticks[e] = infos["tick"][i]
                if not killed and ticks.min() >= 10:
                    opponents[2].send_signal(signal.SIGKILL)
                    killed = True
                # Episode 0's matches only: a finished environment has no opponent for its next.
                live = [int(e) for i, e in enumerate(ids) if not infos["episode_over"][i]]
                if live:
                    env.send(np.zeros((len(live), 1, 69), np.float32), live)
                for r in env.results():
                    results[r["match_id"]] = r
            by_name = {r["agent_names"][1]: r for r in results.values()}
            self.assertIn("forfeit", by_name["opponent2"]["reason"])
            self.assertEqual(by_name["opponent2"]["winner_team"], 0)
            for e in (0, 1, 3):  # played on while match 2 waited for its silent opponent
                other = by_name[f"opponent{e}"]
                self.assertNotIn("forfeit", other["reason"])
                self.assertGreater(other["ticks"], by_name["opponent2"]["ticks"], other)
        finally:
            for p in opponents:
                p.kill()
                p.wait()

    def test_a_vector_learner_plays_the_leagues_games_at_once(self):
        self.serve(self.url, "vec")
        league = subprocess.Popen(
            [f"{BIN}/olympics-league", "run", "--db", os.path.join(self.dir, "league.db"),
             "--name", "vec", "--entrants", "live:vec,zero,random:1,random:2", "--parallel", "3",
             "--time-limit", "2", "--lcm-url", self.url, "--log-dir", self.dir, "--quiet"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            env = OlympicsVectorEnv(3, sport="sandbox", mode="1v1", learner="vec",
                                    lcm_url=self.url, agent_name="vec", timeout_s=600)
            self.assertEqual(env.agents, ["agent_0"])
            # Every environment starts when the league assigns it a game: async, with a timeout.
            env.start()
            results = {}
            while league.poll() is None or len(results) < 3:
                ids, obs, rewards, terminations, truncations, infos = env.recv(1, timeout_s=0.5)
                live = [int(e) for i, e in enumerate(ids) if not infos["episode_over"][i]]
                over = [int(e) for i, e in enumerate(ids) if infos["episode_over"][i]]
                # An environment whose match ended already holds its next assignment's first
                # observation (or none yet: it waits for the league).
                if live or over:
                    env.send(np.zeros((len(live) + len(over), 1, 69), np.float32), live + over)
                for r in env.results():
                    results[r["match_id"]] = r
                self.assertLess(len(results), 4)
            out, _ = league.communicate(timeout=60)
            self.assertEqual(league.returncode, 0, out)
            self.assertEqual(len(results), 3, "live:vec plays three games of a 4-entrant round robin")
            for r in results.values():
                self.assertIn("vec", r["agent_names"])
        finally:
            league.kill()
            league.wait()


if __name__ == "__main__":
    unittest.main()
