"""One trainer's environments spread over several cells: CellsVectorEnv (docs/deploy.md).

Each cell is a host (or pod) with its own olympics-server, reached from the learner's host through
its own relay (`olympics-relay connect --to CELL:7700 --lcm-url URL` on a learner-side LCM port per
cell). The environments are split over the cells (an OlympicsVectorEnv per cell) and batched as
one: the arrays are OlympicsVectorEnv's, [num_envs, num_agents, ...].

A cell that is lost (its server stopped announcing itself: SERVER_GONE or SERVER_RESTARTED; its
matches silent for timeout_s: TIMEOUT) does not stop the learner: its environments start their
next matches on the cells left (the least loaded that has room), and the matches lost are
reported, not hidden. The step that finds the loss returns, for those environments, the new
match's first observation with episode_over and truncated set (as any match that ends) and no
final observation (zeros); infos["lost"] lists them ({"env", "cell", "match_id", "error"}), and
lost_matches() keeps every one. Only when no cell is left, or none has room, does step() raise
MatchError, naming every cell's error.

Seeds: each cell's share of the environments (and each share moved) plays from a base seed of its
own derived from `seed`, so two cells never play the same sequence of match seeds.
"""
import numpy as np

from ._client import MatchError
from .servers import find_servers
from .spaces import box
from .vector_env import OlympicsVectorEnv

# Errors that mean a cell (its server, or the way to it) is gone, not a bad request.
CELL_LOST = ("SERVER_GONE", "SERVER_RESTARTED", "TIMEOUT")


def _code(error):
    return str(error).split(":", 1)[0]


class _Part:
    """An OlympicsVectorEnv on one cell, playing some of the environments (rows)."""

    def __init__(self, cell, rows, env):
        self.cell, self.rows, self.env = cell, list(rows), env


