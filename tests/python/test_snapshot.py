"""Snapshots written by the Python exporter run the same in C++ (olympics-snapshot, olympics-agent)."""
import os
import subprocess
import tempfile
import unittest

import numpy as np

from smpl_olympics.snapshot import export_mlp

from server_process import BIN, start_server


def forward(layers, x, mean, std):
    x = (x - mean) / std
    for i, (w, b) in enumerate(layers):
        x = w @ x + b
        if i + 1 < len(layers):
            x = x / (1 + np.exp(-x))  # silu
    return x


class SnapshotRoundTrip(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="olympics-snap-")
        rng = np.random.default_rng(5)
        sizes = [366, 64, 32, 69]
        self.layers = [(rng.normal(0, 0.2, (o, i)).astype(np.float32), rng.normal(0, 0.1, o).astype(np.float32))
                       for i, o in zip(sizes[:-1], sizes[1:])]
        self.mean = rng.normal(0, 1, 366).astype(np.float32)
        self.std = rng.uniform(0.5, 2, 366).astype(np.float32)
        self.path = export_mlp(self.layers, os.path.join(self.dir, "p.safetensors"), activation="silu",
                               obs_mean=self.mean, obs_std=self.std, policy_id="test", policy_version="3")

    def test_cpp_computes_what_numpy_computes(self):
        rng = np.random.default_rng(6)
        obs = rng.normal(0, 2, (3, 366)).astype(np.float32)
        text = "\n".join(" ".join(f"{v:.9g}" for v in row) for row in obs) + "\n"
        out = subprocess.run([f"{BIN}/olympics-snapshot", "eval", self.path], input=text, capture_output=True,
                             text=True, check=True).stdout
        got = np.array([[float(v) for v in line.split()] for line in out.strip().splitlines()])
        want = np.stack([forward(self.layers, row, self.mean, self.std) for row in obs])
        self.assertEqual(got.shape, (3, 69))
        np.testing.assert_allclose(got, want, rtol=1e-4, atol=1e-5)
        inspected = subprocess.run([f"{BIN}/olympics-snapshot", "inspect", self.path], capture_output=True,
                                   text=True, check=True).stdout
        self.assertIn("MLP 366 -> 64 -> 32 -> 69, silu", inspected)
        self.assertIn("policy_version: 3", inspected)

    def test_a_pytorch_mlp_exports_and_runs_the_same_in_cpp(self):
        try:
            import torch
        except ImportError:
            self.skipTest("python3-torch is not installed (deploy/test.sh installs it)")
        torch.manual_seed(0)
        net = torch.nn.Sequential(torch.nn.Linear(366, 48), torch.nn.SiLU(), torch.nn.Linear(48, 48),
                                  torch.nn.SiLU(), torch.nn.Linear(48, 69))
        path = export_mlp(net, os.path.join(self.dir, "torch.safetensors"), policy_id="torch")
        obs = torch.randn(2, 366)
        with torch.no_grad():
            want = net(obs).numpy()
        text = "\n".join(" ".join(f"{v:.9g}" for v in row) for row in obs.numpy()) + "\n"
        out = subprocess.run([f"{BIN}/olympics-snapshot", "eval", path], input=text, capture_output=True,
                             text=True, check=True).stdout
        got = np.array([[float(v) for v in line.split()] for line in out.strip().splitlines()])
        np.testing.assert_allclose(got, want, rtol=1e-4, atol=1e-5)

    def test_bad_snapshots_say_what_is_wrong(self):
        bad = os.path.join(self.dir, "bad.safetensors")
        with open(bad, "wb") as f:
            f.write(b"\x05\x00\x00\x00\x00\x00\x00\x00{}")
        run = subprocess.run([f"{BIN}/olympics-snapshot", "inspect", bad], capture_output=True, text=True)
        self.assertEqual(run.returncode, 2)
        self.assertIn("the header length points past the end", run.stderr)
        wrong = export_mlp([(np.zeros((4, 3)), np.zeros(4)), (np.zeros((2, 4)), np.zeros(2))],
                           os.path.join(self.dir, "small.safetensors"))
        with self.assertRaises(ValueError):
            export_mlp([(np.zeros((4, 3)), np.zeros(4)), (np.zeros((2, 5)), np.zeros(2))], bad)
        run = subprocess.run([f"{BIN}/olympics-snapshot", "eval", wrong], input="1 2\n", capture_output=True,
                             text=True)
        self.assertEqual(run.returncode, 2)
        self.assertIn("takes 3 observation floats, got 2", run.stderr)

    def test_agent_plays_a_match_with_the_snapshot(self):
        url = f"udpm://239.255.76.67:{23000 + os.getpid() % 5000}?ttl=0&recv_buf_size=4194304"
        server = start_server(url, os.path.join(self.dir, "r.db"), "snap",
                              os.path.join(self.dir, "server.log"))
        try:
            common = [f"--lcm-url={url}", "--request-id=s", "--json", "--timeout=30"]
            opponent = subprocess.Popen([f"{BIN}/olympics-agent", *common, "--slots=1", "--policy=zero"],
                                        stdout=subprocess.PIPE, text=True)
            mine = subprocess.run([f"{BIN}/olympics-agent", *common, "--slots=0", f"--policy=mlp:{self.path}",
                                   "--name=snapshot"], capture_output=True, text=True, timeout=60)
            opponent.communicate(timeout=60)
            self.assertEqual(mine.returncode, 0, mine.stderr)
            self.assertIn('"snapshot"', mine.stdout)
        finally:
            server.kill()
            server.wait()


if __name__ == "__main__":
    unittest.main()
