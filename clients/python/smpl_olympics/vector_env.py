"""Many matches at once from one process: OlympicsVectorEnv, over the C++ VectorClient.

Every array is batched: observations [num_envs, num_agents, obs_size] as one float32 array,
rewards, terminations and truncations [num_envs, num_agents], reward terms
[num_envs, num_agents, n_terms]. An environment whose match ends is reset at once to its next
match (next seed, same request): step() then returns the new match's first observation,
infos["episode_over"][e] is True and infos["final_observation"][e] holds the ended match's last
observation (the reward and flags are the ended match's last). Async mode, as EnvPool's:
send(actions, env_ids) and recv() whichever environments are ready.

Seeds: environment e's k-th match has seed seed + k * num_envs + e. Request ids:
"<request_prefix>-<e>-<k>"; when this env does not own every slot, an opponent process that
requests the same id meets it (olympics-agent --request-id <prefix>-<e>-<k>). With learner=NAME
the env is a league's live learner instead: each environment plays the next match the league
assigns to its entrant live:NAME (agents are then "agent_<i>", one per slot of a team).

Server: lcm_url names a deployment's; without one, the first reset (or start) starts a private
olympics-server sized for num_envs (env.lcm_url then names it), stopped by close() or when the
process ends.
"""
import json

import numpy as np

from . import catalog
from ._client import MatchError, VectorClient
from .private_server import PrivateServer
from .servers import CONNECT_TIMEOUT_S, check_capacity, find_servers, with_server_hint
from .spaces import box