class CellsVectorEnv:
    def __init__(self, cells, envs_per_cell, seed=0, **kwargs):
        """cells: the learner-side LCM URL of each cell's relay (or dicts of lcm_url and
        server_id); envs_per_cell: environments on each (an int, or one per cell). kwargs go to
        every OlympicsVectorEnv (sport, mode, slots, time_limit_s, secret_file, timeout_s, ...)."""
        self.cells = [c if isinstance(c, dict) else {"lcm_url": c, "server_id": ""} for c in cells]
        if not self.cells:
            raise ValueError("CellsVectorEnv needs at least one cell (its relay's lcm_url)")
        counts = envs_per_cell if isinstance(envs_per_cell, (list, tuple)) else \
            [int(envs_per_cell)] * len(self.cells)
        if len(counts) != len(self.cells) or min(counts) < 1:
            raise ValueError(f"envs_per_cell: one count >= 1 per cell ({len(self.cells)}), "
                             f"got {envs_per_cell}")
        self.num_envs = sum(counts)
        self.seed, self._kwargs = int(seed), kwargs
        self._lost, self._errors, self._moves = [], {}, 0
        self._moved = []  # (part, first observations) of environments moved this step
        self._parts, row = [], 0
        for cell, n in zip(self.cells, counts):
            self._parts.append(_Part(cell, range(row, row + n), self._env_on(cell, n, row)))
            row += n
        first = self._parts[0].env
        self.num_agents, self.agents = first.num_agents, first.agents
        self.obs_size, self.action_size = first.obs_size, first.action_size
        self.single_observation_space = first.single_observation_space
        self.single_action_space = first.single_action_space
        shape = (self.num_envs, self.num_agents)
        self.observation_space = box(
            np.broadcast_to(first.single_observation_space.low, shape + (self.obs_size,)),
            np.broadcast_to(first.single_observation_space.high, shape + (self.obs_size,)))
        self.action_space = box(-np.ones(shape + (self.action_size,), np.float32),
                                np.ones(shape + (self.action_size,), np.float32))

    def _env_on(self, cell, n, first_row):
        # Each cell's share (and each move) its own base seed, derived from the env's seed: the
        # shares' seed sequences (base + k * n + e) would overlap if the bases were seed + row.
        words = np.random.SeedSequence([self.seed, first_row, self._moves]).generate_state(2)
        base = (int(words[0]) << 8 | int(words[1]) & 0xFF) % (1 << 40)
        return OlympicsVectorEnv(n, seed=base,
                                 lcm_url=cell["lcm_url"], server_id=cell.get("server_id", ""),
                                 **self._kwargs)

    def reset(self, seed=None):
        """Every environment's first match on its cell: (observations, infos with match_ids)."""
        if seed is not None:
            self.seed = int(seed)
        obs = np.zeros((self.num_envs, self.num_agents, self.obs_size), np.float32)
        match_ids = [""] * self.num_envs
        for part in self._parts:
            o, info = part.env.reset()
            obs[part.rows] = o
            for i, r in enumerate(part.rows):
                match_ids[r] = info["match_ids"][i]
        return obs, {"match_ids": match_ids}

    def step(self, actions):
        """actions [num_envs, num_agents, action_size] -> observations, rewards, terminations,
        truncations, infos (as OlympicsVectorEnv's, plus "lost": the matches lost this step)."""
        actions = np.asarray(actions, np.float32)
        n, a = self.num_envs, self.num_agents
        obs = np.zeros((n, a, self.obs_size), np.float32)
        final = np.zeros_like(obs)
        reward = np.zeros((n, a), np.float32)
        terminated = np.zeros((n, a), bool)
        truncated = np.zeros((n, a), bool)
        episode_over = np.zeros(n, bool)
        tick = np.zeros(n, np.int64)
        terms, lost_now = None, []
        for part in list(self._parts):  # every cell plays its share at once
            try:
                part.env.send(actions[part.rows])
            except MatchError as error:
                lost_now += self._lose(part, error)
        for part in list(self._parts):
            if any(part is moved for moved, _ in self._moved):
                continue  # moved here this step: it starts below
            try:
                ids, o, r, te, tr, info = part.env.recv(min_ready=len(part.rows))
            except MatchError as error:
                lost_now += self._lose(part, error)
                continue
            rows = [part.rows[i] for i in ids]
            obs[rows], reward[rows], terminated[rows], truncated[rows] = o, r, te, tr
            final[rows] = info["final_observation"]
            episode_over[rows] = info["episode_over"]
            tick[rows] = info["tick"]
            if terms is None:
                terms = np.zeros((n, a, info["reward_terms"].shape[-1]), np.float32)
                self.term_names = info["term_names"]
            terms[rows] = info["reward_terms"]
        for part, first in self._moved:  # environments moved to another cell: new matches
            obs[part.rows] = first
            episode_over[part.rows] = True
            truncated[part.rows] = True
        self._moved = []
        if terms is None:
            terms = np.zeros((n, a, 0), np.float32)
        infos = {"reward_terms": terms, "term_names": getattr(self, "term_names", []),
                 "episode_over": episode_over, "final_observation": final, "tick": tick,
                 "lost": lost_now}
        return obs, reward, terminated, truncated, infos

    def _lose(self, part, error):
        """Drops a cell whose error says it is gone; its environments go to the cells left."""
        if _code(error) not in CELL_LOST:
            raise error
        self._errors[part.cell["lcm_url"]] = str(error)
        self._parts.remove(part)
        lost = []
        for r in part.rows:
            try:
                match_id = part.env.match_id(r - part.rows[0])
            except Exception:  # noqa: BLE001 - a match never created has no id
                match_id = ""
            lost.append({"env": r, "cell": part.cell["lcm_url"], "match_id": match_id,
                         "error": str(error)})
        self._lost += lost
        part.env.close()
        self._moves += 1
        tried = []
        for cell, free in self._room_left():  # the cell with the most room first
            if free < len(part.rows):
                tried.append(f"{cell['lcm_url']}: {free} free")
                continue
            try:
                moved = _Part(cell, part.rows, self._env_on(cell, len(part.rows), part.rows[0]))
                first, _ = moved.env.reset()
            except MatchError as refused:
                tried.append(f"{cell['lcm_url']}: {refused}")
                continue
            self._parts.append(moved)
            self._moved.append((moved, first))
            return lost
        raise MatchError(
            f"{_code(error)}: every cell of this env is lost or full: "
            + "; ".join(f"{url}: {why}" for url, why in self._errors.items())
            + ("; no room for the lost environments on " + "; ".join(tried) if tried else ""))

    def env_cells(self):
        """The cell (its lcm_url) each environment plays on now, by environment."""
        cells = [""] * self.num_envs
        for part in self._parts:
            for r in part.rows:
                cells[r] = part.cell["lcm_url"]
        return cells

    def _room_left(self):
        """(cell, matches it has room for) of the cells still played, the roomiest first (from
        their servers' announcements; a cell not heard has none)."""
        cells = {p.cell["lcm_url"]: p.cell for p in self._parts}
        room = []
        for url, cell in cells.items():
            try:
                servers = find_servers(url, self._kwargs.get("secret_file", ""),
                                       cell.get("server_id", ""))
                free = sum(s["capacity"] - s["active_matches"] for s in servers)
            except MatchError:
                free = 0
            room.append((cell, free))
        return sorted(room, key=lambda cell_free: -cell_free[1])

    def lost_matches(self):
        """Every match lost with its cell so far: dicts of env, cell, match_id, error."""
        return list(self._lost)

    def results(self):
        """Results of the matches that ended since the last call, from every cell."""
        out = []
        for part in self._parts:
            out += part.env.results()
        return out

    def close(self):
        for part in self._parts:
            part.env.close()
        self._parts = []
