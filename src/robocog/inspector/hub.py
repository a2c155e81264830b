"""The inspector's side of the robot loop: snapshots in, commands out, never a wait on a socket.

``Inspector.watch(world, mind, loop)`` hooks one loop from outside: it returns the
``on_step`` callback for ``Loop.run`` and wraps ``loop.body`` to keep each frame's
percepts. After every cycle the callback, in the robot's thread,

1. applies the commands the page queued (Narsese to tell or ask, beliefs and goals for
   an agent, English goals for the planner) through the engine's own reader, and
   records each reply or error for the console;
2. takes a snapshot: the world's view every cycle, the mind's view as often as its
   time budget allows (``mind_budget``: the share of wall time mind views may cost),
   and always while paused or stepping;
3. puts it in the ring buffer (:class:`~robocog.inspector.snapshot.History`), which
   drops the oldest;
4. waits while the page has paused the loop (on a condition, not on the network),
   still applying commands and snapshotting after each, until resumed or stepped.

The web server only ever reads the ring buffer and appends to the command queue, each
under a lock held for an in-memory copy; a slow or vanished browser slows nothing here.
"""

from __future__ import annotations

import threading
import time
from collections import deque
from collections.abc import Callable, Sequence
from typing import Any

from robocog.inspector.snapshot import History, Snapshot
from robocog.inspector.views import Json, mind_viewer, world_viewer
from robocog.robot.commands import Command, Outcome
from robocog.robot.loop import Loop, Step
from robocog.robot.percepts import Percept

#: the longest console line accepted (characters)
MAX_INPUT = 4000
#: commands waiting for the loop; more are refused until it takes them
MAX_QUEUED = 64
#: console entries kept
CONSOLE = 200
#: the mind command kinds the console offers
MIND_COMMANDS = ("tell", "ask", "belief", "goal", "query", "english")
CONTROL = ("pause", "resume", "step", "stop")


class Recorder:
    """A Body in front of the real one that keeps the last frame's percepts.

    The loop reads percepts through it, so the inspector sees exactly what the mind
    saw (the detections of this frame) without the world having to keep them.
    """

    def __init__(self, body: Any) -> None:
        self.body = body
        self.last: list[Percept] = []

    def percepts(self) -> list[Percept]:
        """The body's percepts, remembered."""
        self.last = self.body.percepts()
        return self.last

    def execute(self, command: Command) -> Outcome:
        """Passed on unchanged."""
        return self.body.execute(command)

    def time(self) -> float:
        """The body's clock."""
        return self.body.time()

    def __getattr__(self, name: str) -> Any:
        # everything else a runner asks of its body (a bridge's waits and halts)
        return getattr(self.body, name)


