"""SMPL Olympics: Python client for the humanoid sports match server.

    from smpl_olympics import OlympicsParallelEnv
    env = OlympicsParallelEnv(sport="sandbox", mode="1v1", slots=[0], request_id="my-match")
    observations, infos = env.reset(seed=3)
    while env.agents:
        actions = {agent: policy(observations[agent]) for agent in env.agents}
        observations, rewards, terminations, truncations, infos = env.step(actions)
    print(env.result)
"""
import os as _os

# A wheel (pip install ./clients/python) carries the humanoid assets that the scripted players'
# body model and the olympics-server it starts load: point them there, not at a checkout.
_ASSETS = _os.path.join(_os.path.dirname(__file__), "assets")
if _os.path.isdir(_ASSETS):
    _os.environ.setdefault("OLYMPICS_ASSET_DIR", _ASSETS)

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
