"""A Gymnasium single-agent env over a one-slot mode (ball returns, a penalty kick, a free throw,
the sandbox's solo): OlympicsGymEnv, and the ids it is registered under for gymnasium.make.

    import gymnasium, smpl_olympics
    env = gymnasium.make("smpl_olympics/TableTennisBallReturn-v0", lcm_url=URL)
    observation, info = env.reset(seed=0)

Each episode is a match played over an OlympicsParallelEnv that owns the mode's one slot; the
match's end (the sport's time limit, or its rules) terminates or truncates it, as the server says.
reset(seed=s) plays the match with seed s; later resets without a seed play seeds drawn from s,
so a seeded env replays the same matches.
"""
import gymnasium
import numpy as np

from . import catalog
from .env import OlympicsParallelEnv

ID_PREFIX = "smpl_olympics/"


def one_slot_modes():
    """(sport, mode) of every mode with one slot, from the catalog."""
    return [(s, m["name"]) for s in sorted(catalog.catalog()) for m in catalog.sport(s)["modes"]
            if len(m["slot_teams"]) == 1]


def env_id(sport, mode):
    """"smpl_olympics/TableTennisBallReturn-v0" for table_tennis/ball_return."""
    camel = "".join(w.capitalize() for w in f"{sport}_{mode}".split("_"))
    return f"{ID_PREFIX}{camel}-v0"


class OlympicsGymEnv(gymnasium.Env):
    metadata = {"render_modes": []}

    def __init__(self, sport="table_tennis", mode="ball_return", render_mode=None, **env_kwargs):
        """env_kwargs go to OlympicsParallelEnv (lcm_url, time_limit_s, sport_options, ...)."""
        if render_mode is not None:
            raise ValueError(f"render_mode {render_mode!r}: this env draws nothing; watch the "
                             "match's replay (docs/clients.md)")
        slots = len(catalog.mode(sport, mode)["slot_teams"])
        if slots != 1:
            modes = ", ".join(f"{s}/{m}" for s, m in one_slot_modes())
            raise ValueError(f"{sport}/{mode} has {slots} slots; a single-agent env plays a "
                             f"one-slot mode ({modes}): use OlympicsParallelEnv for the others")
        self.parallel_env = OlympicsParallelEnv(sport=sport, mode=mode, **env_kwargs)
        self.agent = self.parallel_env.possible_agents[0]
        self.observation_space = self.parallel_env.observation_space(self.agent)
        self.action_space = self.parallel_env.action_space(self.agent)
        self.render_mode = None
        self._match_seeds = None  # drawn from the last reset's seed, for resets without one

    def reset(self, seed=None, options=None):
        super().reset(seed=seed)
        if seed is not None:
            self._match_seeds = np.random.default_rng(seed)
            match_seed = seed
        elif self._match_seeds is not None:
            match_seed = int(self._match_seeds.integers(1 << 62))
        else:
            match_seed = None  # a fresh one (env.parallel_env.description["seed"] says which)
        observations, infos = self.parallel_env.reset(seed=match_seed, options=options)
        return observations[self.agent], infos[self.agent]

    def step(self, action):
        observations, rewards, terminations, truncations, infos = self.parallel_env.step(
            {self.agent: action})
        a = self.agent
        return observations[a], rewards[a], terminations[a], truncations[a], infos[a]

    @property
    def result(self):
        """The ended match's result (scores, reason, ...), as OlympicsParallelEnv.result."""
        return self.parallel_env.result

    def close(self):
        self.parallel_env.close()


def register_all():
    """Registers every one-slot mode under env_id(sport, mode) (import smpl_olympics does)."""
    for sport, mode in one_slot_modes():
        if env_id(sport, mode) not in gymnasium.registry:
            gymnasium.register(id=env_id(sport, mode),
                               entry_point="smpl_olympics.gym_env:OlympicsGymEnv",
                               kwargs={"sport": sport, "mode": mode})
