"""Procedure-learning worlds after ONA's system tests, and the runner that drives them.

Each environment is a seeded world (``reset(seed)``, ``step()``, ``execute(op)``, a
success counter) with the rules of one of ONA's ``src/system_tests``; a reasoner is
anything that takes Narsese lines and cycle counts and reports the operations it
executed (:class:`~robocog.worlds.procedures.runner.Reasoner`). The worlds speak
Narsese as text and know no engine; the reasoners (ONA's shell through pipes, robocog's
NAR, a scripted policy) are in :mod:`robocog.experiments.procedures`.
"""

from .alien import Alien
from .bandrobot import Bandrobot
from .base import Feed, ProcedureEnv, Score
from .cartpole import Cartpole
from .pong import Pong, Pong2
from .robot import Robot
from .runner import Reasoner, RunResult, run

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
    "Reasoner",
    "Robot",
    "RunResult",
    "Score",
    "run",
]
