"""smpl_olympics.evaluate against real servers: it picks the snapshot that plays best on the
validation seeds (not the latest, not the first), measures it on other held-out seeds (one range
or several) beside the scripted player and against it match by match, and a rerun gives the very
same tables."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from smpl_olympics import catalog
from smpl_olympics.snapshot import export_mlp

HERE = os.path.dirname(os.path.abspath(__file__))


def zero_mlp(obs_size, action_size):
    """A network whose action is exactly zero: on top of the scripted player (residual) it is
    the scripted player; alone it stands still and returns no ball."""
    return [(np.zeros((8, obs_size), np.float32), np.zeros(8, np.float32)),
            (np.zeros((action_size, 8), np.float32), np.zeros(action_size, np.float32))]


class Evaluate(unittest.TestCase):
    def make_run(self):
        run = tempfile.mkdtemp(prefix="olympics-eval-")
        self.addCleanup(shutil.rmtree, run, True)
        spec = catalog.mode("table_tennis", "ball_return")
        os.makedirs(os.path.join(run, "snapshots"))
        with open(os.path.join(run, "args.json"), "w") as f:
            json.dump({"sport": "table_tennis", "mode": "ball_return", "opponent": "",
                       "time_limit": 0.0, "options": ""}, f)
        layers = zero_mlp(spec["obs_size"], spec["action_size"])
        for version, residual in ((1, "none"), (2, "scripted"), (3, "none")):
            export_mlp(layers, os.path.join(run, "snapshots", f"policy-v{version:05d}.safetensors"),
                       activation="silu", sport="table_tennis", mode="ball_return",
                       residual=residual)
        return run

    def evaluate(self, run):
        done = subprocess.run([sys.executable, "-m", "smpl_olympics.evaluate", run,
                               "--validation-seeds", "1-12", "--test-seeds", "101-106,201-206",
                               "--num-envs", "6"], capture_output=True, text=True, cwd=HERE,
                              timeout=600)
        self.assertEqual(done.returncode, 0, done.stdout[-3000:] + done.stderr[-3000:])
        with open(os.path.join(run, "evaluation.json")) as f:
            return json.load(f)

    def test_picks_the_best_snapshot_on_validation_seeds_and_reruns_identically(self):
        run = self.make_run()
        first = self.evaluate(run)
        val = first["validation"]
        self.assertGreater(val["v00002"]["score"], 0, "the scripted player returned no ball")
        self.assertEqual(val["v00001"]["score"], 0)
        # Scores of 0 or 1 per match are a rate with its Wilson 95% interval (v00001 returns no
        # ball); the scripted player's episodes can feed two balls (a quick first point leaves
        # time for a second), and then its score is a mean with 1.96 standard errors.
        self.assertEqual(val["v00001"]["score_rate_95"][0], 0.0)
        low, high = val["v00002"].get("score_rate_95") or val["v00002"]["score_mean_95"]
        self.assertLess(low, val["v00002"]["score_mean"])
        self.assertGreater(high, val["v00002"]["score_mean"])
        self.assertEqual(first["best"], 2, "not the best on the validation seeds")
        with open(os.path.join(run, "snapshots", "policy-best.safetensors"), "rb") as a, \
                open(os.path.join(run, "snapshots", "policy-v00002.safetensors"), "rb") as b:
            self.assertEqual(a.read(), b.read())
        test = first["test"]
        self.assertEqual(set(test), {"scripted", "best: v00002", "latest: v00003"})
        # The chosen snapshot is the scripted player plus zero: the same matches, the same score.
        self.assertEqual(test["best: v00002"], test["scripted"])
        self.assertEqual(test["best: v00002"]["matches"], 12)  # both ranges
        self.assertEqual(first["test_seeds"], [[101, 106], [201, 206]])
        # Match by match against the scripted player: the chosen one (scripted plus zero) differs
        # in none; the latest (zero alone, no ball returned) scores less wherever it scored.
        paired = first["test_against_scripted"]
        self.assertEqual(set(paired), {"best: v00002", "latest: v00003"})
        self.assertEqual((paired["best: v00002"]["mean"], paired["best: v00002"]["better"],
                          paired["best: v00002"]["worse"]), (0.0, 0, 0))
        latest = paired["latest: v00003"]
        self.assertAlmostEqual(latest["mean"], -test["scripted"]["score_mean"])
        self.assertGreater(latest["worse"], 0)
        self.assertEqual(latest["better"], 0)
        self.assertLess(latest["mean_95"][1], 0, "returning no ball is not within noise here")
        # Each test match's score per player, in seed order, adds up to the tables' figures.
        per_match = first["test_episodes"]
        self.assertEqual(set(per_match), set(test))
        for name, played in per_match.items():
            self.assertEqual([e["seed"] for e in played], [*range(101, 107), *range(201, 207)])
            self.assertEqual(sum(e["score"] for e in played), test[name]["score"], name)
        self.assertTrue(any(e["score"] > 0 for e in per_match["scripted"]))
        self.assertEqual(self.evaluate(run), first, "a rerun gave other tables")
        with open(os.path.join(run, "evaluation.md")) as f:
            self.assertIn("| best: v00002 | 12 |", f.read())

    def test_a_score_of_0_or_1_is_a_rate_others_a_mean_each_with_its_95_percent_interval(self):
        from smpl_olympics.evaluate import summary

        class OneTeam:
            others = []

        goals = summary([{"scores": [s]} for s in [1, 0, 0, 1, 1, 0, 0, 0, 0, 1]], OneTeam)
        self.assertNotIn("score_mean_95", goals)
        # Wilson interval of 4 in 10 (docs/figures.md): 16.8%-68.7%.
        self.assertAlmostEqual(goals["score_rate_95"][0], 0.1682, places=3)
        self.assertAlmostEqual(goals["score_rate_95"][1], 0.6873, places=3)
        balls = summary([{"scores": [s]} for s in [2, 0, 1, 1]], OneTeam)  # a 2: not a rate
        self.assertNotIn("score_rate_95", balls)
        half = 1.96 * np.std([2, 0, 1, 1], ddof=1) / 2
        self.assertAlmostEqual(balls["score_mean_95"][0], 1 - half)
        self.assertAlmostEqual(balls["score_mean_95"][1], 1 + half)

    def test_the_paired_difference_is_the_mean_of_the_per_seed_differences(self):
        from smpl_olympics.evaluate import paired_difference
        scripted = [{"seed": s, "scores": [v]} for s, v in ((1, 1), (2, 0), (3, 2), (4, 1))]
        snapshot = [{"seed": s, "scores": [v]} for s, v in ((3, 2), (1, 2), (4, 0), (2, 1))]
        d = paired_difference(snapshot, scripted)  # per seed: +1, +1, 0, -1 (any order)
        diffs = [1, 1, 0, -1]
        error = np.std(diffs, ddof=1) / 2
        self.assertAlmostEqual(d["mean"], 0.25)
        self.assertAlmostEqual(d["mean_95"][0], 0.25 - 1.96 * error)
        self.assertAlmostEqual(d["z"], 0.25 / error)
        self.assertEqual((d["matches"], d["better"], d["worse"]), (4, 2, 1))

    def test_overlapping_seeds_are_refused(self):
        done = subprocess.run([sys.executable, "-m", "smpl_olympics.evaluate", self.make_run(),
                               "--validation-seeds", "1-20", "--test-seeds", "10-30"],
                              capture_output=True, text=True, cwd=HERE)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("overlap", done.stderr)
        within = subprocess.run([sys.executable, "-m", "smpl_olympics.evaluate", self.make_run(),
                                 "--test-seeds", "1001-1020,1010-1030"],
                                capture_output=True, text=True, cwd=HERE)
        self.assertNotEqual(within.returncode, 0)
        self.assertIn("the ranges overlap", within.stderr)


if __name__ == "__main__":
    unittest.main()
