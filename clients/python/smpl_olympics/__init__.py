"""SMPL Olympics: Python client for the humanoid sports match server.

    from smpl_olympics import OlympicsParallelEnv
    env = OlympicsParallelEnv(sport="sandbox", mode="1v1", slots=[0], request_id="my-match")
    observations, infos = env.reset(seed=3)
    while env.agents:
        actions = {agent: policy(observations[agent]) for agent in env.agents}
        observations, rewards, terminations, truncations, infos = env.step(actions)
    print(env.result)
"""
from ._client import MatchClient, MatchError
from .env import OlympicsParallelEnv
from .servers import CapacityError, NoServerError
from .vector_env import OlympicsVectorEnv

__all__ = ["CapacityError", "MatchClient", "MatchError", "NoServerError", "OlympicsParallelEnv",
           "OlympicsVectorEnv"]

try:  # the one-slot modes as Gymnasium envs, for gymnasium.make("smpl_olympics/...-v0")
    import gymnasium  # noqa: F401
except ImportError:  # gymnasium is optional: nothing beyond numpy is required
    pass
else:
    from .gym_env import OlympicsGymEnv, register_all
    register_all()
    __all__.append("OlympicsGymEnv")
