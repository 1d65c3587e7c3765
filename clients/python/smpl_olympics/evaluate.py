"""Pick a run's best snapshot on held-out seeds, then measure it on other held-out seeds.

    python3 -m smpl_olympics.evaluate runs/tt --validation-seeds 1-200 --test-seeds 1001-2000,5001-5200

Every snapshot of the run (snapshots/policy-vNNNNN.safetensors) plays the validation seeds with
its mean action, as olympics-agent plays it (a residual snapshot on top of the scripted player);
the best by the mode's figure (ball return and other one-team modes: the score, e.g. balls
returned in; matches: the win rate, then the score) is copied to policy-best.safetensors and then
plays the test seeds beside the scripted player, which neither training (its seeds start at
10^6) nor the choice saw. Each player on the test seeds is also compared with the scripted player
match by match (the same seeds: a paired difference, its 95% interval and z), which tells a small
gain from noise where the two players' own intervals overlap. The latest snapshot is not the best as a rule: returns in swing by a
factor of five between snapshots 100 iterations apart (docs/training.md).

Deterministic: a match is its seed and the actions, and every player here acts from its
observations alone (restarted for each match), so the tables are the same on every rerun and
every machine. Writes evaluation.md (the tables) and evaluation.json (the tables' figures, and
each test match's seed and score per player, "test_episodes") into the run folder. The
opponent of a match mode is the run's --opponent when it is a policy the agent plays, else the
scripted player. Needs no server running: without --lcm-url each player's matches run on a
private server.
"""
import argparse
import json
import os
import re
import shutil
import sys

import numpy as np

from . import catalog
from ._client import NativePolicy
from .vector_env import OlympicsVectorEnv

SNAPSHOT = re.compile(r"policy-v(\d+)\.safetensors$")


