"""A PettingZoo parallel environment over a real match on an olympics-server.

Agents are named "slot_<k>" for the slots this client plays. reset() requests a match (or joins
the one named by match_id) and returns the first observations; step() sends one action per live
agent and returns the next tick's observations, rewards, terminations, truncations and infos for
the agents that were live, as PettingZoo's ParallelEnv does. Agents whose slot is done leave
env.agents and the following steps' dicts. possible_agents and the spaces come from the sports
catalog, so they are valid before reset(); the spaces are cached objects whose bounds admit every
observation the server sends.
"""
import itertools
import json

import numpy as np

from . import catalog
from ._client import MatchClient
from .layout import ObservationLayout
from .private_server import PrivateServer
from .servers import CONNECT_TIMEOUT_S, find_servers
from .spaces import box

try:  # PettingZoo's base class when it is installed, so isinstance(env, ParallelEnv) holds
    from pettingzoo.utils.env import ParallelEnv as _ParallelEnvBase
except ImportError:  # nothing beyond numpy is required: the same surface without it
    _ParallelEnvBase = object


# Matches a parallel env's private server hosts at once: one, and room for a match still ending
# while the next one starts.
PRIVATE_SERVER_CAPACITY = 4


class OlympicsParallelEnv(_ParallelEnvBase):
    """lcm_url: the server's (a deployment's) LCM URL; none: the env starts a private
    olympics-server for itself at its first reset (env.lcm_url then names it, for opponents to
    join) and stops it on close() or when the process ends."""
    metadata = {"name": "smpl_olympics", "render_modes": [], "is_parallelizable": True}
    render_mode = None

    def __init__(self, sport="sandbox", mode="1v1", slots=None, match_id=None, request_id=None,
                 time_limit_s=0.0, realtime=False, lcm_url="", agent_name="python",
                 policy_id="", policy_version="", server_id="", timeout_s=60.0, learner=None,
                 sport_options=None, secret_file="", connect_timeout_s=CONNECT_TIMEOUT_S):
        self.sport, self.mode = sport, mode
        self.slots = None if slots is None else sorted(slots)
        self.match_id, self.request_id = match_id, request_id
        self.time_limit_s, self.realtime, self.server_id = time_limit_s, realtime, server_id
        self.timeout_s = timeout_s
        # The sport's settings (e.g. {"format": "tiebreak"} for tennis), sent with each request.
        self.sport_options = dict(sport_options or {})
        self.learner = learner  # a league entrant live:<learner>: reset() plays what the league assigns
        self.assignment = None
        # The deployment's secret file ("" = $OLYMPICS_SECRET_FILE, or none): docs/security.md.
        self._client_settings = (agent_name, policy_id, policy_version, secret_file)
        self.lcm_url = lcm_url or ""
        if not self.lcm_url and (learner is not None or match_id is not None):
            raise ValueError("joining a league's or another client's match needs the lcm_url of "
                             "the server hosting it (without one, the env starts a private "
                             "server where nobody else plays)")
        self._client = None  # connected at the first reset (after a private server starts)
        self._server = None
        # The first reset first listens this long for the server's announcement, and raises
        # NoServerError (naming the URL and how to start one) rather than wait timeout_s.
        self._connect = dict(lcm_url=lcm_url, secret_file=secret_file, server_id=server_id,
                             timeout_s=connect_timeout_s)
        self._server_seen = False
        self._episode = itertools.count()
        self._tick = None
        self.description = None
        self.result = None
        self.agents = []
        self._last_obs = {}
        self._use_mode(sport, mode, self.slots)

    def _use_mode(self, sport, mode, slots):
        """Agents, spaces and observation blocks of a sport's mode, from the catalog."""
        spec = catalog.mode(sport, mode)
        self._spec = spec
        if slots is None:
            slots = range(len(spec["slot_teams"]))
        self.possible_agents = [f"slot_{s}" for s in slots]
        obs_space, act_space = catalog.observation_space(spec), catalog.action_space(spec)
        self.observation_spaces = {a: obs_space for a in self.possible_agents}
        self.action_spaces = {a: act_space for a in self.possible_agents}
        self.state_space = box(np.tile(obs_space.low, len(self.possible_agents)),
                               np.tile(obs_space.high, len(self.possible_agents)))
        self._use_layout(ObservationLayout.from_catalog(spec))

    def _use_layout(self, layout):
        """Where the observation's named blocks and fields lie (layout.py)."""
        self.layout = layout
        self.obs_blocks = layout.blocks  # block name -> slice of an observation
        self.obs_fields = layout.fields  # (block, field) -> slice

    @property
    def unwrapped(self):
        """This env itself: it wraps nothing (PettingZoo's wrappers and tests ask for it)."""
        return self

    @property
    def ignored_errors(self):
        """Errors naming this env's client for a match it does not hold: not acted on, counted
        (a server never sends them; docs/security.md). 0 before the first reset."""
        return self._client.ignored_errors if self._client is not None else 0

    @property
    def num_agents(self):
        return len(self.agents)

    @property
    def max_num_agents(self):
        return len(self.possible_agents)

    def observation_size(self, agent=None):
        return self._spec["obs_size"]

    def action_size(self, agent=None):
        return self._spec["action_size"]

    def observation_space(self, agent):
        return self.observation_spaces[agent]

    def action_space(self, agent):
        """Nominal range [-1, 1] (target = scale * a); the server accepts any finite value."""
        return self.action_spaces[agent]

    def state(self):
        """The global state this client sees: the latest observations of possible_agents, in
        slot order, concatenated (zeros for an agent not observed yet)."""
        size = self._spec["obs_size"]
        return np.concatenate([self._last_obs.get(a, np.zeros(size, dtype=np.float32))
                               for a in self.possible_agents])

    def render(self):
        """Nothing to draw here: watch the match's replay (docs/clients.md)."""
        return None

    def reset(self, seed=None, options=None):
        """Start a new match: returns (observations, infos).

        Without match_id, each reset requests a new match with request id "<request_id>-<n>"
        (n = 0, 1, ... per reset), so an opponent process given the same id meets this env.
        Without a seed, each reset draws a fresh one (the match's seed is in env.description).
        """
        if seed is None:
            seed = int(np.random.SeedSequence().entropy % (1 << 62))
        self._connect_client()
        if not self._server_seen:
            find_servers(**self._connect)
            self._server_seen = True
        match_id, slots = self.match_id, self.slots
        if self.learner is not None:
            self.assignment = self._client.wait_assignment(self.learner, max(self.timeout_s, 600.0))
            match_id, slots = self.assignment["match_id"], self.assignment["slots"]
        elif match_id is None:
            episode = next(self._episode)
            base = self.request_id if self.request_id is not None else self._client.client_id
            created = self._client.request_match(
                self.sport, self.mode, seed, self.time_limit_s, self.realtime,
                f"{base}-{episode}", self.server_id, self.timeout_s,
                json.dumps(self.sport_options) if self.sport_options else "")
            match_id = created["match_id"]
            if slots is None:
                slots = list(range(created["num_slots"]))
        elif slots is None:
            raise ValueError("pass slots=[...] to join a match by its id")
        self.description = self._client.join(match_id, slots, self.timeout_s)
        self._use_mode(self.description["sport"], self.description["mode"], slots)
        served = ObservationLayout.from_description(self.description)
        if served.entries != self.layout.entries:
            raise RuntimeError(
                f"the server's {self.description['sport']}/{self.description['mode']} observation "
                f"blocks and fields {served.entries} differ from this package's catalog "
                f"{self.layout.entries}: use the Python package built with that server")
        self._use_layout(served)  # the server's own description, field by field
        self.agents = list(self.possible_agents)
        self.result = None
        self._last_obs = {}
        batch = self._client.next(self.timeout_s)
        observations, _, _, _, infos = self._unpack(batch, self.agents)
        return observations, infos

    def step(self, actions):
        """One tick: actions maps each live agent to an array of action_size floats."""
        size = self.description["action_size"]
        rows = np.zeros((len(self.possible_agents), size), dtype=np.float32)
        for i, agent in enumerate(self.possible_agents):
            if agent in actions:
                rows[i] = np.asarray(actions[agent], dtype=np.float32).reshape(size)
        self._client.act(self._tick, rows)
        batch = self._client.next(self.timeout_s)
        if batch is None:  # the match ended without a final observation reaching us:
            # every live agent still gets its entries (its last observation, no reward), as
            # PettingZoo asks of a step.
            self.result = self._client.wait_result(self.timeout_s)
            ended = list(self.agents)
            self.agents = []
            return ({a: self._last_obs[a] for a in ended}, {a: 0.0 for a in ended},
                    {a: True for a in ended}, {a: False for a in ended},
                    {a: {} for a in ended})
        observations, rewards, terminations, truncations, infos = self._unpack(batch, self.agents)
        self.agents = [a for a in self.agents if not (terminations[a] or truncations[a])]
        if not self.agents:
            # The server's record of the match is env.result, not an info: its match id and wall
            # duration differ between two runs of one seed, and infos must not (PettingZoo's
            # parallel_seed_test compares them; a match that ends on its first step showed it).
            self.result = self._client.wait_result(self.timeout_s)
        return observations, rewards, terminations, truncations, infos

    def close(self):
        """Ends this env's use of the server; a private server stops (its matches end)."""
        self.agents = []
        if self._server is not None:  # a later reset starts a new one
            self._server.close()
            self._server = self._client = None
            self.lcm_url, self._server_seen = "", False

    def _connect_client(self):
        if self._client is not None:
            return
        if not self.lcm_url:
            self._server = PrivateServer(capacity=PRIVATE_SERVER_CAPACITY)
            self.lcm_url, self.server_id = self._server.url, self._server.server_id
            self._connect.update(lcm_url=self.lcm_url, server_id=self.server_id)
        self._client = MatchClient(self.lcm_url, *self._client_settings)

    def block(self, observation, name):
        """The named block of an observation ("self", "ball_position", ...): describe lists them."""
        return self.layout.block(observation, name)

    def field(self, observation, block, name):
        """A named field inside a block (("self", "root_height"), ("ball", "position")): describe
        lists every block's fields, as the server writes them; env.layout.offset/size give where."""
        return self.layout.field(observation, block, name)

    def _unpack(self, batch, live):
        """The batch's entries for the agents in `live` (those that finished earlier drop out)."""
        self._tick = batch["tick"]
        try:
            info = json.loads(batch["info"]) if batch["info"] else {}
        except ValueError:  # not the referee's JSON: the observation itself is still good
            info = {}
        observations, rewards, terminations, truncations, infos = {}, {}, {}, {}, {}
        for i, slot in enumerate(batch["slots"]):
            agent = f"slot_{slot}"
            self._last_obs[agent] = batch["obs"][i]
            if agent not in live:
                continue
            observations[agent] = batch["obs"][i]
            rewards[agent] = float(batch["reward"][i])
            truncations[agent] = bool(batch["truncated"][i])
            terminations[agent] = bool(batch["done"][i]) and not truncations[agent]
            infos[agent] = {"tick": batch["tick"],
                            "reward_terms": dict(zip(batch["term_names"], batch["terms"][i].tolist())),
                            "match": info}
        return observations, rewards, terminations, truncations, infos

