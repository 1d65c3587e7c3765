"""python3 -m smpl_olympics.train: PPO against a real server through the vector env.

    python3 -m smpl_olympics.train --sport table_tennis --mode ball_return --spawn-server \\
        --samples 2000000 --residual scripted --run runs/tt
    python3 -m smpl_olympics.train --resume runs/tt --samples 4000000     # go on
    python3 -m smpl_olympics.train --sport boxing --mode 1v1 --opponent frozen --init runs/solo

Self-play: with no --opponent every slot of the match acts with the one shared policy (the
paper's shared self-play); --opponent frozen plays team 0 against a frozen copy of the learner,
refreshed every --swap-every iterations (alternating frozen copies); --opponent scripted|zero|
random|mlp:FILE plays team 0 against that policy (run in process, the agent's own code).
--residual scripted adds the policy's action (clipped to [-1, 1]) to the scripted baseline's. Everything a run makes
goes to its folder: checkpoint.pt (resume), snapshots/*.safetensors (olympics-agent --policy
mlp:FILE and the league play them), metrics.csv and curves.png. docs/training.md.
"""
import argparse
import copy
import json
import os
import shutil
import sys
import time

import numpy as np

try:
    import torch
except ImportError as missing:  # another Python than the one with PyTorch: say which, and what to do
    _why = (f"the trainer runs in {sys.executable} (Python {sys.version.split()[0]}), which cannot "
            f"import torch ({missing}): install PyTorch into that Python, or run the trainer with "
            "the one that has it (Debian: sudo apt-get install python3-torch python3-matplotlib "
            "libopenblas0-pthread, then /usr/bin/python3 -m smpl_olympics.train)")
    if __name__ == "__main__":
        sys.exit(_why)
    raise ImportError(_why) from missing

from . import catalog
from ._client import DEFAULT_LCM_URL, NativePolicy
from .ppo import ActorCritic, PpoSettings, RunningNorm, gae, ppo_update
from .private_server import TRAINING_SERVER_FLAGS, PrivateServer  # noqa: F401 (tests)
from .snapshot import export_mlp
from .training_log import TrainingLog
from .vector_env import OlympicsVectorEnv

# CPU-sized defaults, and the paper's Table 1 (PPO, lr 5e-4, minibatch 1024, MLP [2048, 1024,
# 512], fixed sigma, gamma 0.99, clip 0.2), which wants a GPU-sized budget.
PRESETS = {
    "cpu": {"hidden": [256, 128], "lr": 3e-4, "minibatch": 512, "num_envs": 16, "horizon": 32},
    "paper": {"hidden": [2048, 1024, 512], "lr": 5e-4, "minibatch": 1024, "num_envs": 64,
              "horizon": 32},
}