def seed_range(text):
    """"A-B" -> range(A, B + 1)."""
    try:
        first, last = (int(x) for x in text.split("-"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"seeds {text!r}: write FIRST-LAST, e.g. 1-200")
    if not 0 < first <= last:
        raise argparse.ArgumentTypeError(f"seeds {text!r}: need 0 < FIRST <= LAST")
    return range(first, last + 1)


def seed_ranges(text):
    """"A-B,C-D" -> [range(A, B + 1), range(C, D + 1)]: one or more ranges, none overlapping."""
    ranges = [seed_range(part) for part in text.split(",")]
    seen = set()
    for r in ranges:
        if seen & set(r):
            raise argparse.ArgumentTypeError(f"seeds {text!r}: the ranges overlap")
        seen |= set(r)
    return ranges


def seeds_label(ranges):
    return ", ".join(f"{r.start}-{r.stop - 1}" for r in ranges)


def parse_args(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m smpl_olympics.evaluate", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run", help="the run folder (its args.json and snapshots/)")
    p.add_argument("--validation-seeds", type=seed_ranges, default=seed_ranges("1-200"),
                   help="seeds that choose the snapshot (default 1-200; ranges: 1-200,501-600)")
    p.add_argument("--test-seeds", type=seed_ranges, default=seed_ranges("1001-2000"),
                   help="seeds that measure the chosen one (default 1001-2000; ranges as above)")
    p.add_argument("--num-envs", type=int, default=16, help="matches played at once")
    p.add_argument("--lcm-url", default="", help="a server's LCM URL (default: a private one)")
    args = p.parse_args(argv)
    validation = {s for r in args.validation_seeds for s in r}
    test = {s for r in args.test_seeds for s in r}
    if validation & test:
        p.error("the validation and test seeds overlap: the test would see the choice's seeds")
    if max(validation | test) >= 10**6:
        p.error("seeds from 10^6 up are the trainer's: pick held-out ones below")
    return args


class Match:
    """The run's mode and who plays which slot: the learning team (team 0, or every slot in a
    one-team mode) and the opponent's."""

    def __init__(self, run_args):
        self.sport, self.mode = run_args["sport"], run_args["mode"]
        self.spec = catalog.mode(self.sport, self.mode)
        teams = self.spec["slot_teams"]
        self.learning = [s for s, t in enumerate(teams) if t == 0]
        self.others = [s for s, t in enumerate(teams) if t != 0]
        opponent = run_args.get("opponent") or "scripted"
        self.opponent = opponent if opponent.split(":")[0] in ("scripted", "zero", "random",
                                                              "mlp") else "scripted"
        self.time_limit_s = float(run_args.get("time_limit") or 0.0)
        options = run_args.get("options") or ""
        self.options = json.loads(options) if options else None

    def native(self, name, seed):
        return NativePolicy(name, self.sport, self.mode, self.spec["observation"],
                            self.spec["action_size"], float(self.spec["control_hz"]), seed)


def play(match, player, ranges, num_envs, lcm_url):
    """The results of `player` (team 0) against the opponent on every seed of these ranges, in
    their order."""
    return [r for seeds in ranges for r in play_range(match, player, seeds, num_envs, lcm_url)]


def play_range(match, player, seeds, num_envs, lcm_url):
    """The results of `player` (team 0) against the opponent on exactly these seeds. Without
    lcm_url, on a private server of this call's own: the matches begun past the last seed end
    with it (on a patient server they would hold its room for minutes)."""
    n = min(num_envs, len(seeds))
    env = OlympicsVectorEnv(n, sport=match.sport, mode=match.mode, seed=seeds.start,
                            time_limit_s=match.time_limit_s, sport_options=match.options,
                            lcm_url=lcm_url)
    # Environment e's k-th match has seed start + k*n + e: the players restart with each.
    players = [[match.native(player, seeds.start + e) for _ in match.learning] +
               [match.native(match.opponent, seeds.start + e) for _ in match.others]
               for e in range(n)]
    slots = match.learning + match.others
    wanted, got = set(seeds), {}
    quota = [len(range(seeds.start + e, seeds.stop, n)) for e in range(n)]
    ended, grace = [0] * n, 1000  # steps for the last results to come once all have ended
    try:
        obs, _ = env.reset()
        while not wanted <= set(got):
            if all(d >= q for d, q in zip(ended, quota)):
                grace -= 1
                if grace < 0:
                    missing = sorted(wanted - set(got))
                    raise RuntimeError(f"no result came for the matches of seeds {missing[:10]}")
            actions = np.zeros((n, len(slots), match.spec["action_size"]), np.float32)
            for e in range(n):
                for i, s in enumerate(slots):
                    actions[e, s] = players[e][i].act(obs[e, s])
            obs, _, _, _, infos = env.step(actions)
            for e in np.nonzero(infos["episode_over"])[0]:
                ended[e] += 1
                for p in players[e]:
                    p.restart()
            for r in env.results():
                if r["seed"] in wanted:
                    got[r["seed"]] = r
    finally:
        env.close()
    return [got[s] for s in seeds]


def wilson_95(k, n):
    """The Wilson score interval of k successes in n (docs/figures.md), as [low, high]."""
    z, p = 1.96, k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * np.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return [float(max(0.0, centre - half)), float(min(1.0, centre + half))]


def summary(results, match):
    """The learning team's figures over these matches, with 95% intervals (docs/figures.md): where
    every match scores 0 or 1 (a goal or not) the score per match is a rate (Wilson interval),
    else a mean (1.96 standard errors)."""
    scores = [r["scores"][0] for r in results]
    out = {"matches": len(results), "score": float(np.sum(scores)),
           "score_mean": float(np.mean(scores))}
    if all(s in (0, 1) for s in scores):
        out["score_rate_95"] = wilson_95(int(np.sum(scores)), len(scores))
    else:  # e.g. a ball return whose episode fed two balls: a mean, +-1.96 standard errors
        half = 1.96 * float(np.std(scores, ddof=1)) / np.sqrt(len(scores)) if len(scores) > 1 else 0.0
        out["score_mean_95"] = [out["score_mean"] - half, out["score_mean"] + half]
    if match.others:
        out["wins"] = sum(r["winner_team"] == 0 for r in results)
        out["losses"] = sum(r["winner_team"] not in (0, -1) for r in results)
        out["win_rate"] = out["wins"] / len(results)
        out["win_rate_95"] = wilson_95(out["wins"], len(results))
    return out


def paired_difference(results, baseline):
    """The learning team's score minus the baseline's, match by match on the same seeds: the mean
    difference with 1.96 standard errors, z (mean over its standard error) and how many matches
    scored more or less. Pairing removes what the seed decides for both players alike."""
    base = {r["seed"]: r["scores"][0] for r in baseline}
    diffs = np.array([r["scores"][0] - base[r["seed"]] for r in results], dtype=float)
    mean = float(np.mean(diffs))
    error = float(np.std(diffs, ddof=1)) / np.sqrt(len(diffs)) if len(diffs) > 1 else 0.0
    return {"matches": len(diffs), "mean": mean,
            "mean_95": [mean - 1.96 * error, mean + 1.96 * error],
            "z": mean / error if error > 0 else 0.0,
            "better": int(np.sum(diffs > 0)), "worse": int(np.sum(diffs < 0))}


def episodes(results):
    """Each match's seed and the learning team's score, in seed order: what a reader needs for
    figures over a part of the test seeds (one range of several) or for another pairing."""
    return [{"seed": r["seed"], "score": r["scores"][0]} for r in results]


def paired_table(rows):
    lines = ["| player | matches | score minus the scripted player's, per match (95% interval) | z "
             "| matches better | matches worse |", "|---|---|---|---|---|---|"]
    for name, d in rows:
        lines.append(f"| {name} | {d['matches']} | {d['mean']:+.3f} ({d['mean_95'][0]:+.3f} to "
                     f"{d['mean_95'][1]:+.3f}) | {d['z']:.1f} | {d['better']} | {d['worse']} |")
    return "\n".join(lines)


def rate(value, interval):
    return f"{100 * value:.1f}% ({100 * interval[0]:.1f}-{100 * interval[1]:.1f}%)"


def figure(s):
    """What the choice maximises: the win rate for matches (then the score), the score else."""
    return (s.get("win_rate", 0.0), s["score_mean"])


def table(rows, match):
    head = ("| player | matches | score | score per match (95% interval) |" +
            (" wins | losses | win rate (95% interval) |" if match.others else ""))
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for name, s in rows:
        per_match = (rate(s["score_mean"], s["score_rate_95"]) if "score_rate_95" in s else
                     f"{s['score_mean']:.3f} ({s['score_mean_95'][0]:.3f}-{s['score_mean_95'][1]:.3f})")
        line = f"| {name} | {s['matches']} | {s['score']:g} | {per_match} |"
        if match.others:
            line += f" {s['wins']} | {s['losses']} | {rate(s['win_rate'], s['win_rate_95'])} |"
        lines.append(line)
    return "\n".join(lines)


def main(argv=None):
    args = parse_args(argv)
    with open(os.path.join(args.run, "args.json")) as f:
        match = Match(json.load(f))
    folder = os.path.join(args.run, "snapshots")
    snapshots = sorted((int(m.group(1)), os.path.join(folder, name))
                       for name in os.listdir(folder) if (m := SNAPSHOT.match(name)))
    if not snapshots:
        sys.exit(f"no snapshots/policy-vNNNNN.safetensors in {args.run}: train first")
    val = args.validation_seeds
    print(f"{match.sport} {match.mode}: {len(snapshots)} snapshots on validation seeds "
          f"{seeds_label(val)}" + (f", against {match.opponent}" if match.others else ""))
    chosen = {}
    for version, path in snapshots:
        chosen[version] = summary(play(match, f"mlp:{path}", val, args.num_envs, args.lcm_url),
                                  match)
        print(f"  v{version:05d}: {chosen[version]}", flush=True)
    best = max(chosen, key=lambda v: (figure(chosen[v]), -v))  # a tie: the earlier snapshot
    best_path = os.path.join(folder, "policy-best.safetensors")
    shutil.copyfile(dict(snapshots)[best], best_path)
    test = args.test_seeds
    players = [("scripted", "scripted"), (f"best: v{best:05d}", f"mlp:{best_path}")]
    latest = snapshots[-1][0]
    if latest != best:
        players.append((f"latest: v{latest:05d}", f"mlp:{snapshots[-1][1]}"))
    results = {name: play(match, player, test, args.num_envs, args.lcm_url)
               for name, player in players}
    measured = [(name, summary(results[name], match)) for name, _ in players]
    paired = [(name, paired_difference(results[name], results["scripted"]))
              for name, _ in players[1:]]
    report = (f"Validation seeds {seeds_label(val)} (choose the snapshot):\n\n" +
              table([(f"v{v:05d}", s) for v, s in chosen.items()], match) +
              f"\n\nTest seeds {seeds_label(test)} (measure it):\n\n" +
              table(measured, match) +
              "\n\nAgainst the scripted player on the same test seeds (paired):\n\n" +
              paired_table(paired) + "\n")
    with open(os.path.join(args.run, "evaluation.md"), "w") as f:
        f.write(report)
    with open(os.path.join(args.run, "evaluation.json"), "w") as f:
        json.dump({"validation_seeds": [[r.start, r.stop - 1] for r in val],
                   "test_seeds": [[r.start, r.stop - 1] for r in test], "best": best,
                   "validation": {f"v{v:05d}": s for v, s in chosen.items()},
                   "test": dict(measured), "test_against_scripted": dict(paired),
                   "test_episodes": {name: episodes(results[name]) for name, _ in players}},
                  f, indent=1)
    print("\n" + report + f"\nchosen: {best_path}")


if __name__ == "__main__":
    main()
