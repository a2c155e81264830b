"""The garbage field as a Gymnasium environment, for learning agents beside the minds.

A thin wrapper: six discrete actions (the operations of Hammer et al., Section IV), an
observation vector built from the same percepts a mind receives, and a reward of 1
per object dropped into the trailer. Gymnasium is an optional extra
(``pip install robocog[gym]``); it is imported only when the environment is made.
"""

from __future__ import annotations

import math
from typing import Any

from robocog.robot.commands import Command, Drop, Forward, GoTo, Pick, Turn
from robocog.robot.percepts import Detection, Gripper, Obstacle, Percept, Pose
from robocog.worlds.garbage import GarbageConfig, GarbageField

ENV_ID = "robocog/GarbageField-v0"
#: action index -> command, in the order of Section IV's operations
ACTIONS: tuple[Command, ...] = (
    Forward(0.5),
    Turn(math.radians(30)),
    Turn(-math.radians(30)),
    GoTo("next"),
    Pick("trash"),
    Drop(),
)
#: observation layout: seen left/center/right, obstacle left/front/right/free,
#: at a checkpoint, holding, fraction of the mission time used
OBSERVATION_SIZE = 10


def observe(percepts: list[Percept], fov: float, progress: float) -> list[float]:
    """The observation vector of one frame."""
    obs = [0.0] * OBSERVATION_SIZE
    third = fov / 6.0
    for p in percepts:
        if isinstance(p, Detection):
            obs[0 if p.bearing > third else (2 if p.bearing < -third else 1)] = 1.0
        elif isinstance(p, Obstacle):
            obs[{"left": 3, "front": 4, "right": 5, "none": 6}[p.sector]] = 1.0
        elif isinstance(p, Pose):
            obs[7] = 1.0 if p.place else 0.0
        elif isinstance(p, Gripper):
            obs[8] = 1.0 if p.holding else 0.0
    obs[9] = min(1.0, progress)
    return obs


def make_env(config: GarbageConfig | None = None, max_steps: int = 2000) -> Any:
    """A ``gymnasium.Env`` over a fresh :class:`GarbageField` (needs gymnasium)."""
    try:
        import gymnasium
        import numpy as np
        from gymnasium import spaces
    except ImportError as exc:  # pragma: no cover - depends on the extra
        raise ImportError(
            "the Gymnasium environment needs the 'gym' extra: pip install robocog[gym]"
        ) from exc

    class GarbageEnv(gymnasium.Env):
        """The garbage field of Hammer et al.: collect the bottles and cups along the route."""

        metadata = {"render_modes": []}

        def __init__(self) -> None:
            self.config = config or GarbageConfig()
            self.action_space = spaces.Discrete(len(ACTIONS))
            self.observation_space = spaces.Box(0.0, 1.0, (OBSERVATION_SIZE,), np.float32)
            self.world = GarbageField(self.config, seed=0)
            self.steps = 0
            self._last: list[Percept] = []

        def _obs(self) -> Any:
            self._last = self.world.percepts()
            progress = self.world.time() / self.config.mission_time
            return np.asarray(observe(self._last, self.config.camera_fov, progress), np.float32)

        def reset(self, *, seed: int | None = None, options: dict | None = None) -> tuple:
            super().reset(seed=seed)
            world_seed = int(self.np_random.integers(0, 2**31 - 1)) if seed is None else seed
            self.world = GarbageField(self.config, seed=world_seed)
            self.steps = 0
            return self._obs(), {"time": self.world.time()}

        def step(self, action: int) -> tuple:
            before = self.world.collected()
            outcome = self.world.execute(ACTIONS[int(action)])
            self.steps += 1
            reward = float(self.world.collected() - before)
            obs = self._obs()
            terminated = self.world.done
            truncated = self.steps >= max_steps and not terminated
            info = {"outcome": outcome.status.value, "reason": outcome.reason}
            return obs, reward, terminated, truncated, info

    return GarbageEnv()


def register() -> None:
    """Register ``robocog/GarbageField-v0`` with Gymnasium's registry."""
    import gymnasium

    if ENV_ID not in gymnasium.registry:
        gymnasium.register(id=ENV_ID, entry_point=f"{__name__}:make_env")
