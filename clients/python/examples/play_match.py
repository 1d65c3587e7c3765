#!/usr/bin/env python3
"""Plays sandbox matches against an olympics-agent process with a random numpy policy.

    olympics-server serve &                                   # a server on the default LCM URL
    olympics-agent --request-id example-0 --slots 1 --policy zero &   # the opponent
    python3 clients/python/examples/play_match.py --request-id example
"""
import argparse

import numpy as np

from smpl_olympics import OlympicsParallelEnv


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--request-id", default="example")
    parser.add_argument("--lcm-url", default="")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()

    env = OlympicsParallelEnv(sport="sandbox", mode="1v1", slots=[0], request_id=args.request_id,
                              lcm_url=args.lcm_url, agent_name="numpy-random")
    rng = np.random.default_rng(args.seed)
    observations, infos = env.reset(seed=args.seed)
    total = 0.0
    while env.agents:
        actions = {a: rng.uniform(-1, 1, env.action_size(a)).astype(np.float32) for a in env.agents}
        observations, rewards, terminations, truncations, infos = env.step(actions)
        total += sum(rewards.values())
    r = env.result
    print(f"match {r['match_id']}: {r['reason']} after {r['ticks']} ticks; scores {r['scores']}; "
          f"winner team {r['winner_team']}; our return {total:.1f}")


if __name__ == "__main__":
    main()
