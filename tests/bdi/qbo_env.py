"""A small room for the Q.bo plans: the robot, a door, and the room's entry.

Directions are compass degrees (0 = +y, 90 = +x). ``looking_Qbo`` sees a target within
60 degrees of the heading and 9 m; ``forward_Qbo`` turns to a direction and moves one
step unless a wall is in the way (then ``found_obstacle`` is perceived);
``search_Qbo`` turns by 30-degree increments, alternating sides around the given
direction, until the way is free, then moves. ``front_of(X)`` is perceived within 1 m.
Actions can complete at once or later (``deferred=True``), like a real robot's. With a
``decoy``, the nearer of the door and the decoy is taken for the door, as the robot of
the paper's second experiment took the opposite door for the target.
"""

from __future__ import annotations

import math

from robocog.bdi import ActionHandle, Agent, Literal


class QboRoom:
    """The environment of the paper's first experiment, small enough to reason about."""

    def __init__(
        self,
        agent: Agent,
        start: tuple[float, float] = (5.0, 2.0),
        heading: float = 90.0,
        door: tuple[float, float] = (5.0, 10.0),
        entry: tuple[float, float] = (8.5, 10.5),
        size: tuple[float, float] = (10.0, 11.0),
        deferred: bool = False,
        decoy: tuple[float, float] | None = None,
    ) -> None:
        self.agent = agent
        self.x, self.y = start
        self.heading = heading
        self.targets = {"door": door, "entry": entry}
        self.size = size
        self.deferred = deferred
        #: a second place that looks like the door (the paper's second experiment)
        self.decoy = decoy
        self.pending: list[tuple[ActionHandle, str, float]] = []
        self.log: list[str] = []
        self.visible: str | None = None
        self.obstacle = False
        agent.register_action("looking_Qbo", self.looking)
        agent.register_action("tcp_write", self.tcp_write, raw=True)
        self.perceive()

    # ---- geometry
    def _place(self, name: str) -> tuple[float, float]:
        tx, ty = self.targets[name]
        if name == "door" and self.decoy is not None:
            dx, dy = self.decoy
            if math.hypot(dx - self.x, dy - self.y) < math.hypot(tx - self.x, ty - self.y):
                return self.decoy
        return tx, ty

    def bearing(self, name: str) -> float:
        tx, ty = self._place(name)
        return math.degrees(math.atan2(tx - self.x, ty - self.y)) % 360

    def distance(self, name: str) -> float:
        tx, ty = self._place(name)
        return math.hypot(tx - self.x, ty - self.y)

    def blocked(self, direction: float) -> bool:
        nx = self.x + math.sin(math.radians(direction))
        ny = self.y + math.cos(math.radians(direction))
        w, h = self.size
        return not (0.0 <= nx <= w and 0.0 <= ny <= h)

    # ---- percepts
    def perceive(self) -> None:
        ps = [Literal("my_current_direction", (round(self.heading) % 360,))]
        if self.obstacle:
            ps.append(Literal("found_obstacle"))
        if self.visible is not None:
            ps.append(Literal("found_target", (Literal(self.visible),)))
            ps.append(Literal("target_direction", (round(self.bearing(self.visible)),)))
        for name in self.targets:
            if self.distance(name) < 1.0:
                ps.append(Literal("front_of", (Literal(name),)))
        self.agent.set_percepts(ps)

    # ---- actions
    def looking(self, target: str) -> bool:
        self.log.append(f"looking_Qbo({target})")
        diff = (self.bearing(target) - self.heading + 180) % 360 - 180
        self.visible = target if abs(diff) <= 60 and self.distance(target) <= 9 else None
        self.perceive()
        return True

    def tcp_write(self, command: Literal) -> bool | ActionHandle:
        name = command.functor
        direction = float(command.args[0])
        self.log.append(f"{name}({command.args[0]!r})")
        if name not in ("forward_Qbo", "search_Qbo"):
            return False
        if self.deferred:
            h = ActionHandle()
            self.pending.append((h, name, direction))
            return h
        self.move(name, direction)
        return True

    def move(self, name: str, direction: float) -> None:
        if name == "search_Qbo":
            for k in range(12):
                off = 30 * ((k + 1) // 2) * (1 if k % 2 else -1)
                if not self.blocked(direction + off):
                    direction = direction + off
                    break
        self.heading = direction % 360
        self.obstacle = self.blocked(self.heading)
        if not self.obstacle:
            self.x += math.sin(math.radians(self.heading))
            self.y += math.cos(math.radians(self.heading))
            self.obstacle = self.blocked(self.heading)
        self.visible = None
        self.perceive()

    def complete_pending(self) -> int:
        """The robot reports the outcome of the actions it was given."""
        done = 0
        while self.pending:
            h, name, direction = self.pending.pop(0)
            self.move(name, direction)
            h.succeed()
            done += 1
        return done
