"""Scripted policies that see the world itself: yardsticks for the environments' rules."""

from __future__ import annotations

import random
from collections.abc import Callable

from robocog.experiments.procedures.reasoners import PolicyReasoner
from robocog.worlds.procedures import Alien, Bandrobot, Cartpole, Pong, Pong2, ProcedureEnv, Robot
from robocog.worlds.procedures.cartpole import UPRIGHT

Policy = Callable[[ProcedureEnv], str | None]


def pong(env: ProcedureEnv) -> str | None:
    """Chase the ball's column."""
    assert isinstance(env, Pong)
    if env.ball_x < env.bat_x:
        return "^left"
    if env.ball_x > env.bat_x:
        return "^right"
    return None


def pong2(env: ProcedureEnv) -> str | None:
    """Chase the ball and stop once it is within reach."""
    assert isinstance(env, Pong2)
    if abs(env.ball_x - env.bat_x) <= env.half_width // 2:
        return "^stop"
    return "^left" if env.ball_x < env.bat_x else "^right"


def alien(env: ProcedureEnv) -> str | None:
    """Shoot when in reach, otherwise move towards the alien."""
    assert isinstance(env, Alien)
    return {"c0": "^shoot", "r0": "^right", "l0": "^left"}[env.relation()]


def cartpole(env: ProcedureEnv) -> str | None:
    """Push against the tilt the pole will have next step."""
    assert isinstance(env, Cartpole)
    ahead = env.angle + env.angular_velocity
    if ahead > UPRIGHT:
        return "^right"
    return "^left"


def robot(env: ProcedureEnv) -> str | None:
    """Go for visible food, turn away from walls, otherwise go ahead.

    A turn towards food seen aside is not undone by the opposite turn (food between
    two sectors would make the robot turn back and forth for ever); it goes ahead
    instead.
    """
    assert isinstance(env, Robot)
    food, state = [row[:] for row in env.food], env.rng.getstate()
    (left, middle, right), ahead, _ = env.view()  # looking eats; undo that
    env.food = food
    env.rng.setstate(state)
    last = getattr(env, "_scripted_last", None)
    free = ahead != (env.x, env.y) and middle != "w"
    op = "^left"
    if middle == "f" or (free and {left, right} == {"o"}):
        op = "^forward"
    elif left == "f" and last != "^right":
        op = "^left"
    elif right == "f" and last != "^left":
        op = "^right"
    elif free:
        op = "^forward"
    env._scripted_last = op  # type: ignore[attr-defined]
    return op


def bandrobot(env: ProcedureEnv) -> str | None:
    """Fetch the object, carry it to the goal, drop it there."""
    assert isinstance(env, Bandrobot)
    aim = env.goal_position if env.holding else env.target
    if env.position < aim:
        return "^right"
    if env.position > aim:
        return "^left"
    return "^drop" if env.holding else "^pick"


PERFECT: dict[str, Policy] = {
    "pong": pong,
    "pong2": pong2,
    "alien": alien,
    "cartpole": cartpole,
    "robot": robot,
    "bandrobot": bandrobot,
}


def scripted(name: str) -> PolicyReasoner:
    """The scripted policy of a world as a reasoner."""
    return PolicyReasoner(PERFECT[name], name=f"scripted-{name}")


def random_policy(seed: int) -> PolicyReasoner:
    """A random operation or none at every goal."""
    rng = random.Random(seed)
    return PolicyReasoner(lambda env: rng.choice([*env.operations, None]), name="random")
