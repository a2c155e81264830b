"""ROS 2 actions on bare DDS, as rmw_cyclonedds lays them out.

An action ``/name`` is three services and two topics: ``send_goal``, ``get_result`` and
``cancel_goal`` (requests on ``rq/name/_action/<service>Request``, replies on
``rr/name/_action/<service>Reply``, each sample led by the client's id and a sequence
number), ``feedback`` and ``status`` on ``rt/name/_action/...``. The client here sends
a goal, asks for its result as soon as the goal is accepted (as rclpy does), and hands
feedback and the final status to callbacks; the server accepts goals, runs each in a
callback and answers result requests when the goal ends, also for requests that came
before the end. Both keep to the link's one reading thread: they only offer their
readers and handlers, and never block on the network.
"""

from __future__ import annotations

import itertools
import logging
import random
import threading
import time
import uuid
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from cyclonedds.core import Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from robocog.bridges.ros2 import messages as m

log = logging.getLogger("robocog.bridges.ros2")

Handler = tuple[DataReader, Callable[[Any], None]]
#: (status word, result message or None) -> None
DoneCallback = Callable[[str, Any], None]


def _names(action: str) -> dict[str, str]:
    base = m.topic_name(action.rstrip("/") + "/_action", "").lstrip("/")
    return {
        "send_goal": base + "/send_goal",
        "get_result": base + "/get_result",
        "cancel_goal": base + "/cancel_goal",
        "feedback": base + "/feedback",
        "status": base + "/status",
    }


def _uuid_list(goal_id: bytes) -> list[int]:
    return list(goal_id)


class _Entities:
    """Topic creation shared by the client and the server."""

    def __init__(self, dp: DomainParticipant, qos: Qos) -> None:
        self.dp = dp
        self.qos = qos

    def topic(self, name: str, kind: type) -> Topic:
        return Topic(self.dp, name, kind, qos=self.qos)

    def writer(self, name: str, kind: type) -> DataWriter:
        return DataWriter(self.dp, self.topic(name, kind), qos=self.qos)

    def reader(self, name: str, kind: type) -> DataReader:
        return DataReader(self.dp, self.topic(name, kind), qos=self.qos)


@dataclass
class _ClientGoal:
    goal_id: bytes
    on_done: DoneCallback
    on_feedback: Callable[[Any], None] | None
    accepted: bool = False


