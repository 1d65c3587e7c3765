"""Steps per second of the Python vector environment (OlympicsVectorEnv) on whatever server its
LCM URL reaches: run it inside a cell and on a learner's host through olympics-relay
(tests/fleet/remote_learner_test.sh does both) to see what the relay costs a trainer.

    PYTHONPATH=build/python python3 benchmarks/relay_vector_bench.py ENVS STEPS SECRET_FILE
"""
import sys
import time

import numpy as np
from smpl_olympics.vector_env import OlympicsVectorEnv


def main(envs, steps, secret_file):
    # Tennis: a match lasts its time limit whatever the players do, so every step is a step.
    # LCM's default URL: the cell's server, or the relay carrying its traffic to this host.
    env = OlympicsVectorEnv(envs, sport="tennis", mode="1v1", seed=1, time_limit_s=600,
                            secret_file=secret_file, lcm_url="udpm://239.255.76.67:7667?ttl=0")
    env.reset()
    actions = np.zeros(env.action_space.shape, np.float32)
    env.step(actions)  # the first step waits for every match to start
    start = time.perf_counter()
    for _ in range(steps):
        infos = env.step(actions)[-1]
    seconds = time.perf_counter() - start
    env.close()
    print(f"{envs} envs x {steps} steps: {seconds:.2f} s, {envs * steps / seconds:.0f} "
          f"env-steps/s, {1000 * seconds / steps:.2f} ms per step (ticks now "
          f"{np.asarray(infos['tick']).tolist()})")


if __name__ == "__main__":
    main(int(sys.argv[1]), int(sys.argv[2]), sys.argv[3])
