"""The house of the domestic robot: a 7x7 grid with the fridge in one corner, the owner
in the opposite one and the robot in the middle; what each agent perceives of it."""

from __future__ import annotations

import threading

from robocog.bdi.actions import ActionHandle
from robocog.bdi.environment import Environment
from robocog.bdi.terms import Literal

SIZE = 7
FRIDGE = (0, 0)
OWNER = (SIZE - 1, SIZE - 1)


class HouseEnv(Environment):
    """Actions: ``open(fridge)``, ``close(fridge)``, ``get(beer)``, ``hand_in(beer)``,
    ``move_towards(fridge|owner)`` for the robot, ``sip(beer)`` for the owner,
    ``deliver(beer, N)`` for the supermarket (it takes four seconds)."""

    def init(self, args: list) -> None:
        self.robot = [SIZE // 2, SIZE // 2]
        self.fridge_open = False
        self.carrying = False
        self.sips = 0
        self.beers = 2
        self.update()

    def update(self) -> None:
        """Jason's updatePercepts: where the robot is, the stock while the fridge is
        open, and whether the owner has beer."""
        self.clear_percepts("robot")
        self.clear_percepts("owner")
        at = tuple(self.robot)
        if at == FRIDGE:
            self.add_percept("at(robot,fridge)", agent="robot")
        if at == OWNER:
            self.add_percept("at(robot,owner)", agent="robot")
        if self.fridge_open:
            self.add_percept(f"stock(beer,{self.beers})", agent="robot")
        if self.sips > 0:
            self.add_percept("has(owner,beer)", agent="robot")
            self.add_percept("has(owner,beer)", agent="owner")

    def execute_action(self, agent: str, action: Literal) -> bool | ActionHandle:
        print(f"[{agent}] doing: {action}", flush=True)
        name = action.functor
        arg = str(action.args[0]) if action.args else ""
        ok = False
        if name == "open" and not self.fridge_open:
            self.fridge_open = ok = True
        elif name == "close" and self.fridge_open:
            self.fridge_open, ok = False, True
        elif name == "move_towards" and arg in ("fridge", "owner"):
            goal = FRIDGE if arg == "fridge" else OWNER
            for k in (0, 1):
                self.robot[k] += (goal[k] > self.robot[k]) - (goal[k] < self.robot[k])
            ok = True
        elif name == "get" and self.fridge_open and self.beers > 0 and not self.carrying:
            self.beers -= 1
            self.carrying = ok = True
        elif name == "hand_in" and self.carrying:
            self.sips, self.carrying, ok = 10, False, True
        elif name == "sip" and self.sips > 0:
            self.sips -= 1
            ok = True
        elif name == "deliver":

            def delivered() -> None:  # four seconds later, as the Java version sleeps
                self.beers += int(action.args[1])
                self.update()

            return self._after(4.0, delivered)
        if not ok:
            return False
        self.update()
        return self._after(0.1)  # the Java version sleeps 100 ms after each action

    @staticmethod
    def _after(seconds: float, then: object = None) -> ActionHandle:
        """An outcome that arrives ``seconds`` later (the agent waits, the others run)."""
        handle = ActionHandle()

        def done() -> None:
            if callable(then):
                then()
            handle.succeed()

        timer = threading.Timer(seconds, done)
        timer.daemon = True  # a run that stops does not wait for it
        timer.start()
        return handle