def parse_args(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m smpl_olympics.train", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--run", default="runs/latest", help="folder for everything the run makes")
    p.add_argument("--resume", help="a run folder: go on from its checkpoint")
    p.add_argument("--sport", default="sandbox")
    p.add_argument("--mode", default="solo")
    p.add_argument("--options", default="", help="the sport's settings, JSON")
    p.add_argument("--time-limit", type=float, default=0.0, help="seconds per match (0: sport's)")
    p.add_argument("--samples", type=int, default=1_000_000, help="agent-steps to train for")
    p.add_argument("--preset", choices=sorted(PRESETS), default="cpu")
    p.add_argument("--hidden", type=int, nargs="+", help="hidden layer sizes (preset's)")
    p.add_argument("--num-envs", type=int, help="matches played at once (preset's)")
    p.add_argument("--horizon", type=int, help="ticks per environment per iteration (preset's)")
    p.add_argument("--lr", type=float, help="learning rate (preset's)")
    p.add_argument("--minibatch", type=int, help="minibatch size (preset's)")
    p.add_argument("--epochs", type=int, default=4)
    p.add_argument("--gamma", type=float, default=0.99)
    p.add_argument("--lam", type=float, default=0.95)
    p.add_argument("--clip", type=float, default=0.2)
    p.add_argument("--target-kl", type=float, default=0.02,
                   help="stop an update's epochs past 1.5x this KL (0: never)")
    p.add_argument("--log-std", type=float, default=-1.6, help="exploration sigma = exp(this)")
    p.add_argument("--learn-std", action="store_true", help="learn sigma (default: fixed)")
    p.add_argument("--residual", choices=["none", "scripted"], default="none",
                   help="act = base policy's action + the network's")
    p.add_argument("--opponent", default="",
                   help="team 1's policy: frozen, scripted, zero, random, mlp:FILE "
                        "(none: every slot plays the shared policy)")
    p.add_argument("--win-reward", type=float, default=0.0,
                   help="added to the last reward of a match the learner's team won (minus: "
                        "lost), from the server's result; 0: the sport's rewards only")
    p.add_argument("--term-weights", default="",
                   help="NAME=W,...: train on the reward terms with these weights instead of the "
                        "sport's (terms not named keep theirs); e.g. facing=0,velocity=0")
    p.add_argument("--action-mask", default="",
                   help="START:END,...: the action entries the network learns (the rest stay "
                        "zero, or the base policy's with --residual); e.g. 39:69, the SMPL arms "
                        "(bodies 14-23), keeps the scripted legs; empty: all")
    p.add_argument("--critic-warmup", type=int, default=0,
                   help="iterations that fit only the value function before the policy moves")
    p.add_argument("--swap-every", type=int, default=10, help="--opponent frozen: refresh period")
    p.add_argument("--league", default="",
                   help="learn from the matches a league assigns to its live learner NAME "
                        "(olympics-league selfplay --learner NAME --snapshots RUN/snapshots): the "
                        "league picks the opponents (PFSP, ...) from the snapshots this run "
                        "publishes and its bots; one team's slots learn")
    p.add_argument("--init", help="warm start from a run folder (blocks matched by name)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--lcm-url", default="",
                   help="the server's LCM URL (default: a private server, as --spawn-server)")
    p.add_argument("--secret", default="", help="the deployment's secret file")
    p.add_argument("--spawn-server", action="store_true",
                   help="start a private olympics-server for this run (results in the run folder);"
                        " the default without --lcm-url")
    p.add_argument("--snapshot-every", type=int, default=20, help="iterations between snapshots")
    p.add_argument("--quiet", action="store_true", help="no progress line")
    p.add_argument("--torch-threads", type=int, default=1,
                   help="PyTorch's threads (1: the server's workers keep the other cores)")
    args = p.parse_args(argv)
    if args.league and (args.opponent or args.win_reward or args.spawn_server):
        p.error("--league: the league chooses the opponents and rates the outcomes, and it needs "
                "the server it uses; drop --opponent, --win-reward and --spawn-server (run "
                "olympics-server and olympics-league selfplay --learner NAME beside it)")
    for key, value in PRESETS[args.preset].items():
        if getattr(args, key) is None:
            setattr(args, key, value)
    return args


def action_mask(spec, size):
    """--action-mask "START:END,..." as a 0/1 vector of the action's size, or None."""
    if not spec:
        return None
    mask = np.zeros(size, np.float32)
    for part in spec.split(","):
        try:
            start, end = (int(x) for x in part.split(":"))
        except ValueError:
            raise SystemExit(f"--action-mask: {part!r} is not START:END (e.g. 39:69)")
        if not 0 <= start < end <= size:
            raise SystemExit(f"--action-mask: {part!r} is outside the action's 0:{size}")
        mask[start:end] = 1
    return mask