class ActionClient:
    """The client side of one action."""

    def __init__(
        self,
        dp: DomainParticipant,
        action: str,
        types: m.ActionTypes,
        qos: Qos,
        on_write: Callable[[str, Any], None] | None = None,
    ) -> None:
        names = _names(action)
        e = _Entities(dp, qos)
        self.action = action
        #: told (DDS topic, request) of every goal sent, to record a run
        self.on_write = on_write
        self.types = types
        self.guid = random.getrandbits(63)
        self._seq = itertools.count(1)
        self._lock = threading.Lock()
        self._goals: dict[bytes, _ClientGoal] = {}
        self._send_seq: dict[int, bytes] = {}
        self._result_seq: dict[int, bytes] = {}
        self._warned: set[str] = set()
        self._send = e.writer("rq/" + names["send_goal"] + "Request", types.send_goal_request)
        self._result = e.writer("rq/" + names["get_result"] + "Request", types.get_result_request)
        self._cancel = e.writer("rq/" + names["cancel_goal"] + "Request", m.CancelGoalRequest)
        self.handlers: list[Handler] = [
            (
                e.reader("rr/" + names["send_goal"] + "Reply", types.send_goal_response),
                self._on_sent,
            ),
            (
                e.reader("rr/" + names["get_result"] + "Reply", types.get_result_response),
                self._on_result,
            ),
            (e.reader("rr/" + names["cancel_goal"] + "Reply", m.CancelGoalResponse), self._ignore),
            (e.reader("rt/" + names["feedback"], types.feedback_message), self._on_feedback),
            (e.reader("rt/" + names["status"], m.GoalStatusArray), self._ignore),
        ]

    def server_ready(self) -> bool:
        """True when a server's request readers and reply writers are matched."""
        try:
            return bool(
                self._send.get_matched_subscriptions()
                and self._result.get_matched_subscriptions()
                and self.handlers[0][0].get_matched_publications()
                and self.handlers[1][0].get_matched_publications()
            )
        except Exception:  # noqa: BLE001 - a closed participant: not ready
            return False

    def wait_for_server(self, timeout: float) -> bool:
        """Wait until ``server_ready()`` or the time is up (as rclpy's wait_for_server)."""
        end = time.monotonic() + timeout
        while not self.server_ready():
            if time.monotonic() >= end:
                return False
            time.sleep(0.02)
        return True

    def send_goal(
        self,
        goal: Any,
        on_done: DoneCallback,
        on_feedback: Callable[[Any], None] | None = None,
    ) -> bytes:
        """Send ``goal``; ``on_done(status, result)`` is called once, from the reading
        thread, when the goal ends or is rejected. Returns the goal's id."""
        goal_id = uuid.uuid4().bytes
        seq = next(self._seq)
        with self._lock:
            self._goals[goal_id] = _ClientGoal(goal_id, on_done, on_feedback)
            self._send_seq[seq] = goal_id
        request = self.types.send_goal_request(self.guid, seq, m.UUID(_uuid_list(goal_id)), goal)
        # recorded before it is sent: a reply recorded by another thread comes after it
        if self.on_write is not None:
            self.on_write(self._send.topic.name, request)
        self._send.write(request)
        return goal_id

    def forget(self, goal_id: bytes) -> None:
        """Stop waiting for a goal (its late result is then dropped quietly)."""
        with self._lock:
            self._goals.pop(goal_id, None)

    def cancel_all(self) -> None:
        """Cancel every goal of this action (a zero goal id and a zero stamp)."""
        self._cancel.write(m.CancelGoalRequest(self.guid, next(self._seq)))

    # -- the reading thread --------------------------------------------------------

    def _once(self, key: str, message: str, *args: object) -> None:
        if key not in self._warned:
            self._warned.add(key)
            log.warning(message, *args)

    def _on_sent(self, reply: Any) -> None:
        if reply.client_guid != self.guid:
            return  # another client's reply
        with self._lock:
            goal_id = self._send_seq.pop(reply.sequence_number, None)
            goal = self._goals.get(goal_id) if goal_id is not None else None
        if goal is None:
            self._once("sent", "%s: a goal reply for no goal of ours; ignored", self.action)
            return
        if not reply.accepted:
            self.forget(goal.goal_id)
            goal.on_done("rejected", None)
            return
        goal.accepted = True
        seq = next(self._seq)
        with self._lock:
            self._result_seq[seq] = goal.goal_id
        self._result.write(
            self.types.get_result_request(self.guid, seq, m.UUID(_uuid_list(goal.goal_id)))
        )

    def _on_result(self, reply: Any) -> None:
        if reply.client_guid != self.guid:
            return
        with self._lock:
            goal_id = self._result_seq.pop(reply.sequence_number, None)
            goal = self._goals.pop(goal_id, None) if goal_id is not None else None
        if goal is None:
            self._once("result", "%s: a result of an unknown goal; ignored", self.action)
            return
        goal.on_done(m.STATUS_WORDS.get(reply.status, f"status {reply.status}"), reply.result)

    def _on_feedback(self, message: Any) -> None:
        with self._lock:
            goal = self._goals.get(bytes(message.goal_id.uuid))
        if goal is not None and goal.on_feedback is not None:
            goal.on_feedback(message.feedback)

    def _ignore(self, _message: Any) -> None:
        return


@dataclass
class ServerGoal:
    """One goal on the server: its id, the goal message, and how it ended."""

    goal_id: bytes
    goal: Any
    status: int = m.STATUS_ACCEPTED
    result: Any = None
    cancel_requested: bool = False
    waiting: list[tuple[int, int]] = field(default_factory=list)  # (client guid, seq)


