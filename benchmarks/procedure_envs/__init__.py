"""Procedure-learning environments after ONA's system tests, and reasoners to drive them.

Each environment is a seeded world (``reset(seed)``, ``step()``, ``execute(op)``, a
success counter) with the rules of one of ONA's ``src/system_tests``; a reasoner is
anything that takes Narsese lines and cycle counts and reports the operations it
executed (ONA's shell through pipes, robocog's NAR, or a scripted policy).
"""

from .alien import Alien
from .bandrobot import Bandrobot
from .base import Feed, ProcedureEnv, Score
from .cartpole import Cartpole
from .pong import Pong, Pong2
from .robot import Robot
from .runner import RunResult, run

#: Environment classes by command-line name.
ENVIRONMENTS: dict[str, type[ProcedureEnv]] = {
    cls.name: cls for cls in (Pong, Pong2, Alien, Cartpole, Robot, Bandrobot)
}

__all__ = [
    "ENVIRONMENTS",
    "Alien",
    "Bandrobot",
    "Cartpole",
    "Feed",
    "Pong",
    "Pong2",
    "ProcedureEnv",
    "Robot",
    "RunResult",
    "Score",
    "run",
]
