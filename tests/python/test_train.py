"""The reference trainer (smpl_olympics.train): PPO improves the return on a trivial task; its
snapshots act in the C++ MLP player exactly as in PyTorch (a residual one on top of the very
scripted baseline); a resumed run goes on where it stopped; a short run against a real server
leaves its checkpoint, snapshots, metrics and curves, and its snapshot plays a match."""
import json
import os
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np
import torch

from server_process import BIN
from smpl_olympics import train
from smpl_olympics._client import NativePolicy
from smpl_olympics.ppo import ActorCritic, RunningNorm
from smpl_olympics.training_log import TrainingLog, read_metrics


class ToyVectorEnv:
    """A trivial task with the vector env's interface: the best action is a fixed linear map of
    the observation (clipped), reward 1 - mean squared error, 16-tick episodes."""
    OBS, ACT, LENGTH = 8, 4, 16

    def __init__(self, num_envs, seed=0, agents=1):
        self.n, self.agents, self.rng = num_envs, agents, np.random.default_rng(seed)
        self.w = np.random.default_rng(42).normal(0, 0.4, (self.ACT, self.OBS)).astype(np.float32)
        self.t = np.zeros(num_envs, int)

    def _obs(self):
        self.o = self.rng.normal(0, 1, (self.n, self.agents, self.OBS)).astype(np.float32)
        return self.o

    def reset(self):
        return self._obs(), {}

    def step(self, actions):
        target = np.clip(self.o @ self.w.T, -1, 1)
        reward = 1 - ((actions - target) ** 2).mean(-1)
        self.t += 1
        over = self.t >= self.LENGTH
        self.t[over] = 0
        final = self.o.copy()
        infos = {"episode_over": over, "reward_terms": reward[..., None],
                 "final_observation": final}
        flags = np.repeat(over[:, None], self.agents, axis=1)
        return self._obs(), reward, flags, flags, infos

    def results(self):
        return []

    def close(self):
        pass


class ToyLeagueEnv(ToyVectorEnv):
    """ToyVectorEnv stepped as a league's live learner steps its matches (start/send/recv): at
    each recv a random part of the environments is ready, and environment 0 never gets a match
    after its first (the league started none for it)."""

    def start(self):
        self.o = self._obs()
        self.ready = {e: (self.o[e].copy(), np.zeros(self.agents, np.float32), False)
                      for e in range(self.n)}

    def send(self, actions, env_ids):
        for row, e in enumerate(env_ids):
            target = np.clip(self.o[e] @ self.w.T, -1, 1)
            reward = (1 - ((actions[row] - target) ** 2).mean(-1)).astype(np.float32)
            self.t[e] += 1
            over = bool(self.t[e] >= self.LENGTH)
            self.t[e] = 0 if over else self.t[e]
            self.o[e] = self.rng.normal(0, 1, (self.agents, self.OBS))
            if not (over and e == 0):
                self.ready[e] = (self.o[e].copy(), reward, over)

    def recv(self, min_ready=1):
        envs = [e for e in sorted(self.ready) if self.rng.random() < 0.6] or [min(self.ready)]
        obs, reward, over = (np.stack(x) for x in zip(*(self.ready.pop(e) for e in envs)))
        flags = np.repeat(over[:, None], self.agents, axis=1)
        infos = {"episode_over": over, "reward_terms": reward[..., None], "final_observation": obs}
        return np.array(envs), obs, reward, flags, flags, infos


TOY_SPEC = {"slot_teams": [0], "obs_size": ToyVectorEnv.OBS, "action_size": ToyVectorEnv.ACT,
            "observation": [{"name": "x", "size": ToyVectorEnv.OBS}],
            "rewards": [{"name": "match"}]}


def run_args(run, *extra):
    return train.parse_args(["--run", run, "--quiet", *extra])


class TrainTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="olympics-train-")

    def test_ppo_improves_the_return_on_a_trivial_task(self):
        args = run_args(os.path.join(self.dir, "toy"), "--samples", "40000", "--num-envs", "16",
                        "--horizon", "32", "--hidden", "64", "64", "--lr", "1e-3",
                        "--learn-std", "--log-std", "-1")
        trainer = train.Trainer(args, spec=TOY_SPEC)
        trainer.train(make_env=lambda: ToyVectorEnv(args.num_envs))
        rows = [r for r in read_metrics(args.run) if r["episode_return"]]
        first = np.mean([float(r["episode_return"]) for r in rows[:5]])
        last = np.mean([float(r["episode_return"]) for r in rows[-5:]])
        # A random guess scores about 16 * (1 - 0.6); the map is learnable to nearly 16.
        self.assertGreater(last, first + 2.0, f"return {first:.2f} -> {last:.2f}")

    def test_a_league_run_steps_whichever_matches_are_ready_and_learns(self):
        # --league collects asynchronously: environment 0 waits for good after its first match
        # and holds no other; each environment's steps are their own sequence.
        args = run_args(os.path.join(self.dir, "toy-league"), "--league", "toy", "--samples",
                        "40000", "--num-envs", "16", "--horizon", "32", "--hidden", "64", "64",
                        "--lr", "1e-3", "--learn-std", "--log-std", "-1")
        trainer = train.Trainer(args, spec=TOY_SPEC)
        trainer.train(make_env=lambda: ToyLeagueEnv(args.num_envs))
        rows = read_metrics(args.run)
        self.assertGreaterEqual(trainer.samples, 40000)
        sizes = np.diff([0] + [int(r["samples"]) for r in rows])
        self.assertTrue(all(sizes >= 16 * 32), f"every batch full: {sizes}")
        returns = [float(r["episode_return"]) for r in rows if r["episode_return"]]
        first, last = np.mean(returns[:5]), np.mean(returns[-5:])
        self.assertGreater(last, first + 2.0, f"return {first:.2f} -> {last:.2f}")

    def test_episode_figures_are_each_episodes_own_sums(self):
        ep = train.Episodes(2, 1, 2)
        ep.add(np.array([[1.0], [2.0]]), np.array([[[1, 0]], [[0, 3]]]), np.array([False, True]))
        ep.add(np.array([[4.0], [8.0]]), np.array([[[0, 0]], [[5, 5]]]), np.array([True, False]))
        s = ep.summary(["racket", "contact"])
        self.assertEqual(s["episodes"], 2)
        self.assertEqual(s["episode_return"], (2.0 + 5.0) / 2)
        self.assertEqual(s["episode_length"], (1 + 2) / 2)
        self.assertEqual((s["term_racket"], s["term_contact"]), (0.5, 1.5))
        self.assertEqual(s["touch_rate"], 0.5)  # the first ended episode touched, the second not
        self.assertEqual(ep.summary(["racket", "contact"]), {"episodes": 0})

    def test_win_reward_lands_on_the_last_tick_of_each_ended_match(self):
        args = run_args(os.path.join(self.dir, "win"), "--win-reward", "5", "--opponent",
                        "frozen", "--hidden", "16")
        trainer = train.Trainer(args, spec=dict(TOY_SPEC, slot_teams=[0, 1]))

        class Results:  # the results come in two batches, as they would over the network
            batches = [[{"match_id": "won", "winner_team": 0, "slot_team": [0, 1]},
                        {"match_id": "lost", "winner_team": 1, "slot_team": [0, 1]}],
                       [{"match_id": "drawn", "winner_team": -1, "slot_team": [0, 1]}]]

            def results(self):
                return self.batches.pop(0) if self.batches else []
        rewards = np.zeros((4, 2, 1), np.float32)  # [tick, env, learning slot]
        trainer.credit_outcomes(Results(), {"won": (1, 0), "lost": (3, 1), "drawn": (2, 0)},
                                rewards)
        self.assertEqual(rewards[1, 0, 0], 5.0)
        self.assertEqual(rewards[3, 1, 0], -5.0)
        self.assertEqual(float(np.abs(rewards).sum()), 10.0)  # the draw earned nothing
        self.assertEqual(trainer.outcomes_missed, 0)
        self.assertEqual(len(trainer.results), 3)  # kept for the metrics row's win rate
        trainer.RESULT_WAIT_S = 0.2
        trainer.credit_outcomes(Results(), {"never": (0, 0)}, rewards)  # its result is lost
        self.assertEqual(trainer.outcomes_missed, 1)
        self.assertEqual(float(np.abs(rewards).sum()), 10.0)

    def test_action_mask_learns_only_the_named_entries_and_critic_warmup_holds_the_policy(self):
        args = run_args(os.path.join(self.dir, "mask"), "--samples", "8192", "--num-envs", "16",
                        "--horizon", "32", "--hidden", "32", "--lr", "1e-3",
                        "--action-mask", "1:3", "--critic-warmup", "8")
        trainer = train.Trainer(args, spec=TOY_SPEC)
        start = [p.detach().clone() for p in trainer.model.actor.parameters()]
        args.samples = 8 * 16 * 32  # exactly the warm-up's iterations
        trainer.train(make_env=lambda: ToyVectorEnv(args.num_envs))
        for before, after in zip(start, trainer.model.actor.parameters()):
            self.assertTrue(torch.equal(before, after), "the actor moved during the warm-up")
        critic_rows = [r for r in read_metrics(args.run) if r.get("value_loss")]
        self.assertGreater(float(critic_rows[0]["value_loss"]), float(critic_rows[-1]["value_loss"]))
        args.samples = 16384
        trainer.train(make_env=lambda: ToyVectorEnv(args.num_envs))
        last = trainer.model.actor[-1]
        self.assertTrue(torch.equal(last.weight[[0, 3]], torch.zeros(2, 32)))
        self.assertTrue(torch.equal(last.bias[[0, 3]], torch.zeros(2)))
        self.assertGreater(float(last.weight[1:3].abs().sum()), 0.0)
        obs = torch.randn(64, ToyVectorEnv.OBS)
        a, _, _ = trainer.model.act(obs)  # no exploration outside the mask either
        self.assertTrue(torch.equal(a[:, [0, 3]], torch.zeros(64, 2)))
        self.assertGreater(float(a[:, 1:3].std()), 0.0)
        older = {k: v for k, v in trainer.model.state_dict().items() if k != "mask"}
        unmasked = ActorCritic(ToyVectorEnv.OBS, ToyVectorEnv.ACT, [32])
        unmasked.load_state_dict(older)  # a checkpoint from before --action-mask
        self.assertTrue(torch.equal(unmasked.mask, torch.ones(ToyVectorEnv.ACT)))
        with self.assertRaises(SystemExit) as bad:
            train.action_mask("3:9", 4)
        self.assertIn("outside the action's 0:4", str(bad.exception))

    def test_term_weights_override_the_sports_by_name(self):
        terms = [{"name": "facing", "weight": 0.1}, {"name": "strike", "weight": 0.6},
                 {"name": "point", "weight": 1.0}]
        self.assertIsNone(train.term_weights(terms, ""))
        np.testing.assert_allclose(train.term_weights(terms, "facing=0, point=3"), [0.0, 0.6, 3.0])
        with self.assertRaises(SystemExit) as bad:
            train.term_weights(terms, "facing=0,punch=2")
        self.assertIn("punch", str(bad.exception))
        self.assertIn("facing, strike, point", str(bad.exception))

    def test_frozen_self_play_plays_a_copy_refreshed_every_swap(self):
        args = run_args(os.path.join(self.dir, "frozen"), "--samples", "2048", "--num-envs", "4",
                        "--horizon", "64", "--hidden", "16", "--opponent", "frozen",
                        "--swap-every", "2")
        spec = dict(TOY_SPEC, slot_teams=[0, 1])
        trainer = train.Trainer(args, spec=spec)
        self.assertEqual((trainer.learning, trainer.others), ([0], [1]))
        seen = []
        opponent_actions = trainer.opponent_actions

        def watch(raw, env_ids):
            seen.append(trainer.frozen[0].state_dict()["actor.0.weight"].clone())
            return opponent_actions(raw, env_ids)
        trainer.opponent_actions = watch
        trainer.train(make_env=lambda: ToyVectorEnv(4, agents=2))
        self.assertEqual(trainer.iteration, 8)
        # Iterations 1-2 met the initial copy, 3-4 the copy made after iteration 2, ...
        per_iteration = [seen[i * 64] for i in range(8)]
        self.assertTrue(torch.equal(per_iteration[0], per_iteration[1]))
        self.assertFalse(torch.equal(per_iteration[1], per_iteration[2]))
        self.assertTrue(torch.equal(per_iteration[2], per_iteration[3]))
        self.assertTrue(torch.equal(trainer.frozen[0].state_dict()["actor.0.weight"],
                                    trainer.model.state_dict()["actor.0.weight"]))

    def test_warm_start_matches_observation_blocks_by_name(self):
        solo = train.Trainer(run_args(os.path.join(self.dir, "solo"), "--sport", "table_tennis",
                                      "--mode", "ball_return", "--hidden", "16"))
        solo.norm.update(np.random.default_rng(1).normal(3, 2, (50, solo.obs_size)))
        solo.save()
        duel = train.Trainer(run_args(os.path.join(self.dir, "duel"), "--sport", "table_tennis",
                                      "--mode", "1v1", "--hidden", "16"))
        matched = duel.warm_start(os.path.join(self.dir, "solo"))
        self.assertIn("self", matched)
        self.assertIn("ball_position", matched)
        at = 0
        w_src = solo.model.state_dict()["actor.0.weight"]
        w_dst = duel.model.state_dict()["actor.0.weight"]
        offsets = {}
        o = 0
        for b in solo.spec["observation"]:
            offsets[b["name"]] = o
            o += b["size"]
        for b in duel.spec["observation"]:
            cols = w_dst[:, at:at + b["size"]]
            if b["name"] in matched:
                s0 = offsets[b["name"]]
                self.assertTrue(torch.equal(cols, w_src[:, s0:s0 + b["size"]]), b["name"])
                np.testing.assert_array_equal(duel.norm.mean[at:at + b["size"]],
                                              solo.norm.mean[s0:s0 + b["size"]])
            else:
                self.assertEqual(float(cols.abs().sum()), 0.0, b["name"])
            at += b["size"]
        self.assertTrue(torch.equal(duel.model.state_dict()["actor.2.weight"],
                                    solo.model.state_dict()["actor.2.weight"]))
        self.assertLess(len(matched), len(duel.spec["observation"]), "1v1 has blocks of its own")

    def test_resume_goes_on_where_the_run_stopped(self):
        run = os.path.join(self.dir, "resume")
        args = run_args(run, "--samples", "1024", "--num-envs", "4", "--horizon", "64",
                        "--hidden", "32", "--sport", "sandbox", "--mode", "solo")
        first = train.Trainer(args, spec=TOY_SPEC)
        first.train(make_env=lambda: ToyVectorEnv(4))
        saved = torch.load(os.path.join(run, "checkpoint.pt"), weights_only=False)
        self.assertEqual((saved["iteration"], saved["samples"]), (4, 1024))
        again = train.Trainer(args, spec=TOY_SPEC)
        again.load(run)
        for k, v in first.model.state_dict().items():
            self.assertTrue(torch.equal(v, again.model.state_dict()[k]), k)
        np.testing.assert_array_equal(again.norm.mean, first.norm.mean)
        again.args.samples = 2048
        again.train(make_env=lambda: ToyVectorEnv(4))
        rows = read_metrics(run)
        self.assertEqual([int(r["iteration"]) for r in rows], list(range(1, 9)))
        self.assertEqual(int(rows[-1]["samples"]), 2048)
        self.assertGreater(float(rows[-1]["wall_s"]), float(rows[3]["wall_s"]))

    def test_a_short_run_against_the_server_plays_in_the_cpp_player_with_equal_actions(self):
        run = os.path.join(self.dir, "tt")
        env = dict(os.environ, OLYMPICS_BIN_DIR=BIN)
        out = subprocess.run(
            ["/usr/bin/python3", "-m", "smpl_olympics.train", "--run", run, "--sport",
             "table_tennis", "--mode", "ball_return", "--samples", "1024",  # a private server
             "--num-envs", "4", "--horizon", "64", "--hidden", "32", "--residual", "scripted",
             "--snapshot-every", "1", "--quiet"],
            env=env, capture_output=True, text=True, timeout=600)
        self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
        for f in ("checkpoint.pt", "metrics.csv", "curves.png", "args.json", "server.log",
                  "snapshots/policy-latest.safetensors", "snapshots/policy-v00004.safetensors"):
            self.assertTrue(os.path.exists(os.path.join(run, f)), f)
        rows = read_metrics(run)
        self.assertEqual(len(rows), 4)
        self.assertGreater(sum(int(r["episodes"]) for r in rows), 0, "episodes ended and counted")

        # The snapshot in C++ (olympics-snapshot: the MLP alone) against PyTorch's mean action.
        state = torch.load(os.path.join(run, "checkpoint.pt"), weights_only=False)
        spec = train.catalog.mode("table_tennis", "ball_return")
        model = ActorCritic(spec["obs_size"], spec["action_size"], [32])
        model.load_state_dict(state["model"])
        norm = RunningNorm(spec["obs_size"])
        norm.load_state_dict(state["norm"])
        obs = np.random.default_rng(3).normal(0, 1, (5, spec["obs_size"])).astype(np.float32)
        obs = obs * norm.std().astype(np.float32) + norm.mean.astype(np.float32)
        want = model.mean_action(torch.as_tensor(norm.normalise(obs))).numpy()
        snapshot = os.path.join(run, "snapshots", "policy-latest.safetensors")
        evaluated = subprocess.run([f"{BIN}/olympics-snapshot", "eval", snapshot],
                                   input="\n".join(" ".join(map(repr, map(float, o))) for o in obs),
                                   capture_output=True, text=True, check=True).stdout
        got = np.array([[float(x) for x in line.split()] for line in evaluated.strip().splitlines()])
        np.testing.assert_allclose(got, want, atol=1e-4)

        # Residual: the C++ player adds the same scripted baseline the trainer added.
        native = lambda name: NativePolicy(name, "table_tennis", "ball_return",  # noqa: E731
                                           spec["observation"], spec["action_size"])
        player, scripted = native("mlp:" + snapshot), native("scripted")
        for o, w in zip(obs, want):
            np.testing.assert_allclose(player.act(o), np.clip(w, -1, 1) + scripted.act(o),
                                       atol=1e-4)

        # And it plays a match through olympics-agent, as the league would.
        server = subprocess.Popen([f"{BIN}/olympics-server", "serve", "--lcm-url", URL, "--id",
                                   "trained", "--results", os.path.join(self.dir, "r.db")],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        try:
            agent = subprocess.run(
                [f"{BIN}/olympics-agent", "--lcm-url", URL, "--sport", "table_tennis", "--mode",
                 "ball_return", "--request-id", "trained", "--policy", "mlp:" + snapshot,
                 "--time-limit", "10", "--json", "--timeout", "60"],
                capture_output=True, text=True, timeout=120)
            self.assertEqual(agent.returncode, 0, agent.stdout + agent.stderr)
            self.assertEqual(json.loads(agent.stdout.strip().splitlines()[-1])["mode"],
                             "ball_return")
        finally:
            server.terminate()
            server.wait(timeout=30)


    def test_a_killed_run_takes_its_spawned_server_with_it(self):
        run = os.path.join(self.dir, "killed")
        trainer = subprocess.Popen(
            ["/usr/bin/python3", "-m", "smpl_olympics.train", "--run", run, "--sport", "sandbox",
             "--mode", "solo", "--spawn-server", "--samples", "100000000", "--hidden", "16",
             "--quiet"], env=dict(os.environ, OLYMPICS_BIN_DIR=BIN),
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        servers = lambda: [p for p in os.listdir("/proc") if p.isdigit()  # noqa: E731
                           and run in _cmdline(p) and "olympics-server" in _cmdline(p)]
        give_up = time.monotonic() + 60
        while not os.path.exists(os.path.join(run, "metrics.csv")) and time.monotonic() < give_up:
            time.sleep(0.1)
        self.assertEqual(len(servers()), 1, "the run plays on its own server")
        trainer.kill()
        trainer.wait()
        give_up = time.monotonic() + 20
        while servers() and time.monotonic() < give_up:
            time.sleep(0.1)
        self.assertEqual(servers(), [], "the server outlived its run")

    def test_a_league_run_learns_from_games_against_opponents_the_league_picks(self):
        # olympics-league selfplay with a live learner: the trainer's client plays the learning
        # side of every game, the league picks each opponent by PFSP from the bot and the
        # snapshots the trainer publishes as it goes.
        run, db = os.path.join(self.dir, "league-run"), os.path.join(self.dir, "league.db")
        server = subprocess.Popen([f"{BIN}/olympics-server", "serve", "--lcm-url", URL, "--id",
                                   "leaguetrain", "--results", os.path.join(self.dir, "l.db"),
                                   *train.TRAINING_SERVER_FLAGS],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        league = subprocess.Popen(
            [f"{BIN}/olympics-league", "selfplay", "--db", db, "--name", "lt", "--learner",
             "lt", "--snapshots", os.path.join(run, "snapshots"), "--strategy", "pfsp:even",
             "--bots", "zero", "--sport", "sandbox", "--mode", "1v1", "--time-limit", "1",
             "--matches", "1000", "--parallel", "2", "--lcm-url", URL, "--log-dir", self.dir,
             "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        try:
            out = subprocess.run(
                ["/usr/bin/python3", "-m", "smpl_olympics.train", "--run", run, "--sport",
                 "sandbox", "--mode", "1v1", "--league", "lt", "--lcm-url", URL, "--samples",
                 "320", "--num-envs", "2", "--horizon", "16", "--hidden", "32",
                 "--snapshot-every", "1", "--quiet"],
                env=dict(os.environ, OLYMPICS_BIN_DIR=BIN), capture_output=True, text=True,
                timeout=600)
            self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
            rows = read_metrics(run)
            self.assertEqual(len(rows), 10)
            self.assertGreater(sum(int(r["episodes"]) for r in rows), 3, "games ended and counted")
            win_rates = [float(r["win_rate"]) for r in rows if r.get("win_rate")]
            self.assertTrue(win_rates and all(0 <= w <= 1 for w in win_rates),
                            f"the learner's own results, found by its name: {win_rates}")
            table = subprocess.run([f"{BIN}/olympics-league", "table", "--db", db, "--name", "lt",
                                    "--json"], capture_output=True, text=True, timeout=60)
            played = {e["entrant"]: e["wins"] + e["draws"] + e["losses"]
                      for e in json.loads(table.stdout)}
            self.assertGreater(played["lt"], 3, played)
            self.assertGreater(sum(n for name, n in played.items() if name.startswith("mlp-")), 0,
                               f"the league also picked the run's own snapshots: {played}")
        finally:
            for p in (league, server):
                p.kill()
                p.wait()


def _cmdline(pid):
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            return f.read().decode(errors="replace")
    except OSError:  # it ended meanwhile
        return ""


class Curves(unittest.TestCase):
    def test_a_ball_return_curve_has_no_empty_win_rate_panel(self):
        run = tempfile.mkdtemp(prefix="olympics-curves-")
        log = TrainingLog(run, ["contact", "hits"])
        for i in range(1, 4):  # a ball return: scores and touches, never a winner
            log.write({"iteration": i, "samples": 100 * i, "episode_return": 1.0 * i,
                       "episode_length": 40, "score": 0.1 * i, "touch_rate": 0.2,
                       "term_contact": 0.5, "term_hits": 0.1})
        panels = log.plot(os.path.join(run, "curves.png"), "ball return")
        self.assertEqual(panels, ["episode_return", "episode_length", "score", "touch_rate",
                                  "term_contact", "term_hits"])
        self.assertTrue(os.path.getsize(os.path.join(run, "curves.png")) > 0)


class TrainerSaysWhichPython(unittest.TestCase):
    def test_a_python_without_torch_gets_which_python_and_what_to_do(self):
        shadow = tempfile.mkdtemp(prefix="olympics-notorch-")
        os.makedirs(os.path.join(shadow, "torch"))
        with open(os.path.join(shadow, "torch", "__init__.py"), "w") as f:
            f.write("raise ImportError('no torch in this test')\n")
        env = dict(os.environ, PYTHONPATH=f"{shadow}:{os.environ.get('PYTHONPATH', '')}")
        done = subprocess.run([sys.executable, "-m", "smpl_olympics.train", "--samples", "1"],
                              env=env, capture_output=True, text=True, timeout=120)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn(f"the trainer runs in {sys.executable}", done.stderr)
        self.assertIn("python3-torch", done.stderr)
        self.assertNotIn("Traceback", done.stderr)


class RunsAreNotCommitted(unittest.TestCase):
    def test_the_default_run_folder_is_ignored_by_git(self):
        repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        if not os.path.isdir(os.path.join(repo, ".git")) and not os.path.isfile(
                os.path.join(repo, ".git")):
            self.skipTest("not a git checkout")
        run = train.parse_args([]).run
        for made in (os.path.join(run, "snapshots", "000001.npz"), os.path.join(run, "metrics.jsonl")):
            checked = subprocess.run(["git", "check-ignore", "-q", made], cwd=repo)
            self.assertEqual(checked.returncode, 0, f"{made} is not ignored by git")


URL = f"udpm://239.255.76.67:{25000 + os.getpid() % 9000}?ttl=0&recv_buf_size=4194304"

if __name__ == "__main__":
    unittest.main()
