"""PPO's pieces (PyTorch): the actor-critic, observation normalisation, GAE and the clipped update.

The actor is an MLP whose output is the mean action; exploration noise has a fixed standard
deviation (the paper's choice) or a learned one per action entry. The actor exports to the
project's snapshot format (snapshot.export_mlp) with the normaliser's mean and std, so the C++
MLP player computes the same action as `ActorCritic.mean_action`.
"""
from dataclasses import dataclass

import numpy as np
import torch
from torch import nn


def mlp(sizes, activation=nn.SiLU):
    layers = []
    for i in range(len(sizes) - 1):
        layers.append(nn.Linear(sizes[i], sizes[i + 1]))
        if i < len(sizes) - 2:
            layers.append(activation())
    return nn.Sequential(*layers)


class RunningNorm:
    """Running mean and variance of observations (parallel Welford, float64)."""

    def __init__(self, size):
        self.mean = np.zeros(size, np.float64)
        self.var = np.ones(size, np.float64)
        self.count = 1e-4

    def update(self, x):
        x = np.asarray(x, np.float64).reshape(-1, self.mean.shape[0])
        n, mean, var = x.shape[0], x.mean(0), x.var(0)
        delta, total = mean - self.mean, self.count + n
        self.mean = self.mean + delta * n / total
        self.var = (self.var * self.count + var * n + delta ** 2 * self.count * n / total) / total
        self.count = total

    def std(self):
        return np.sqrt(self.var + 1e-8)

    def normalise(self, x):
        return ((x - self.mean) / self.std()).astype(np.float32)

    def state_dict(self):
        return {"mean": self.mean, "var": self.var, "count": self.count}

    def load_state_dict(self, d):
        self.mean, self.var, self.count = np.asarray(d["mean"]), np.asarray(d["var"]), d["count"]


class ActorCritic(nn.Module):
    def __init__(self, obs_size, action_size, hidden, log_std=-1.6, learn_std=False,
                 action_mask=None):
        super().__init__()
        self.actor = mlp([obs_size, *hidden, action_size])
        self.critic = mlp([obs_size, *hidden, 1])
        # Small last layer: the first actions are near the mean of zero (or of the base policy
        # when residual), not the random output of a fresh network.
        with torch.no_grad():
            self.actor[-1].weight.mul_(0.01)
            self.actor[-1].bias.zero_()
        self.log_std = nn.Parameter(torch.full((action_size,), float(log_std)),
                                    requires_grad=learn_std)
        # The entries the network may act on (all by default). Masked entries are exactly zero:
        # their rows of the last layer start at zero and get no gradient, so the exported
        # snapshot holds the mask itself, and they are neither explored nor in the likelihood.
        mask = torch.ones(action_size) if action_mask is None else \
            torch.as_tensor(action_mask, dtype=torch.float32)
        self.register_buffer("mask", mask)
        if action_mask is not None:
            last = self.actor[-1]
            with torch.no_grad():
                last.weight.mul_(mask[:, None])
                last.bias.mul_(mask)
            last.weight.register_hook(lambda g: g * self.mask[:, None])
            last.bias.register_hook(lambda g: g * self.mask)

    def distribution(self, obs):
        mean = self.actor(obs)
        return torch.distributions.Normal(mean, self.log_std.exp().expand_as(mean))

    def value(self, obs):
        return self.critic(obs).squeeze(-1)

    def load_state_dict(self, state, strict=True, **kwargs):
        # Checkpoints from before --action-mask have no "mask": they acted on every entry.
        state = dict(state)
        state.setdefault("mask", torch.ones_like(self.mask))
        return super().load_state_dict(state, strict, **kwargs)

    def log_prob(self, d, actions):
        return (d.log_prob(actions) * self.mask).sum(-1)

    @torch.no_grad()
    def act(self, obs):
        """Sampled actions, their log-probabilities and the values, for a batch of observations."""
        d = self.distribution(obs)
        a = d.mean + (d.sample() - d.mean) * self.mask
        return a, self.log_prob(d, a), self.value(obs)

    @torch.no_grad()
    def mean_action(self, obs):
        return self.actor(obs)


def gae(rewards, values, dones, last_values, gamma, lam):
    """Advantages and returns, [T, B] arrays; dones[t] ends the episode after step t."""
    T = rewards.shape[0]
    adv = np.zeros_like(rewards)
    running = np.zeros_like(last_values)
    for t in reversed(range(T)):
        next_values = last_values if t == T - 1 else values[t + 1]
        keep = 1.0 - dones[t]
        delta = rewards[t] + gamma * next_values * keep - values[t]
        running = delta + gamma * lam * keep * running
        adv[t] = running
    return adv, adv + values


@dataclass
class PpoSettings:
    lr: float = 3e-4
    epochs: int = 4
    minibatch: int = 512
    clip: float = 0.2
    value_coef: float = 0.5
    entropy_coef: float = 0.0
    max_grad_norm: float = 1.0
    target_kl: float = 0.02  # stop an update's epochs once the policy moved this far (0: never)


def ppo_update(model, optimizer, batch, s: PpoSettings, generator, train_policy=True):
    """One PPO update over a flat batch (obs, actions, log_probs, advantages, returns);
    returns mean losses, the approximate KL and the minibatch steps taken. The epochs stop early
    once the KL from the collecting policy passes 1.5 x target_kl: with a small fixed sigma a
    small move of the mean is a large KL, and unchecked updates wrecked the scripted baseline a
    residual policy starts from (measured: median KL 0.3 per update in fencing).
    train_policy=False fits the value function only (a critic warm-up: the policy stays put
    until the advantages it would follow mean something)."""
    obs, actions, old_logp, adv, ret = (torch.as_tensor(batch[k]) for k in
                                        ("obs", "actions", "log_probs", "advantages", "returns"))
    adv = (adv - adv.mean()) / (adv.std() + 1e-8)
    n = obs.shape[0]
    stats = {"policy_loss": 0.0, "value_loss": 0.0, "approx_kl": 0.0}
    steps, kl = 0, 0.0
    for _ in range(s.epochs):
        if s.target_kl and kl > 1.5 * s.target_kl:
            break
        order = torch.randperm(n, generator=generator)
        for start in range(0, n, s.minibatch):
            idx = order[start:start + s.minibatch]
            d = model.distribution(obs[idx])
            logp = model.log_prob(d, actions[idx])
            ratio = (logp - old_logp[idx]).exp()
            policy_loss = -torch.min(ratio * adv[idx],
                                     ratio.clamp(1 - s.clip, 1 + s.clip) * adv[idx]).mean()
            value_loss = (model.value(obs[idx]) - ret[idx]).pow(2).mean()
            loss = s.value_coef * value_loss
            if train_policy:
                loss = loss + policy_loss - s.entropy_coef * (d.entropy() * model.mask).sum(-1).mean()
            optimizer.zero_grad()
            loss.backward()
            nn.utils.clip_grad_norm_(model.parameters(), s.max_grad_norm)
            optimizer.step()
            stats["policy_loss"] += policy_loss.item()
            stats["value_loss"] += value_loss.item()
            kl = (old_logp[idx] - logp).mean().item()
            stats["approx_kl"] += kl
            steps += 1
            if s.target_kl and kl > 1.5 * s.target_kl:
                break
    out = {k: v / max(steps, 1) for k, v in stats.items()}
    out["update_steps"] = steps
    return out
