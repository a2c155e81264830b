"""The garbage field as a Gymnasium environment (only when the gym extra is installed)."""

from __future__ import annotations

import math

import pytest

from robocog.robot import Detection, Gripper, Obstacle, Pose
from robocog.worlds.garbage_gym import ACTIONS, OBSERVATION_SIZE, observe


def test_observation_encodes_thirds_sectors_place_and_gripper() -> None:
    fov = math.radians(60)
    obs = observe(
        [
            Detection("cup", math.radians(25), 1.0),
            Obstacle("front", 1.0),
            Pose(0, 0, 0, "p1"),
            Gripper("cup1"),
        ],
        fov,
        0.5,
    )
    assert len(obs) == OBSERVATION_SIZE
    assert obs[:3] == [1.0, 0.0, 0.0]
    assert obs[3:7] == [0.0, 1.0, 0.0, 0.0]
    assert obs[7:] == [1.0, 1.0, 0.5]


def test_the_environment_passes_gymnasiums_checker() -> None:
    gymnasium = pytest.importorskip("gymnasium")
    from gymnasium.utils.env_checker import check_env

    from robocog.worlds.garbage_gym import ENV_ID, make_env, register

    env = make_env()
    check_env(env, skip_render_check=True)
    register()
    assert ENV_ID in gymnasium.registry


def test_an_episode_is_seeded_and_rewards_collected_objects() -> None:
    pytest.importorskip("gymnasium")
    from robocog.worlds.garbage_gym import make_env

    def episode(seed: int) -> tuple[float, int]:
        env = make_env()
        obs, _ = env.reset(seed=seed)
        total, steps = 0.0, 0
        done = False
        while not done:
            if obs[8]:
                action = 5  # drop
            elif obs[:3].any():
                action = 4  # pick
            else:
                action = 3  # goto next
            obs, reward, terminated, truncated, _ = env.step(action)
            total += reward
            steps += 1
            done = terminated or truncated
        return total, steps

    first, again = episode(7), episode(7)
    assert first == again
    assert 0 < first[0] <= 10
    assert len(ACTIONS) == 6