class ActionServer:
    """The server side of one action: ``execute(goal, handle)`` runs each accepted goal
    (on a thread of its own) and ends it with ``handle.succeed/abort/cancel``."""

    def __init__(
        self,
        dp: DomainParticipant,
        action: str,
        types: m.ActionTypes,
        result_type: type,
        qos: Qos,
        execute: Callable[[ServerGoal, ActionServer], None],
        on_cancel: Callable[[bytes], None] | None = None,
    ) -> None:
        names = _names(action)
        e = _Entities(dp, qos)
        self.action = action
        self.types = types
        self.result_type = result_type
        self.execute = execute
        #: told the goal id of every cancel request (all zeros: every goal)
        self.on_cancel = on_cancel
        self._lock = threading.Lock()
        self.goals: dict[bytes, ServerGoal] = {}
        self._send_reply = e.writer("rr/" + names["send_goal"] + "Reply", types.send_goal_response)
        self._result_reply = e.writer(
            "rr/" + names["get_result"] + "Reply", types.get_result_response
        )
        self._cancel_reply = e.writer("rr/" + names["cancel_goal"] + "Reply", m.CancelGoalResponse)
        self._feedback = e.writer("rt/" + names["feedback"], types.feedback_message)
        self._status = e.writer("rt/" + names["status"], m.GoalStatusArray)
        self.handlers: list[Handler] = [
            (
                e.reader("rq/" + names["send_goal"] + "Request", types.send_goal_request),
                self._on_goal,
            ),
            (
                e.reader("rq/" + names["get_result"] + "Request", types.get_result_request),
                self._on_get_result,
            ),
            (
                e.reader("rq/" + names["cancel_goal"] + "Request", m.CancelGoalRequest),
                self._on_cancel,
            ),
        ]

    def _on_goal(self, request: Any) -> None:
        goal_id = bytes(request.goal_id.uuid)
        goal = ServerGoal(goal_id, request.goal)
        with self._lock:
            self.goals[goal_id] = goal
            if len(self.goals) > 1000:  # keep the ended ones of a long run bounded
                for key in [k for k, g in self.goals.items() if g.status >= 4][:500]:
                    del self.goals[key]
        stamp = m.stamp_now(time.time())
        self._send_reply.write(
            self.types.send_goal_response(request.client_guid, request.sequence_number, True, stamp)
        )
        goal.status = m.STATUS_EXECUTING
        self._publish_status()
        threading.Thread(target=self._run, args=(goal,), daemon=True, name="action-goal").start()

    def _run(self, goal: ServerGoal) -> None:
        try:
            self.execute(goal, self)
        except Exception as exc:  # noqa: BLE001 - a failing goal is aborted, not a crash
            log.exception("%s: the goal failed", self.action)
            if goal.status < 4:
                self.finish(goal, m.STATUS_ABORTED, self.result_type())
                del exc

    def finish(self, goal: ServerGoal, status: int, result: Any) -> None:
        """End ``goal`` with ``status`` and answer every result request waiting for it."""
        with self._lock:
            goal.status, goal.result = status, result
            waiting, goal.waiting = goal.waiting, []
        for guid, seq in waiting:
            self._result_reply.write(self.types.get_result_response(guid, seq, status, result))
        self._publish_status()

    def feedback(self, goal: ServerGoal, feedback: Any) -> None:
        """Publish feedback for a goal under way."""
        self._feedback.write(self.types.feedback_message(m.UUID(list(goal.goal_id)), feedback))

    def _on_get_result(self, request: Any) -> None:
        goal_id = bytes(request.goal_id.uuid)
        with self._lock:
            goal = self.goals.get(goal_id)
            if goal is not None and goal.status < 4:
                goal.waiting.append((request.client_guid, request.sequence_number))
                return
        if goal is None:
            status, result = m.STATUS_UNKNOWN, self.result_type()
        else:
            status, result = goal.status, goal.result
        self._result_reply.write(
            self.types.get_result_response(
                request.client_guid, request.sequence_number, status, result
            )
        )

    def _on_cancel(self, request: Any) -> None:
        wanted = bytes(request.goal_info.goal_id.uuid)
        everything = not any(wanted)
        if self.on_cancel is not None:
            self.on_cancel(wanted)
        canceling = []
        with self._lock:
            for goal in self.goals.values():
                if goal.status < 4 and (everything or goal.goal_id == wanted):
                    goal.cancel_requested = True
                    goal.status = m.STATUS_CANCELING
                    canceling.append(m.GoalInfo(m.UUID(list(goal.goal_id))))
        code = 0 if canceling else 2  # ERROR_NONE, else ERROR_UNKNOWN_GOAL_ID
        self._cancel_reply.write(
            m.CancelGoalResponse(request.client_guid, request.sequence_number, code, canceling)
        )
        self._publish_status()

    def _publish_status(self) -> None:
        with self._lock:
            entries = [
                m.GoalStatus(m.GoalInfo(m.UUID(list(g.goal_id))), g.status)
                for g in self.goals.values()
                if g.status < 4
            ]
        self._status.write(m.GoalStatusArray(entries))
