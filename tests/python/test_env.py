"""The Python package against a real olympics-server and a real olympics-agent opponent."""
import json
import os
import sqlite3
import subprocess
import tempfile
import unittest

import numpy as np

from smpl_olympics import MatchClient, MatchError, OlympicsParallelEnv

from server_process import BIN, start_server


class EnvAgainstRealServer(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="olympics-py-")
        self.url = f"udpm://239.255.76.67:{21000 + os.getpid() % 9000}?ttl=0&recv_buf_size=4194304"
        self.db = os.path.join(self.dir, "results.db")
        self.server = start_server(self.url, self.db, "py", os.path.join(self.dir, "server.log"))

    def tearDown(self):
        self.server.kill()
        self.server.wait()

    def test_plays_a_match_against_an_agent_process(self):
        opponent = subprocess.Popen([f"{BIN}/olympics-agent", "--lcm-url", self.url, "--request-id",
                                     "py-0", "--slots", "1", "--policy", "zero", "--name", "cpp",
                                     "--json"], stdout=subprocess.PIPE, text=True)
        env = OlympicsParallelEnv(sport="sandbox", mode="1v1", slots=[0], request_id="py",
                                  lcm_url=self.url, agent_name="python")
        observations, infos = env.reset(seed=4)
        self.assertEqual(env.agents, ["slot_0"])
        self.assertEqual(observations["slot_0"].shape, (366,))
        self.assertEqual(observations["slot_0"].dtype, np.float32)
        self.assertLessEqual(float(np.abs(observations["slot_0"]).max()), 5.0)
        # The server says what each block of the observation is, and the tick length.
        self.assertEqual(env.description["control_hz"], 30)
        self.assertEqual(list(env.obs_blocks), ["self", "time_remaining", "others"])
        self.assertEqual(env.obs_blocks["others"], slice(359, 366))
        self.assertEqual(env.block(observations["slot_0"], "time_remaining").shape, (1,))
        with self.assertRaises(KeyError):
            env.block(observations["slot_0"], "ball_position")
        # Fields inside the self block, by name: the root's height first, the rotations at 70.
        obs0 = observations["slot_0"]
        self.assertEqual(env.field(obs0, "self", "root_height")[0], obs0[0])
        self.assertEqual(env.obs_fields[("self", "body_rotations")], slice(70, 214))
        self.assertEqual(env.field(obs0, "self", "angular_velocities").shape, (72,))
        with self.assertRaises(KeyError):
            env.field(obs0, "self", "joint_angles")
        rng = np.random.default_rng(0)
        steps, returns = 0, 0.0
        while env.agents:
            actions = {a: rng.uniform(-1, 1, 69) for a in env.agents}
            observations, rewards, terminations, truncations, infos = env.step(actions)
            steps += 1
            returns += rewards.get("slot_0", 0.0)
            if "slot_0" in infos:
                self.assertEqual(set(infos["slot_0"]["reward_terms"]), {"alive", "fall"})
        self.assertGreater(steps, 0)
        self.assertIsNotNone(env.result)
        out, _ = opponent.communicate(timeout=60)
        self.assertEqual(opponent.returncode, 0)
        printed = json.loads(out.strip().splitlines()[-1])
        self.assertEqual(printed["match_id"], env.result["match_id"])
        self.assertEqual(printed["ticks"], env.result["ticks"])
        row = sqlite3.connect(self.db).execute(
            "SELECT ticks, reason FROM matches WHERE match_id = ?", (env.result["match_id"],)).fetchone()
        self.assertEqual(row, (env.result["ticks"], env.result["reason"]))
        agents = sqlite3.connect(self.db).execute(
            "SELECT agent FROM participants WHERE match_id = ? ORDER BY slot", (env.result["match_id"],)).fetchall()
        self.assertEqual(agents, [("python",), ("cpp",)])

    def test_owning_every_slot_needs_no_opponent_and_resets_to_new_matches(self):
        env = OlympicsParallelEnv(sport="sandbox", mode="2v2", lcm_url=self.url, time_limit_s=1.0)
        ids = set()
        for episode in range(2):
            observations, _ = env.reset(seed=episode)
            self.assertEqual(sorted(observations), ["slot_0", "slot_1", "slot_2", "slot_3"])
            while env.agents:
                env.step({a: np.zeros(69, dtype=np.float32) for a in env.agents})
            ids.add(env.result["match_id"])
        self.assertEqual(len(ids), 2)

    def test_a_live_learner_plays_what_the_league_assigns(self):
        league = subprocess.Popen([f"{BIN}/olympics-league", "run", "--db", os.path.join(self.dir, "league.db"),
                                   "--name", "live", "--entrants", "live:torch,zero", "--time-limit", "2",
                                   "--lcm-url", self.url, "--log-dir", self.dir, "--quiet"],
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        env = OlympicsParallelEnv(learner="torch", lcm_url=self.url, agent_name="torch")
        observations, _ = env.reset()
        self.assertEqual(env.assignment["opponent"], "zero")
        while env.agents:
            env.step({a: np.zeros(69, dtype=np.float32) for a in env.agents})
        out, _ = league.communicate(timeout=60)
        self.assertEqual(league.returncode, 0, out)
        self.assertIn("torch", out)
        self.assertEqual(env.result["agent_names"][env.assignment["slots"][0]], "torch")

    def test_the_settings_in_force_are_described_and_stored(self):
        env = OlympicsParallelEnv(sport="tennis", mode="ball_return", lcm_url=self.url,
                                  sport_options={"net_height": 0.914})
        env.reset(seed=1)
        options = json.loads(env.description["options"])
        self.assertEqual(options["net_height"], 0.914)
        self.assertEqual(options["format"], "sets", "defaults are filled in")
        self.assertEqual(env.description["time_limit_s"], 1800.0, "the sport's default")
        self.assertIn("ball_position", env.obs_blocks)
        while env.agents:
            env.step({a: np.zeros(69, dtype=np.float32) for a in env.agents})
        self.assertEqual(json.loads(env.result["options"]), options)
        stored = sqlite3.connect(self.db).execute(
            "SELECT options FROM matches WHERE match_id = ?", (env.result["match_id"],)).fetchone()
        self.assertEqual(json.loads(stored[0]), options)

    def test_task_fields_resolve_by_name_from_the_servers_description(self):
        env = OlympicsParallelEnv(sport="soccer", mode="1v1", lcm_url=self.url, time_limit_s=1.0)
        self.assertEqual(env.layout.size("ball", "position"), 3, "from the catalog before reset")
        observations, _ = env.reset(seed=3)
        # The server sent every block's fields, and the env reads by them.
        served = dict(zip((n for n, _ in env.description["obs_blocks"]),
                          env.description["obs_fields"]))
        self.assertEqual(served["ball"], [("position", 3), ("velocity", 3), ("spin", 3)])
        self.assertEqual(served["match"][3], ("restart", 1))
        obs = observations["slot_0"]
        ball = env.field(obs, "ball", "position")
        self.assertEqual(ball.shape, (3,))
        at = env.layout.offset("ball", "position")
        np.testing.assert_array_equal(ball, obs[at:at + 3])
        np.testing.assert_array_equal(env.field(obs, "ball", "velocity"),
                                      env.block(obs, "ball")[3:6])
        # It holds the ball: at kick-off the ball lies on the ground, its centre a radius up.
        root_height = float(env.field(obs, "self", "root_height")[0])
        self.assertAlmostEqual(float(ball[2]) + root_height, 0.11, delta=0.01)
        self.assertEqual(env.layout.offset("match", "restart"), env.layout.offset("match") + 3)
        with self.assertRaises(KeyError) as refused:
            env.field(obs, "ball", "colour")
        self.assertIn("position, velocity, spin", str(refused.exception))
        while env.agents:
            env.step({a: np.zeros(69, dtype=np.float32) for a in env.agents})

    def test_a_secured_server_plays_with_the_secret_and_refuses_without(self):
        secret = os.path.join(self.dir, "secret")
        subprocess.run([f"{BIN}/olympics-server", "secret", secret], check=True, capture_output=True)
        url = self.url.replace(str(21000 + os.getpid() % 9000), str(31000 + os.getpid() % 9000))
        server = start_server(url, os.path.join(self.dir, "secured.db"), "vault",
                              os.path.join(self.dir, "secured.log"), "--secret", secret)
        try:
            env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=url,
                                      time_limit_s=1.0, secret_file=secret)
            env.reset(seed=1)
            while env.agents:
                env.step({a: np.zeros(69, dtype=np.float32) for a in env.agents})
            self.assertIsNotNone(env.result)
            stranger = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=url,
                                           timeout_s=60.0)
            with self.assertRaises(MatchError) as caught:
                stranger.reset()
            self.assertIn("UNAUTHENTICATED", str(caught.exception))
        finally:
            server.kill()
            server.wait()

    def test_a_match_on_lcms_multi_port_provider(self):
        # mpudpm://: every channel hashed to one of 64 ports; the server subscribes to each
        # match's action channel by name (docs/server.md, Scale notes).
        url = f"mpudpm://239.255.76.67:{41000 + os.getpid() % 9000 * 2}?ttl=0&nports=64"
        server = start_server(url, os.path.join(self.dir, "multi.db"), "multi",
                              os.path.join(self.dir, "multi.log"))
        try:
            env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=url, time_limit_s=1.0)
            env.reset(seed=2)
            while env.agents:
                env.step({a: np.zeros(69, dtype=np.float32) for a in env.agents})
            self.assertGreater(env.result["ticks"], 0)
            stored = sqlite3.connect(os.path.join(self.dir, "multi.db")).execute(
                "SELECT ticks FROM matches WHERE match_id = ?", (env.result["match_id"],)).fetchone()
            self.assertEqual(stored, (env.result["ticks"],))
        finally:
            server.kill()
            server.wait()

    def test_errors_naming_a_match_it_does_not_hold_are_ignored_and_counted(self):
        """An error naming this env's client with a match it does not hold changes nothing and
        is counted: a server never sends one, so someone else did (docs/security.md)."""
        import socket
        import struct
        from olympics import error_t, protocol_version_t
        env = OlympicsParallelEnv(sport="sandbox", mode="1v1", lcm_url=self.url, time_limit_s=3.0)
        env.reset(seed=1)
        self.assertEqual(env.ignored_errors, 0)
        forged = error_t()
        forged.protocol_version = protocol_version_t.VERSION
        forged.server_id, forged.match_id = "py", "py_other-1-7"
        forged.client_id, forged.code = env._client.client_id, "UNKNOWN_MATCH"
        forged.message = "forged: the env must not stop for this"
        forged.signature = bytes(56)
        group, port = self.url[len("udpm://"):].split("?")[0].split(":")
        sender = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        sender.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 0)
        ticks = 0
        while env.agents:  # LCM's small-message datagram: magic, sequence, channel, payload
            sender.sendto(struct.pack(">II", 0x4C433032, ticks) + b"OLY_ERROR\0" + forged.encode(),
                          (group, int(port)))
            env.step({a: np.zeros(69, dtype=np.float32) for a in env.agents})
            ticks += 1
        # Played to the end by the sport's own rules (zero actions: both fall, about 2 s).
        self.assertGreater(ticks, 30)
        self.assertIn(env.result.get("reason"), ("all_fell", "last_team_standing", "time_limit"),
                      env.result)
        self.assertGreater(env.ignored_errors, 0)

    def test_errors_reach_python(self):
        with self.assertRaises(ValueError) as caught:  # the catalog knows before any server
            OlympicsParallelEnv(sport="curling", lcm_url=self.url)
        self.assertIn("known sports: ", str(caught.exception))
        self.assertIn("boxing", str(caught.exception))
        with self.assertRaises(ValueError) as caught:
            OlympicsParallelEnv(sport="tennis", mode="3v3", lcm_url=self.url)
        self.assertIn("its modes: ball_return, 1v1, 2v2", str(caught.exception))
        client = MatchClient(self.url, "python", "", "", "")
        with self.assertRaises(MatchError) as caught:  # and the server says so too
            client.request_match("curling", "1v1", 0, 0.0, False, "py-curling", "", 60.0, "")
        self.assertIn("UNKNOWN_SPORT", str(caught.exception))
        self.assertIn("known sports: sandbox", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
