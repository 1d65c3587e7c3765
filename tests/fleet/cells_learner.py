"""The learner of tests/fleet/learner_cells_test.sh: a CellsVectorEnv over the cells whose relays'
learner-side LCM URLs are given, stepping until told to stop (a file appears) or a deadline; the
steps so far go to a file as it runs, and a JSON summary (steps after the first loss, lost
matches, the environments' cells at the end, ticks) is printed at the end.

    PYTHONPATH=build/python python3 tests/fleet/cells_learner.py SECRET WORK URL1 URL2 ...
"""
import json
import os
import sys
import time

import numpy as np
from smpl_olympics.cells_vector_env import CellsVectorEnv


def main(secret, work, urls):
    env = CellsVectorEnv(urls, 2, seed=5, sport="tennis", mode="1v1", time_limit_s=600,
                         secret_file=secret, timeout_s=20)
    env.reset()
    actions = np.zeros((env.num_envs, env.num_agents, env.action_size), np.float32)
    steps, steps_after_loss, lost, deadline, longest = 0, 0, [], time.time() + 150, 0.0
    while not os.path.exists(f"{work}/stop") and time.time() < deadline:
        began = time.perf_counter()
        _, _, _, _, infos = env.step(actions)
        longest = max(longest, time.perf_counter() - began)
        lost += infos["lost"]
        steps += 1
        steps_after_loss += 1 if lost else 0
        if steps % 20 == 0:
            with open(f"{work}/learner-steps.tmp", "w") as f:
                f.write(f"{steps} {steps_after_loss}\n")
            os.replace(f"{work}/learner-steps.tmp", f"{work}/learner-steps")
        last_ticks = infos["tick"].tolist()
    print(json.dumps({"steps": steps, "steps_after_loss": steps_after_loss, "lost": lost,
                      "lost_matches": env.lost_matches(), "cells_now": env.env_cells(),
                      "ticks": last_ticks, "longest_step_s": round(longest, 2)}))
    env.close()


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