class Inspector:
    """Snapshots of one running world and mind, and the page's commands for them."""

    def __init__(
        self,
        capacity: int = 3000,
        mind_budget: float = 0.01,
        min_mind_interval: float = 0.5,
        world_budget: float | None = None,
    ) -> None:
        self.history = History(capacity)
        self.mind_budget = mind_budget
        #: the share of wall time snapshots of the world may take (None: every cycle)
        self.world_budget = world_budget
        self._next_world = 0.0
        self.min_mind_interval = min_mind_interval
        self._lock = threading.Lock()
        self._wake = threading.Condition(self._lock)
        self._queue: deque[Json] = deque()
        self.console: deque[Json] = deque(maxlen=CONSOLE)
        self._next_id = 1
        self._stop_command = False
        self.paused = False
        self._steps = 0
        self.closed = False
        #: asked between waits: true ends a pause and the lingering as closing does
        #: (the command's Ctrl-C, whose own raise can be lost in a __del__)
        self.interrupted: Callable[[], bool] | None = None
        self.run_label = ""
        self.runs = 0
        self.world: Any = None
        self.mind: Any = None
        self.loop: Loop | None = None
        self._world_view: Callable[[Any, Sequence[Percept] | None], Json] | None = None
        self._mind_view: Any = None
        self._recorder: Recorder | None = None
        self._mind_json: Json | None = None
        self._mind_seq = -1
        self._next_mind = 0.0
        self._cycle = 0
        self.live = True

    # ---- hooking a loop (robot thread) -----------------------------------------

    def watch(self, world: Any, mind: Any, loop: Any, label: str = "") -> Callable[[Step], None]:
        """Hook ``loop`` (running ``mind`` on ``world``): returns its ``on_step``.

        ``loop`` is a :class:`Loop`, or anything that reads its body from a ``body``
        attribute and calls ``on_step`` after each cycle (a bridge's runner)."""
        self.finish()
        if self._mind_view is not None and hasattr(self._mind_view, "detach"):
            self._mind_view.detach()
        self.world, self.mind, self.loop = world, mind, loop
        self._world_view = world_viewer(world)
        self._mind_view = mind_viewer(mind)
        self._recorder = Recorder(loop.body)
        loop.body = self._recorder
        self.runs += 1
        self.run_label = label or f"run {self.runs}: {getattr(mind, 'name', type(mind).__name__)}"
        self._cycle = 0
        self._mind_json = None
        self._next_mind = 0.0
        self.snapshot(None, force_mind=True)
        return self.on_step

    def finish(self) -> None:
        """Snapshot the last run as it ended, its mind included (the budget may have
        skipped the mind's last cycles); nothing when that is already the newest."""
        latest = self.history.latest()
        if self._world_view is None or latest is None:
            return
        if latest.mind_seq != latest.seq or latest.run != self.run_label:
            self.snapshot(None, force_mind=True)

    def watcher(self, label: Callable[[Any, Any], str] | None = None) -> Callable[..., Any]:
        """A ``watch`` for code that makes its own loops: ``(world, mind, loop) -> on_step``."""

        def hook(world: Any, mind: Any, loop: Loop) -> Callable[[Step], None]:
            return self.watch(world, mind, loop, label(world, mind) if label else "")

        return hook

    def on_step(self, step: Step | None) -> None:
        """After each cycle: apply commands, snapshot, and wait while paused.

        Every cycle is snapshotted, unless a ``world_budget`` is given: then a loop
        so fast that snapshotting every cycle would cost more than that share of its
        time (a BDI agent on the garbage field decides in a tenth of a millisecond)
        is sampled so that it does not. Cycles after a command, or while paused or
        stepping, are always taken."""
        self._cycle += 1
        applied = self.apply_commands()
        if applied or self.paused or time.perf_counter() >= self._next_world:
            self.snapshot(step, force_mind=applied or self.paused)
        if self.paused:
            self.hold()

    def hold(self) -> None:
        """While paused, serve commands until resumed or asked for one step (or
        closed, or interrupted)."""
        while not self.closed and not (self.interrupted and self.interrupted()):
            with self._lock:
                if not self.paused:
                    return
                if self._steps > 0:
                    self._steps -= 1
                    return
                if not self._queue:
                    self._wake.wait(0.1)
            if self.apply_commands():
                self.snapshot(None, force_mind=True)

    def snapshot(self, step: Step | None, force_mind: bool = False) -> None:
        """Take a view of the world (and, within the budget, of the mind) into history."""
        if self._world_view is None:
            return
        now = time.perf_counter()
        # (the cost of this snapshot, the mind's view aside, sets when the next is due)
        percepts = self._recorder.last if self._recorder is not None else None
        world = self._world_view(self.world, percepts)
        seq = self.history.next_seq
        mind_cost = 0.0
        if self._mind_view is not None and (force_mind or now >= self._next_mind):
            started = time.perf_counter()
            try:
                self._mind_json = self._mind_view.view()
            except Exception as exc:  # a view must never stop the robot
                self._mind_json = {"kind": "error", "error": f"{type(exc).__name__}: {exc}"}
            cost = mind_cost = time.perf_counter() - started
            self._mind_seq = seq
            self._next_mind = started + max(self.min_mind_interval, cost / self.mind_budget)
        stats: Json = {}
        actions: list[list[str]] = []
        if step is not None:
            stats = {
                "cycle_ms": round(step.cycle_seconds * 1e3, 3),
                "reason_ms": round(step.reason_seconds * 1e3, 3),
            }
            actions = [[str(c), o.status.value, o.reason or ""] for c, o in step.actions]
        self.history.add(
            Snapshot(
                seq=seq,
                run=self.run_label,
                cycle=self._cycle,
                wall=time.time(),
                world=world,
                mind=self._mind_json,
                mind_seq=self._mind_seq,
                stats=stats,
                actions=actions,
            )
        )
        if self.world_budget:
            spent = time.perf_counter() - now - mind_cost
            self._next_world = now + spent / self.world_budget

    # ---- commands (server thread submits, robot thread applies) ----------------------

    def submit(self, kind: str, text: str = "") -> Json:
        """Queue a console command; control commands act at once. Returns its entry.

        Raises ValueError for an unknown kind, a line too long, or a full queue.
        """
        if kind not in MIND_COMMANDS + CONTROL:
            raise ValueError(f"unknown command {kind!r}")
        if len(text) > MAX_INPUT:
            raise ValueError(f"a console line is at most {MAX_INPUT} characters")
        with self._lock:
            entry: Json = {"id": self._next_id, "kind": kind, "text": text, "status": "queued"}
            self._next_id += 1
            if kind == "pause":
                self.paused = True
                entry.update(status="ok", reply="paused")
            elif kind == "resume":
                self.paused = False
                self._steps = 0
                entry.update(status="ok", reply="running")
            elif kind == "step":
                if not self.paused:
                    self.paused = True
                self._steps += 1
                entry.update(status="ok", reply="one cycle")
            elif kind == "stop":
                # the console command running now ends at its next slice (a NARS
                # cycles line every hundred cycles); the ones queued behind it still run
                self._stop_command = True
                entry.update(status="ok", reply="stopping the running command")
            else:
                if not self.live:
                    raise ValueError("this is a recorded run: there is no mind to instruct")
                if len(self._queue) >= MAX_QUEUED:
                    raise ValueError("too many commands waiting for the loop; try again")
                self._queue.append(entry)
            self.console.append(entry)
            self._wake.notify_all()
            return dict(entry)

    def apply_commands(self) -> bool:
        """Apply the queued commands to the mind (robot thread). True if any was."""
        if not self._queue:
            return False
        with self._lock:
            todo = list(self._queue)
            self._queue.clear()
        for entry in todo:
            view = self._mind_view
            self._stop_command = False
            try:
                if view is None:
                    raise ValueError("this mind offers no console")
                if hasattr(view, "should_stop"):
                    view.should_stop = self.command_stopped
                reply = view.command(entry["kind"], entry["text"])
                status = "ok"
            except Exception as exc:  # the engine's reader names line and column
                reply, status = f"{type(exc).__name__}: {exc}", "error"
            with self._lock:
                entry["reply"] = reply
                entry["status"] = status
                entry["cycle"] = self._cycle
        return True

    def command_stopped(self) -> bool:
        """Whether the console command running now should end (the page's ``stop``, the
        inspector closing, or the command's Ctrl-C): asked by the mind's view between
        slices of its work."""
        interrupted = self.interrupted
        return self._stop_command or self.closed or bool(interrupted and interrupted())

    def console_entries(self, after: int = 0) -> list[Json]:
        """Console entries with an id above ``after`` (copies)."""
        with self._lock:
            return [dict(e) for e in self.console if e["id"] > after]

    def state(self) -> Json:
        """Paused or running, the run's label, the history's range."""
        with self._lock:
            paused, steps = self.paused, self._steps
        first, last = self.history.bounds()
        return {
            "live": self.live,
            "paused": paused,
            "steps_pending": steps,
            "run": self.run_label,
            "first": first,
            "last": last,
            "dropped": self.history.dropped,
        }

    # ---- after the run ----------------------------------------------------------------

    def linger(self, stop: Callable[[], bool] | None = None, max_cycles: int = 100_000) -> None:
        """Keep the last world and mind at the page's disposal after the run ended: apply
        commands, and run the loop while the mind has work (a planner's request) or the
        page asks for steps. Returns when ``stop()`` is true or the inspector is closed."""
        ran = 0
        self.finish()
        interrupted = self.interrupted
        while not self.closed and not (stop and stop()) and not (interrupted and interrupted()):
            with self._lock:
                if not self._queue and not self._steps and not self._busy():
                    self._wake.wait(0.1)
                stepping = self._steps > 0
                if stepping:
                    self._steps -= 1
            applied = self.apply_commands()
            if self.loop is not None and (stepping or (self._busy() and not self.paused)):
                if ran < max_cycles:
                    step = self.loop.step()
                    ran += 1
                    self._cycle += 1
                    self.snapshot(step, force_mind=True)
                    continue
            if applied:
                self.snapshot(None, force_mind=True)

    def _busy(self) -> bool:
        return bool(getattr(self.mind, "busy", False))

    def close(self) -> None:
        """Let a paused or lingering loop go."""
        with self._lock:
            self.closed = True
            self.paused = False
            self._wake.notify_all()
        if self._mind_view is not None and hasattr(self._mind_view, "detach"):
            self._mind_view.detach()