def term_weights(rewards, spec):
    """--term-weights "NAME=W,..." over the sport's weights (a vector in term order), or None."""
    if not spec:
        return None
    weights = {t["name"]: float(t.get("weight", 1.0)) for t in rewards}
    for item in spec.split(","):
        name, _, value = item.partition("=")
        if name.strip() not in weights or not value:
            sys.exit(f"--term-weights: '{item}' is not NAME=WEIGHT with NAME one of this mode's "
                     f"terms: {', '.join(weights)}")
        weights[name.strip()] = float(value)
    return np.array([weights[t["name"]] for t in rewards], np.float32)


# A run's private server (the default without --lcm-url): results and log in the run folder.
# Matches hosted at once: the run's num_envs, and room for more (opponents' and helpers').
SPAWNED_SERVER_CAPACITY = 1024


def spawn_server(run_dir):
    try:
        server = PrivateServer(capacity=SPAWNED_SERVER_CAPACITY, folder=run_dir)
    except (FileNotFoundError, RuntimeError) as error:
        sys.exit(f"the olympics-server for this run: {error}")
    return server, server.url


class Trainer:
    """`spec`: the mode's catalog entry (default: from the catalog; tests pass their own)."""
    RESULT_WAIT_S = 30.0  # --win-reward: how long a match's result may take to come

    def __init__(self, args, spec=None):
        self.args = args
        self.run_dir = args.run
        os.makedirs(os.path.join(self.run_dir, "snapshots"), exist_ok=True)
        spec = spec or catalog.mode(args.sport, args.mode)
        self.spec = spec
        # With --league the env holds one team's slots (the league says which, match by match).
        self.teams = [0] * spec["slot_teams"].count(0) if args.league else spec["slot_teams"]
        self.shared = not args.opponent
        self.learning = [s for s in range(len(self.teams)) if self.shared or self.teams[s] == 0]
        self.others = [s for s in range(len(self.teams)) if s not in self.learning]
        self.obs_size, self.action_size = spec["obs_size"], spec["action_size"]
        self.term_names = [t["name"] for t in spec["rewards"]]
        self.term_weights = term_weights(spec["rewards"], args.term_weights)
        torch.set_num_threads(args.torch_threads)
        torch.manual_seed(args.seed)
        self.generator = torch.Generator().manual_seed(args.seed)
        self.rng = np.random.default_rng(args.seed)
        self.model = ActorCritic(self.obs_size, self.action_size, args.hidden, args.log_std,
                                 args.learn_std, action_mask(args.action_mask, self.action_size))
        self.optimizer = torch.optim.Adam([p for p in self.model.parameters() if p.requires_grad],
                                          lr=args.lr)
        self.norm = RunningNorm(self.obs_size)
        self.iteration, self.samples, self.wall = 0, 0, 0.0
        self.frozen = None  # (model, norm) of --opponent frozen
        self.pending = {}  # --league: env -> (obs, action, log-prob, value) of its step in flight
        self.results = []  # results of ended matches not yet in a metrics row
        self.outcomes_missed = 0  # --win-reward: ended matches whose result did not come
        self.ppo = PpoSettings(lr=args.lr, epochs=args.epochs, minibatch=args.minibatch,
                               clip=args.clip, target_kl=args.target_kl)

    # ---------------------------------------------------------------- policies in process
    def native(self, name, seed):
        return NativePolicy(name, self.args.sport, self.args.mode, self.spec["observation"],
                            self.action_size, float(self.spec["control_hz"]), seed)

    def make_helpers(self, num_envs):
        base = (lambda e, s: self.native("scripted", e * 100 + s)) if self.args.residual != "none" \
            else (lambda e, s: None)
        self.base = [[base(e, s) for s in self.learning] for e in range(num_envs)]
        opp = self.args.opponent
        native_opp = opp and opp != "frozen"
        self.opponents = [[self.native(opp, e * 100 + s) if native_opp else None
                           for s in self.others] for e in range(num_envs)]
        if opp == "frozen" and self.frozen is None:
            self.refresh_frozen()

    def refresh_frozen(self):
        self.frozen = (copy.deepcopy(self.model).eval(), copy.deepcopy(self.norm))

    def restart_helpers(self, e):
        for p in self.base[e] + self.opponents[e]:
            if p is not None:
                p.restart()

    def base_actions(self, raw_obs, env_ids):
        """[rows, learning, action] from the base policy (zeros without --residual); row k is
        environment env_ids[k]'s."""
        out = np.zeros((raw_obs.shape[0], len(self.learning), self.action_size), np.float32)
        if self.args.residual != "none":
            for row, e in enumerate(env_ids):
                for i, s in enumerate(self.learning):
                    out[row, i] = self.base[e][i].act(raw_obs[row, s])
        return out

    def opponent_actions(self, raw_obs, env_ids):
        out = np.zeros((raw_obs.shape[0], len(self.others), self.action_size), np.float32)
        if not self.others:
            return out
        if self.args.opponent == "frozen":
            model, norm = self.frozen
            obs = torch.as_tensor(norm.normalise(raw_obs[:, self.others]))
            return np.clip(model.mean_action(obs).numpy(), -1, 1)
        for row, e in enumerate(env_ids):
            for i, s in enumerate(self.others):
                out[row, i] = self.opponents[e][i].act(raw_obs[row, s])
        return out

    def act(self, raw_obs, env_ids):
        """For these environments' observations [rows, slots, obs]: the learning slots'
        normalised observations, sampled actions, log-probabilities and values, and the actions
        to send for every slot."""
        obs = self.norm.normalise(raw_obs[:, self.learning])  # [rows, L, obs]
        act, logp, value = self.model.act(torch.as_tensor(obs))
        act = act.numpy()
        actions = np.zeros((len(env_ids), len(self.teams), self.action_size), np.float32)
        # The network's part is clipped to the action space; a base or an opponent policy's
        # is sent as it is (the scripted players use joint targets beyond +-1).
        actions[:, self.learning] = np.clip(act, -1, 1) + self.base_actions(raw_obs, env_ids)
        if self.others:
            actions[:, self.others] = self.opponent_actions(raw_obs, env_ids)
        self.norm.update(raw_obs[:, self.learning])
        return obs, act, logp.numpy(), value.numpy(), actions

    def learning_rewards(self, rewards, truncated, infos):
        """The learning slots' rewards [rows, L] (the weighted terms with --term-weights). A
        match cut by its time limit is not an end: its last reward bootstraps from its last
        state."""
        if self.term_weights is None:
            r = rewards[:, self.learning].astype(np.float32)
        else:
            r = (infos["reward_terms"][:, self.learning] @ self.term_weights).astype(np.float32)
        for row in np.nonzero(infos["episode_over"])[0]:
            for i, s in enumerate(self.learning):
                if truncated[row, s]:
                    final = self.norm.normalise(infos["final_observation"][row, s])
                    with torch.no_grad():
                        r[row, i] += self.args.gamma * float(self.model.value(torch.as_tensor(final)))
        return r

    # ---------------------------------------------------------------- the loop
    def make_env(self):
        a = self.args
        if a.league:  # each environment plays the next match the league assigns
            return OlympicsVectorEnv(a.num_envs, sport=a.sport, mode=a.mode, learner=a.league,
                                     lcm_url=a.lcm_url, secret_file=a.secret, timeout_s=600,
                                     agent_name=a.league, policy_id="ppo")
        # Training seeds start at 10^6 (olympics-bench evaluates on seeds 1..N); a resumed run
        # moves on to seeds it has not played.
        seed = 10**6 * (1 + a.seed) + self.iteration * a.num_envs * 7919
        return OlympicsVectorEnv(a.num_envs, sport=a.sport, mode=a.mode, seed=seed,
                                 time_limit_s=a.time_limit,
                                 sport_options=json.loads(a.options) if a.options else None,
                                 lcm_url=a.lcm_url, secret_file=a.secret,
                                 agent_name=os.path.basename(os.path.normpath(self.run_dir)),
                                 policy_id="ppo", request_prefix=f"train{os.getpid()}")

    def train(self, make_env=None):
        """Trains until args.samples; `make_env` (tests) replaces the server's vector env."""
        a = self.args
        server = None
        if a.league and not a.lcm_url:  # the league's server: on LCM's default URL
            a.lcm_url = DEFAULT_LCM_URL
        if a.spawn_server or not a.lcm_url:
            server, a.lcm_url = spawn_server(self.run_dir)
        log = TrainingLog(self.run_dir, self.term_names, resume=self.iteration > 0,
                          until_iteration=self.iteration)
        env = (make_env or self.make_env)()
        self.make_helpers(a.num_envs)
        try:
            if a.league:  # matches start as the league assigns them: step whichever are ready
                env.start()
                self.pending = {}  # a new client: nothing of the last one's is in flight
            else:
                raw, _ = env.reset()
            ep = Episodes(a.num_envs, len(self.learning), len(self.term_names))
            while self.samples < a.samples:
                started = time.monotonic()
                if a.league:
                    batch = self.collect_ready(env, ep)
                else:
                    batch, raw = self.collect(env, raw, ep)
                stats = ppo_update(self.model, self.optimizer, batch, self.ppo, self.generator,
                                   train_policy=self.iteration >= a.critic_warmup)
                self.iteration += 1
                self.samples += len(batch["obs"])
                self.wall += time.monotonic() - started
                if a.opponent == "frozen" and self.iteration % a.swap_every == 0:
                    self.refresh_frozen()
                row = {"iteration": self.iteration, "samples": self.samples,
                       "wall_s": round(self.wall, 2),
                       "samples_per_s": len(batch["obs"]) / (time.monotonic() - started),
                       "std": float(self.model.log_std.exp().mean()), **stats,
                       **ep.summary(self.term_names), **self.scores()}
                if a.win_reward:
                    row["outcomes_missed"] = self.outcomes_missed
                log.write(row)
                if not a.quiet:
                    TrainingLog.progress(row, a.samples)
                if self.iteration % a.snapshot_every == 0:
                    self.save()
            self.save()
            self.plot(log)
            if not a.quiet:
                print(f"\n{self.run_dir}: {self.samples:,} samples in {self.wall:.0f} s; latest "
                      f"snapshot {self.snapshot_path('latest')}")
        finally:
            env.close()
            if server is not None:
                server.close()

    def plot(self, log):
        a = self.args
        try:
            log.plot(os.path.join(self.run_dir, "curves.png"),
                     f"{a.sport} {a.mode}: PPO{' residual on scripted' if a.residual != 'none' else ''}"
                     f", {self.samples:,} samples, {self.wall / 60:.1f} min")
        except ImportError:
            print("no curves.png: matplotlib is not installed (apt-get install python3-matplotlib)")

    def collect(self, env, raw, ep):
        a, L = self.args, len(self.learning)
        T, N = a.horizon, a.num_envs
        buf = {k: [] for k in ("obs", "actions", "log_probs", "values", "rewards", "dones")}
        ended = {}  # match id -> (tick of this iteration, environment) of the matches that ended
        for t in range(T):
            ids = [env.match_id(e) for e in range(N)] if a.win_reward else None
            obs, act, logp, value, actions = self.act(raw, range(N))
            raw, rewards, _, truncated, infos = env.step(actions)
            r = self.learning_rewards(rewards, truncated, infos)
            done = np.repeat(np.asarray(infos["episode_over"], np.float32)[:, None], L, axis=1)
            for e in np.nonzero(infos["episode_over"])[0]:
                self.restart_helpers(e)
                if ids is not None:
                    ended[ids[e]] = (t, e)
            ep.add(rewards[:, self.learning], infos["reward_terms"][:, self.learning],
                   infos["episode_over"])
            buf["obs"].append(obs)
            buf["actions"].append(act)
            buf["log_probs"].append(logp)
            buf["values"].append(value)
            buf["rewards"].append(r)
            buf["dones"].append(done)
        with torch.no_grad():
            last = self.model.value(torch.as_tensor(self.norm.normalise(raw[:, self.learning])))
        last = last.numpy()
        arr = {k: np.asarray(v, np.float32) for k, v in buf.items()}
        self.results.extend(env.results())  # the client keeps them until asked
        if ended:
            self.credit_outcomes(env, ended, arr["rewards"])
        adv, ret = gae(arr["rewards"], arr["values"], arr["dones"], last, a.gamma, a.lam)
        flat = lambda x, *tail: x.reshape(-1, *tail)  # noqa: E731
        return {"obs": flat(arr["obs"], self.obs_size), "actions": flat(arr["actions"], self.action_size),
                "log_probs": flat(arr["log_probs"]), "advantages": flat(adv),
                "returns": flat(ret)}, raw

    def collect_ready(self, env, ep):
        """--league: steps whichever matches are ready (env.recv) until the batch holds
        horizon x num_envs steps, so a match waiting for the league to start holds no other.
        Each environment's steps form their own sequence for GAE; a step whose action is out
        when the batch is full (self.pending) completes in the next batch."""
        a, L = self.args, len(self.learning)
        keys = ("obs", "actions", "log_probs", "values", "rewards", "dones")
        seqs, steps = {}, 0
        while steps < a.horizon * a.num_envs:
            ids, raw, rewards, _, truncated, infos = env.recv(min_ready=1)
            r = self.learning_rewards(rewards, truncated, infos)
            over = np.asarray(infos["episode_over"], bool)
            completing = [row for row, e in enumerate(ids) if e in self.pending]
            for row in completing:
                e = ids[row]
                step = self.pending.pop(e) + (r[row], np.full(L, over[row], np.float32))
                seq = seqs.setdefault(e, {k: [] for k in keys})
                for k, v in zip(keys, step):
                    seq[k].append(v)
                if over[row]:
                    self.restart_helpers(e)
            ep.add(rewards[completing][:, self.learning],
                   infos["reward_terms"][completing][:, self.learning], over[completing],
                   envs=[ids[row] for row in completing])
            steps += len(completing)
            obs, act, logp, value, actions = self.act(raw, ids)
            env.send(actions, ids)
            for row, e in enumerate(ids):
                self.pending[e] = (obs[row], act[row], logp[row], value[row])
        self.results.extend(env.results())
        parts = {k: [] for k in ("obs", "actions", "log_probs", "advantages", "returns")}
        for e, seq in seqs.items():
            arr = {k: np.asarray(v, np.float32)[:, None] for k, v in seq.items()}  # [T_e, 1, ...]
            last = self.pending[e][3][None]  # every environment that answered has an action out
            adv, ret = gae(arr["rewards"], arr["values"], arr["dones"], last, a.gamma, a.lam)
            for k, v in (("obs", arr["obs"].reshape(-1, self.obs_size)),
                         ("actions", arr["actions"].reshape(-1, self.action_size)),
                         ("log_probs", arr["log_probs"].ravel()), ("advantages", adv.ravel()),
                         ("returns", ret.ravel())):
                parts[k].append(v)
        return {k: np.concatenate(v) for k, v in parts.items()}

    def credit_outcomes(self, env, ended, rewards):
        """--win-reward: +W (won) or -W (lost) on the last tick of each learning slot whose match
        ended in this iteration. A result comes a round trip after the match's last tick: the
        trainer waits for it (so that what a run learns does not depend on how loaded the
        machine is: reruns are identical); one that has not come within RESULT_WAIT_S is lost
        and gets nothing (counted in `outcomes_missed`)."""
        give_up = time.monotonic() + self.RESULT_WAIT_S
        heard = self.results
        while True:
            for r in heard:
                where = ended.pop(r["match_id"], None)
                if where is None or r["winner_team"] < 0:
                    continue
                t, e = where
                for i, s in enumerate(self.learning):
                    won = r["slot_team"][s] == r["winner_team"]
                    rewards[t, e, i] += self.args.win_reward if won else -self.args.win_reward
            if not ended or time.monotonic() > give_up:
                break
            time.sleep(0.002)
            heard = env.results()
            self.results.extend(heard)
        self.outcomes_missed += len(ended)

    def scores(self):
        """The sport's own figure from the matches that ended: the learning team's score (ball
        return: balls returned in; a match: points), and its win rate against an opponent (with
        --league: against whoever the league picked; the learner's team, which varies from game
        to game, is the one its client's name plays)."""
        results, self.results = self.results, []
        if self.args.league:
            results = [r for r in results if self.args.league in r["agent_names"]]
            teams = [r["slot_team"][r["agent_names"].index(self.args.league)] for r in results]
        else:
            teams = [0] * len(results)
        if not results:
            return {}
        if self.shared and not self.args.league:
            return {"score": float(np.mean([np.mean(r["scores"]) for r in results]))}
        return {"score": float(np.mean([r["scores"][t] for r, t in zip(results, teams)])),
                "win_rate": float(np.mean([r["winner_team"] == t for r, t in zip(results, teams)]))}

    # ---------------------------------------------------------------- files
    def snapshot_path(self, tag):
        return os.path.join(self.run_dir, "snapshots", f"policy-{tag}.safetensors")

    def save(self):
        torch.save({"model": self.model.state_dict(), "optimizer": self.optimizer.state_dict(),
                    "norm": self.norm.state_dict(), "iteration": self.iteration,
                    "samples": self.samples, "wall": self.wall, "args": vars(self.args),
                    "generator": self.generator.get_state(), "torch_rng": torch.get_rng_state(),
                    "frozen": None if self.frozen is None else
                    (self.frozen[0].state_dict(), self.frozen[1].state_dict())},
                   os.path.join(self.run_dir, "checkpoint.pt"))
        # "v<iteration>": the league's self-play (olympics-league selfplay --snapshots DIR) picks
        # the newest up between matches and rates it against PFSP-chosen opponents.
        path = self.snapshot_path(f"v{self.iteration:05d}")
        export_mlp(self.model.actor, path, activation="silu", obs_mean=self.norm.mean,
                   obs_std=self.norm.std(), policy_id=os.path.basename(os.path.normpath(self.run_dir)),
                   policy_version=str(self.iteration), sport=self.args.sport, mode=self.args.mode,
                   residual=self.args.residual, samples=str(self.samples))
        shutil.copyfile(path, self.snapshot_path("latest"))

    def load(self, run_dir):
        state = torch.load(os.path.join(run_dir, "checkpoint.pt"), weights_only=False)
        self.model.load_state_dict(state["model"])
        self.optimizer.load_state_dict(state["optimizer"])
        self.norm.load_state_dict(state["norm"])
        self.iteration, self.samples, self.wall = state["iteration"], state["samples"], state["wall"]
        self.generator.set_state(state["generator"])
        torch.set_rng_state(state["torch_rng"])
        if state["frozen"] is not None:
            model, norm = copy.deepcopy(self.model), RunningNorm(self.obs_size)
            model.load_state_dict(state["frozen"][0])
            norm.load_state_dict(state["frozen"][1])
            self.frozen = (model.eval(), norm)

    def warm_start(self, run_dir):
        """Weights of another run (another mode of the sport, e.g. the single-player task): the
        first layers' columns are matched by observation block name, the rest copied."""
        state = torch.load(os.path.join(run_dir, "checkpoint.pt"), weights_only=False)
        src_args = state["args"]
        src = catalog.mode(src_args["sport"], src_args["mode"])["observation"]
        dst = self.spec["observation"]
        offsets = lambda blocks: {b["name"]: (sum(x["size"] for x in blocks[:i]), b["size"])  # noqa: E731
                                  for i, b in enumerate(blocks)}
        so, do = offsets(src), offsets(dst)
        pairs = [(so[n][0], do[n][0], do[n][1]) for n in do if n in so and so[n][1] == do[n][1]]
        mine = self.model.state_dict()
        for key, value in state["model"].items():
            if key in ("actor.0.weight", "critic.0.weight"):
                w = torch.zeros_like(mine[key])
                for s0, d0, n in pairs:
                    w[:, d0:d0 + n] = value[:, s0:s0 + n]
                mine[key] = w
            elif mine[key].shape == value.shape:
                mine[key] = value
        self.model.load_state_dict(mine)
        mean, var = np.zeros(self.obs_size), np.ones(self.obs_size)
        for s0, d0, n in pairs:
            mean[d0:d0 + n] = state["norm"]["mean"][s0:s0 + n]
            var[d0:d0 + n] = state["norm"]["var"][s0:s0 + n]
        self.norm.load_state_dict({"mean": mean, "var": var, "count": state["norm"]["count"]})
        return [n for n in do if n in so]