class OlympicsVectorEnv:
    def __init__(self, num_envs, sport="sandbox", mode="1v1", slots=None, seed=None,
                 time_limit_s=0.0, sport_options=None, realtime=False, server_id="",
                 request_prefix="", lcm_url="", agent_name="python", policy_id="",
                 policy_version="", secret_file="", timeout_s=60.0, drop_rate=0.0, learner="",
                 connect_timeout_s=CONNECT_TIMEOUT_S):
        self.num_envs, self.sport, self.mode = int(num_envs), sport, mode
        spec = catalog.mode(sport, mode)
        if learner:  # the league says which slots, match by match: one team's worth
            self.slots = []
            self.agents = [f"agent_{i}" for i in range(spec["slot_teams"].count(0))]
        else:
            self.slots = sorted(slots) if slots is not None else list(range(len(spec["slot_teams"])))
            self.agents = [f"slot_{s}" for s in self.slots]
        self.num_agents = len(self.agents)
        self.obs_size, self.action_size = spec["obs_size"], spec["action_size"]
        self.term_names = [t["name"] for t in spec["rewards"]]
        self.single_observation_space = catalog.observation_space(spec)
        self.single_action_space = catalog.action_space(spec)
        self.observation_space = box(
            np.broadcast_to(self.single_observation_space.low, (self.num_envs, self.num_agents, self.obs_size)),
            np.broadcast_to(self.single_observation_space.high, (self.num_envs, self.num_agents, self.obs_size)))
        self.action_space = box(-np.ones((self.num_envs, self.num_agents, self.action_size), np.float32),
                                np.ones((self.num_envs, self.num_agents, self.action_size), np.float32))
        self._settings = dict(
            num_envs=self.num_envs, sport=sport, mode=mode, time_limit_s=time_limit_s,
            realtime=realtime, options=json.dumps(sport_options) if sport_options else "",
            server_id=server_id, slots=self.slots, request_prefix=request_prefix,
            timeout_s=timeout_s, lcm_url=lcm_url, agent_name=agent_name, policy_id=policy_id,
            policy_version=policy_version, secret_file=secret_file,
            drop_rate=drop_rate,  # TEST ONLY: share of sent datagrams dropped
            learner=learner)
        self.seed = _fresh_seed() if seed is None else int(seed)
        self._client = None
        if not lcm_url and learner:
            raise ValueError("learner=: pass the lcm_url of the server the league uses (without "
                             "one, the env starts a private server the league does not know)")
        self._server = None  # the private server, when no lcm_url was given
        # The first reset (or start) listens this long for the servers' announcements: none
        # raises NoServerError; fewer matches admitted than num_envs raises CapacityError.
        self._connect = dict(lcm_url=lcm_url, secret_file=secret_file, server_id=server_id,
                             timeout_s=connect_timeout_s)
        self._servers_checked = False

    @property
    def ignored_errors(self):
        """Errors naming this env's client for a match it does not hold: not acted on, counted
        (a server never sends them; docs/security.md). 0 before the first reset."""
        return self._client.ignored_errors if self._client is not None else 0

    @property
    def lcm_url(self):
        """The server's URL: the one given, or the private server's once it runs ("" before)."""
        return self._settings["lcm_url"]

    def _check_servers(self):
        if self._servers_checked:
            return
        if not self._settings["lcm_url"]:
            self._server = PrivateServer(capacity=self.num_envs)
            for settings in (self._settings, self._connect):
                settings.update(lcm_url=self._server.url, server_id=self._server.server_id)
        if self._settings["learner"]:  # the league requests the matches: only a server is needed
            find_servers(**self._connect)
        else:
            check_capacity(self.num_envs, **self._connect)
        self._servers_checked = True

    def reset(self, seed=None, options=None):
        """Starts num_envs new matches; returns (observations [envs, agents, obs], infos).
        A seed sets the base seed; without one, the base seed of the constructor (or a fresh
        one if none was given) is used for the first reset and fresh ones afterwards."""
        if seed is not None:
            self.seed = int(seed)
        elif self._client is not None:
            self.seed = _fresh_seed()
        self._check_servers()
        self._client = VectorClient(seed=self.seed, **self._settings)
        batch = self._waiting(self._client.reset)
        return batch["obs"], {"match_ids": [self._client.match_id(e) for e in range(self.num_envs)]}

    def start(self, seed=None):
        """Async: starts every environment's first match without waiting; recv() returns each
        as it begins (a league's live learner gets its matches one by one)."""
        self.seed = int(seed) if seed is not None else self.seed
        self._check_servers()
        self._client = VectorClient(seed=self.seed, **self._settings)
        self._client.start()

    def step(self, actions):
        """actions [num_envs, num_agents, action_size] -> observations, rewards, terminations,
        truncations, infos (reward_terms, episode_over, final_observation, tick)."""
        batch = self._waiting(self._client.step, self._actions(actions, self.num_envs))
        return self._unpack(batch)[1:]

    def send(self, actions, env_ids=None):
        """Async: actions [len(env_ids), num_agents, action_size] for these environments
        (default: all)."""
        env_ids = list(range(self.num_envs)) if env_ids is None else [int(e) for e in env_ids]
        self._client.send(env_ids, self._actions(actions, len(env_ids)))

    def recv(self, min_ready=1, timeout_s=None):
        """Async: the environments whose next observation has come (at least min_ready, or
        whatever came within timeout_s when given): (env_ids, observations, rewards,
        terminations, truncations, infos), rows in env_ids order."""
        return self._unpack(self._waiting(self._client.recv, int(min_ready), timeout_s))

    def match_id(self, env):
        """The id of the match environment `env` plays now (its result carries it)."""
        return self._client.match_id(int(env))

    def results(self):
        """Results of the matches that ended since the last call (dicts, as env.result)."""
        return self._client.take_results() if self._client is not None else []

    def close(self):
        """Stops playing; a private server stops too (a later reset starts a new one)."""
        self._client = None
        if self._server is not None:
            self._server.close()
            self._server = None
            for settings in (self._settings, self._connect):
                settings.update(lcm_url="", server_id="")
            self._servers_checked = False

    def _waiting(self, call, *args):
        """call(*args), its TIMEOUT saying what to check: the server."""
        try:
            return call(*args)
        except MatchError as error:
            hinted = with_server_hint(error, self._settings["lcm_url"])
            if hinted is error:
                raise
            raise hinted from error

    def _actions(self, actions, n):
        actions = np.ascontiguousarray(actions, dtype=np.float32)
        expected = (n, self.num_agents, self.action_size)
        if actions.shape != expected:
            raise ValueError(f"actions must have shape {expected}, got {actions.shape}")
        return actions

    def _unpack(self, b):
        infos = {"reward_terms": b["terms"], "term_names": self.term_names,
                 "episode_over": b["episode_over"], "final_observation": b["final_obs"],
                 "tick": b["tick"]}
        return b["envs"], b["obs"], b["reward"], b["terminated"], b["truncated"], infos


def _fresh_seed():
    return int(np.random.SeedSequence().entropy % (1 << 40))
