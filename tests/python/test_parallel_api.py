"""PettingZoo's parallel API rules, checked by hand against real matches on a real olympics-server:
finer than PettingZoo's own parallel_api_test (which test_pettingzoo.py runs for every mode),
e.g. agents dropping out before the match's end, and the spaces' bounds."""
import os
import tempfile
import unittest

import numpy as np

from smpl_olympics import OlympicsParallelEnv
from smpl_olympics.spaces import Box

from server_process import start_server


def check_parallel_api(test, env, seed, max_steps=10_000):
    """Plays one episode with actions sampled from the action spaces and asserts every rule on
    the way; returns the set of agents seen dropping out before the match's end."""
    # Before reset: agents, their number and the spaces are known.
    test.assertGreater(len(env.possible_agents), 0)
    test.assertEqual(env.max_num_agents, len(env.possible_agents))
    for agent in env.possible_agents:
        space = env.observation_space(agent)
        test.assertIs(space, env.observation_space(agent), "spaces are cached objects")
        test.assertIs(env.action_space(agent), env.action_space(agent))
        for attribute in ("shape", "dtype", "contains", "sample", "low", "high"):
            test.assertTrue(hasattr(space, attribute), attribute)
        test.assertEqual(space.dtype, np.float32)
        test.assertTrue(env.action_space(agent).contains(env.action_space(agent).sample()))

    observations, infos = env.reset(seed=seed)
    test.assertEqual(set(observations), set(env.agents))
    test.assertEqual(set(infos), set(env.agents))
    test.assertEqual(env.num_agents, len(env.agents))
    test.assertEqual(env.state().shape, env.state_space.shape)
    for agent, obs in observations.items():
        test.assertIn(agent, env.possible_agents)
        test.assertTrue(env.observation_space(agent).contains(obs),
                        f"{agent}'s first observation is outside its space")

    gone, dropped_early, steps = set(), set(), 0
    while env.agents and steps < max_steps:
        live = list(env.agents)
        actions = {a: env.action_space(a).sample() for a in live}
        observations, rewards, terminations, truncations, infos = env.step(actions)
        steps += 1
        for d in (observations, rewards, terminations, truncations, infos):
            test.assertTrue(set(d) <= set(live), "only agents live before the step appear")
            test.assertFalse(set(d) & gone, "an agent that finished earlier appeared again")
        for agent in env.agents:
            test.assertIn(agent, observations, "every live agent is observed")
        test.assertEqual(set(rewards), set(terminations))
        test.assertEqual(set(rewards), set(truncations))
        for agent, obs in observations.items():
            test.assertTrue(env.observation_space(agent).contains(obs),
                            f"{agent}'s observation at step {steps} is outside its space: "
                            f"{obs[~((obs >= env.observation_space(agent).low) & (obs <= env.observation_space(agent).high))]}")
            test.assertIsInstance(rewards[agent], float)
            test.assertIsInstance(terminations[agent], bool)
            test.assertIsInstance(truncations[agent], bool)
        finished = {a for a in live if terminations.get(a) or truncations.get(a)}
        test.assertEqual(set(env.agents), set(live) - finished, "finished agents leave env.agents")
        test.assertEqual(env.num_agents, len(env.agents))
        if finished and env.agents:
            dropped_early |= finished
        gone |= finished
        test.assertEqual(env.state().shape, env.state_space.shape)
    test.assertFalse(env.agents, "the match ended")
    test.assertIsNotNone(env.result)
    return dropped_early


class ParallelApi(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="olympics-api-")
        self.url = f"udpm://239.255.76.67:{22000 + os.getpid() % 9000}?ttl=0&recv_buf_size=4194304"
        self.server = start_server(self.url, os.path.join(self.dir, "results.db"), "api",
                                   os.path.join(self.dir, "server.log"))

    def tearDown(self):
        self.server.kill()
        self.server.wait()

    def test_sandbox_2v2_owning_every_slot_with_agents_dropping_out(self):
        env = OlympicsParallelEnv(sport="sandbox", mode="2v2", lcm_url=self.url, time_limit_s=6.0)
        self.assertEqual(env.possible_agents, ["slot_0", "slot_1", "slot_2", "slot_3"])
        self.assertEqual(env.num_agents, 0)
        # Random actions fell humanoids one by one: those agents leave before the match ends.
        dropped = set()
        for seed in (1, 2, 3):
            dropped |= check_parallel_api(self, env, seed)
        self.assertTrue(dropped, "no agent finished before the others: drop-out untested")

    def test_tennis_observations_with_unclamped_task_blocks_are_in_the_space(self):
        env = OlympicsParallelEnv(sport="tennis", mode="ball_return", lcm_url=self.url,
                                  time_limit_s=4.0)
        space = env.observation_space("slot_0")
        self.assertEqual(space.shape, (384,))
        self.assertEqual(float(space.high[0]), 5.0, "the self block is clamped to +-5")
        self.assertTrue(np.isinf(space.high[env.obs_blocks["ball_velocity"]]).all())
        check_parallel_api(self, env, seed=5)

    def test_one_slot_of_a_1v1_is_one_agent_before_and_after_reset(self):
        env = OlympicsParallelEnv(sport="fencing", mode="1v1", slots=[1], lcm_url=self.url,
                                  request_id="api-fence")
        self.assertEqual(env.possible_agents, ["slot_1"])
        self.assertEqual(env.observation_space("slot_1").shape, (env.observation_size(),))

    def test_reset_without_a_seed_draws_a_fresh_one_and_a_seed_repeats(self):
        env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=self.url, time_limit_s=0.2)
        seeds = []
        for seed in (None, None, 11, 11):
            env.reset(seed=seed)
            seeds.append(env.description["seed"])
            while env.agents:
                env.step({a: np.zeros(69, dtype=np.float32) for a in env.agents})
        self.assertNotEqual(seeds[0], seeds[1], "two unseeded episodes got the same seed")
        self.assertEqual(seeds[2:], [11, 11])


class SpacesWithoutGymnasium(unittest.TestCase):
    def test_box_contains_samples_and_refuses_outside(self):
        box = Box(np.array([-1, -np.inf], np.float32), np.array([1, np.inf], np.float32), (2,), seed=3)
        for _ in range(100):
            self.assertTrue(box.contains(box.sample()))
        self.assertFalse(box.contains(np.array([2.0, 0.0], np.float32)))
        self.assertFalse(box.contains(np.zeros(3, np.float32)))
        self.assertTrue(box.contains(np.array([0.5, 1e30], np.float32)))
        self.assertFalse(box.contains(np.array([np.nan, 0.0], np.float32)))


if __name__ == "__main__":
    unittest.main()
