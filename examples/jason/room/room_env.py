"""The room's door: the porter's ``lock`` and ``unlock`` actions, and what every agent
perceives of the door (``locked(door)`` or ``~locked(door)``)."""

from __future__ import annotations

from robocog.bdi.environment import Environment
from robocog.bdi.terms import Literal

LOCKED = "locked(door)"
UNLOCKED = "~locked(door)"


class RoomEnv(Environment):
    """A door that starts locked; each action is reported on stdout as Jason's does."""

    def init(self, args: list) -> None:
        self.locked = True
        self.add_percept(LOCKED)

    def execute_action(self, agent: str, action: Literal) -> bool:
        print(f"Agent {agent} is doing {action}", flush=True)
        if action.functor in ("lock", "unlock"):
            self.locked = action.functor == "lock"
        self.clear_percepts()
        self.add_percept(LOCKED if self.locked else UNLOCKED)
        return True
