#!/usr/bin/env python3
"""Python's OlympicsVectorEnv against the C++ VectorClient, side by side on one server process:
agent-steps/s of each, alternating, and their ratio (the target is >= 0.9).

    PYTHONPATH=build/python python3 benchmarks/vector_env_bench.py [--envs 16] [--seconds 6] [--json]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from smpl_olympics import OlympicsVectorEnv

BIN = os.environ.get("OLYMPICS_BIN_DIR", os.path.join(os.path.dirname(__file__), "..", "build", "bin"))


def python_agent_steps(env, seconds):
    zero = np.zeros((env.num_envs, env.num_agents, env.action_size), np.float32)
    steps, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        env.step(zero)
        steps += env.num_envs * env.num_agents
    return steps / (time.perf_counter() - start)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--envs", type=int, default=16)
    parser.add_argument("--seconds", type=float, default=6.0)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    folder = tempfile.mkdtemp(prefix="olympics-vector-env-bench-")
    url = f"udpm://239.255.76.67:{26000 + os.getpid() % 9000}?ttl=0&recv_buf_size=8388608"
    with open(os.path.join(folder, "server.log"), "w") as log:
        server = subprocess.Popen([f"{BIN}/olympics-server", "serve", "--lcm-url", url, "--results",
                                   os.path.join(folder, "results.db"), "--id", "vbench",
                                   "--capacity", str(args.envs * 8)], stdout=log, stderr=log)
    try:
        time.sleep(1.0)
        env = OlympicsVectorEnv(args.envs, sport="sandbox", mode="1v1", seed=1, time_limit_s=20.0,
                                lcm_url=url)
        env.reset()
        python_agent_steps(env, 0.5)
        rounds, py, cpp = 3, [], []
        for _ in range(rounds):  # alternating, so the machine's noise hits both alike
            py.append(python_agent_steps(env, args.seconds / rounds))
            out = subprocess.run([f"{BIN}/olympics-bench", "vector", "--json", "--connect", url,
                                  "--envs", str(args.envs), "--seconds", str(args.seconds / rounds)],
                                 check=True, capture_output=True, text=True).stdout
            cpp.append(json.loads(out)["vector_agent_steps_per_s"])
        ratios = [p / c for p, c in zip(py, cpp)]
        report = {"scene": "sandbox 1v1, zero actions, sync mode, one olympics-server process",
                  "envs": args.envs, "python_agent_steps_per_s": float(np.median(py)),
                  "cpp_agent_steps_per_s": float(np.median(cpp)),
                  "ratio_python_over_cpp": float(np.median(ratios)), "ratios": ratios}
    finally:
        server.kill()
        server.wait()
    if args.json:
        print(json.dumps(report, indent=2))
    else:
        print(f"vector env: {report['scene']}, {args.envs} matches in one client")
        print(f"  Python OlympicsVectorEnv {report['python_agent_steps_per_s']:9.0f} agent-steps/s")
        print(f"  C++ VectorClient         {report['cpp_agent_steps_per_s']:9.0f} agent-steps/s")
        print(f"  ratio                    {report['ratio_python_over_cpp']:9.2f} (median of "
              f"{', '.join(f'{r:.2f}' for r in ratios)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