class Episodes:
    """Per (environment, learning agent): the running return, length and reward-term sums;
    what finished in an iteration is averaged into its row."""

    def __init__(self, num_envs, agents, terms):
        self.ret = np.zeros((num_envs, agents))
        self.len = np.zeros((num_envs, agents))
        self.terms = np.zeros((num_envs, agents, terms))
        self.done_ret, self.done_len, self.done_terms = [], [], []

    def add(self, rewards, terms, over, envs=None):
        """One step of every environment, or of `envs` (rows in that order)."""
        envs = np.arange(len(self.ret)) if envs is None else np.asarray(envs, int)
        self.ret[envs] += rewards
        self.len[envs] += 1
        self.terms[envs] += terms
        for e in envs[np.asarray(over, bool)]:
            # Copies: the rows are zeroed for the next episode right after.
            self.done_ret.extend(self.ret[e].tolist())
            self.done_len.extend(self.len[e].tolist())
            self.done_terms.extend(self.terms[e].copy())
            self.ret[e], self.len[e], self.terms[e] = 0, 0, 0

    def summary(self, names):
        if not self.done_ret:
            return {"episodes": 0}
        out = {"episodes": len(self.done_ret), "episode_return": float(np.mean(self.done_ret)),
               "episode_length": float(np.mean(self.done_len))}
        for k, n in enumerate(names):
            out[f"term_{n}"] = float(np.mean([t[k] for t in self.done_terms]))
        if "contact" in names:  # racket sports: the share of episodes that touched the ball
            k = names.index("contact")
            out["touch_rate"] = float(np.mean([t[k] > 0 for t in self.done_terms]))
        self.done_ret, self.done_len, self.done_terms = [], [], []
        return out


def main(argv=None):
    args = parse_args(argv)
    if args.resume:
        stored = torch.load(os.path.join(args.resume, "checkpoint.pt"), weights_only=False)["args"]
        keep = {k: getattr(args, k) for k in ("samples", "lcm_url", "secret", "spawn_server",
                                               "quiet")}
        defaults = vars(parse_args([]))  # settings added since the run was stored
        args = argparse.Namespace(**{**defaults, **stored, **keep, "run": args.resume,
                                     "resume": args.resume})
    if not args.quiet:
        print(f"trainer: {sys.executable} (Python {sys.version.split()[0]}, torch "
              f"{torch.__version__}, numpy {np.__version__})")
    trainer = Trainer(args)
    if args.resume:
        trainer.load(args.resume)
        print(f"resuming {args.resume} at iteration {trainer.iteration}, "
              f"{trainer.samples:,} samples")
    elif args.init:
        print(f"warm start from {args.init}: blocks {', '.join(trainer.warm_start(args.init))}")
    with open(os.path.join(args.run, "args.json"), "w") as f:
        json.dump(vars(args), f, indent=1)
    trainer.train()


if __name__ == "__main__":
    main()
