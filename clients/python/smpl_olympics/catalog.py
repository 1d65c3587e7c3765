"""What the server's sports are, without asking a server: the catalog that the build writes with
`olympics-server describe --json` (sports.json, shipped in this package). A mode's slots, teams,
vector sizes, observation blocks and their bounds come from here."""
import functools
import json
import os

import numpy as np

from .spaces import box


@functools.lru_cache(maxsize=1)
def catalog():
    with open(os.path.join(os.path.dirname(__file__), "sports.json")) as f:
        return {s["name"]: s for s in json.load(f)["sports"]}


def sport(name):
    sports = catalog()
    if name not in sports:
        raise ValueError(f"unknown sport {name!r}; known sports: {', '.join(sorted(sports))}")
    return sports[name]


def mode(sport_name, mode_name):
    """The mode's entry: slot_teams, obs_size, action_size, observation blocks, rewards, calls."""
    modes = {m["name"]: m for m in sport(sport_name)["modes"]}
    if mode_name not in modes:
        raise ValueError(f"sport {sport_name!r} has no mode {mode_name!r}; "
                         f"its modes: {', '.join(modes)}")
    return modes[mode_name]


def observation_space(spec):
    """A Box whose bounds admit every observation the server sends for this mode: the self block
    is clamped to +-5 by the server, the task blocks are not clamped (infinite bounds)."""
    bounds = np.concatenate([
        np.full(b["size"], np.inf if b["bound"] is None else b["bound"], dtype=np.float32)
        for b in spec["observation"]])
    return box(-bounds, bounds)


def action_space(spec):
    """Actions are in [-1, 1] (the server maps them to joint targets)."""
    size = spec["action_size"]
    return box(-np.ones(size, dtype=np.float32), np.ones(size, dtype=np.float32))
