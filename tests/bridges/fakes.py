"""An in-memory Link: what a bridge sends is recorded, readings are fed by the test."""

from __future__ import annotations

import threading
import time

from robocog.bridges.body import RobotBody


class FakeLink:
    """Records requests with their time; ``body`` is set when the link is started."""

    def __init__(self) -> None:
        self.body: RobotBody | None = None
        self.sent: list[tuple[float, str, tuple[object, ...]]] = []
        self.closed = False
        self.lock = threading.Lock()
        self.tokens = 0
        self.on_gripper_request: str | None = None
        #: when set, every goal ends with this status shortly after it is sent
        self.goal_status: str | None = None

    def start(self, body: RobotBody) -> None:
        self.body = body

    def close(self) -> None:
        self.closed = True

    def _record(self, kind: str, *args: object) -> None:
        with self.lock:
            self.sent.append((time.monotonic(), kind, args))

    def send_velocity(self, linear: float, angular: float) -> None:
        self._record("twist", linear, angular)

    def send_goal(self, x: float, y: float, yaw: float) -> int:
        self.tokens += 1
        self._record("goal", x, y, yaw, self.tokens)
        if self.goal_status is not None and self.body is not None:
            timer = threading.Timer(0.01, self.body.on_goal_result, (self.tokens, self.goal_status))
            timer.start()
        return self.tokens

    def cancel_goals(self) -> None:
        self._record("cancel")

    def send_gripper(self, text: str) -> int | None:
        self._record("gripper", text)
        if self.on_gripper_request is not None and self.body is not None:
            self.body.on_gripper(self.on_gripper_request)
        return None

    def of(self, kind: str) -> list[tuple[object, ...]]:
        with self.lock:
            return [args for _t, k, args in self.sent if k == kind]

    def times(self, kind: str) -> list[float]:
        with self.lock:
            return [t for t, k, _args in self.sent if k == kind]
