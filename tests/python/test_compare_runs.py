"""smpl_olympics.compare_runs on run folders made here (no server): identical runs pass, one
changed bit of a tensor, a changed metric or a changed evaluation fails, what is allowed to
vary (wall time, policy_id, results counted as they arrived) does not."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from smpl_olympics.compare_runs import compare
from smpl_olympics.snapshot import export_mlp

COLUMNS = ["iteration", "samples", "wall_s", "samples_per_s", "score", "episode_return"]


def make_run(folder, policy_id, weight=0.5, wall_s=1.0, score=0.25, ret=3.0):
    os.makedirs(os.path.join(folder, "snapshots"))
    layers = [(np.full((4, 3), weight, np.float32), np.zeros(4, np.float32)),
              (np.ones((2, 4), np.float32), np.zeros(2, np.float32))]
    for v in (1, 2):
        export_mlp(layers, os.path.join(folder, "snapshots", f"policy-v{v:05d}.safetensors"),
                   activation="silu", policy_id=policy_id, policy_version=str(v))
    with open(os.path.join(folder, "metrics.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        w.writerow([1, 2048, wall_s, 2048 / wall_s, score, ret])
    with open(os.path.join(folder, "evaluation.json"), "w") as f:
        f.write('{"best": 2}')
    return folder


class CompareRuns(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="olympics-compare-")
        self.addCleanup(shutil.rmtree, self.root)
        self.a = make_run(os.path.join(self.root, "a"), "a")

    def test_runs_that_differ_only_where_runs_may_vary_are_identical(self):
        b = make_run(os.path.join(self.root, "b"), "b", wall_s=7.5, score=0.5)
        problems, notes, summary = compare(self.a, b)
        self.assertEqual(problems, [])
        self.assertEqual(len(notes), 1, notes)  # the score column, reported, not failed
        self.assertIn("2 snapshots, 8 tensors", summary)
        self.assertEqual(len(compare(self.a, b, strict=True)[0]), 1)

    def test_one_changed_bit_of_a_tensor_fails(self):
        b = make_run(os.path.join(self.root, "b"), "b", weight=np.nextafter(np.float32(0.5), np.float32(1)))
        problems, _, _ = compare(self.a, b)
        self.assertEqual(len(problems), 2, problems)  # layers.0.weight of both snapshots
        self.assertTrue(all("layers.0.weight" in p for p in problems), problems)

    def test_a_changed_metric_or_evaluation_fails(self):
        b = make_run(os.path.join(self.root, "b"), "b", ret=3.0000001)
        with open(os.path.join(b, "evaluation.json"), "w") as f:
            f.write('{"best": 1}')
        problems, _, _ = compare(self.a, b)
        self.assertEqual(len(problems), 2, problems)
        self.assertTrue(any("episode_return" in p for p in problems), problems)
        self.assertTrue(any("evaluation.json" in p for p in problems), problems)

    def test_the_command_exits_1_on_a_difference_and_names_it(self):
        b = make_run(os.path.join(self.root, "b"), "b", weight=0.25)
        done = subprocess.run([sys.executable, "-m", "smpl_olympics.compare_runs", self.a, b],
                              capture_output=True, text=True, timeout=60)
        self.assertEqual(done.returncode, 1, done.stdout + done.stderr)
        self.assertIn("DIFFERS: policy-v00001.safetensors layers.0.weight", done.stdout)
        done = subprocess.run([sys.executable, "-m", "smpl_olympics.compare_runs", self.a,
                               self.root], capture_output=True, text=True, timeout=60)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("not a run folder", done.stderr)


if __name__ == "__main__":
    unittest.main()
