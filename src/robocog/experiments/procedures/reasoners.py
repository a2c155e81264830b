"""Reasoners that can drive a procedure-learning world (:mod:`robocog.worlds.procedures`).

They live here, not beside the worlds, because one of them runs robocog's NARS engine
and the worlds know no engine; the worlds' runner drives any object with the
:class:`~robocog.worlds.procedures.runner.Reasoner` protocol.

A reasoner takes feeds (Narsese lines, one cycle each, and counts of free cycles) and
returns the operations it executed while digesting them, in order:

* :class:`OnaShell` runs ONA's ``NAR shell`` as a child process and talks to it through
  pipes, configured the way ONA's own system tests configure the reasoner (operation
  names and ids, babbling operations, babbling chance).
* :class:`RobocogNar` wraps ``robocog.nars.NAR``; it refuses to start, with the reason,
  when that engine cannot yet execute a learned procedure.
* :class:`PolicyReasoner` answers each goal with a scripted policy, which gives the
  environments' tests and the benchmark a perfect and a random baseline.
* :class:`TracingReasoner` wraps any of them and writes a replayable trace.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Sequence
from typing import Any

from robocog.ona_process import (
    OnaError,
    OnaProcess,
    OnaUnavailable,
    ona_command,
    unavailable_reason,
)
from robocog.worlds.procedures.base import Feed, ProcedureEnv
from robocog.worlds.procedures.runner import Reasoner

_EXECUTED = re.compile(r"^(\^\S+) executed with args")


class ReasonerUnavailable(RuntimeError):
    """The reasoner cannot run here; the message says why."""


class ReasonerError(RuntimeError):
    """The reasoner failed during a run (died, timed out, rejected input)."""


def setup_commands(env: ProcedureEnv) -> list[str]:
    """Shell commands that configure a reasoner as ONA's test configures it for ``env``.

    The operations get ONA's ids in the test's order, babbling is limited to them (the
    shell starts with ten operations registered), and the babbling chance is the test's.
    """
    commands = [f"*setopname {i} {op}" for i, op in enumerate(env.operations, start=1)]
    commands += [f"*babblingops={len(env.operations)}", f"*motorbabbling={env.babbling_chance}"]
    return commands + list(env.shell_setup)


#: the command that starts ONA's binary, or None when ONA is not installed
ona_executable = ona_command


class OnaShell:
    """ONA's ``NAR shell`` driven through pipes, one child process per run.

    The process is a :class:`robocog.ona_process.OnaProcess`: each feed is written in one
    go followed by a sync comment, and the reply is read (with a timeout) up to the
    comment's echo; the ``^op executed with args`` lines in it are the executed
    operations. ``*volume=0`` keeps ONA from printing derivations, which would only cost
    time. Any failure of the process (it died, timed out, rejected an input) is a
    :class:`ReasonerError` quoting ONA's last output.
    """

    name = "ona-shell"

    def __init__(self, timeout: float = 60.0, command: Sequence[str] | None = None) -> None:
        self.timeout = timeout
        self.command = list(command) if command else None
        self._process: OnaProcess | None = None

    @staticmethod
    def unavailable_reason() -> str | None:
        """None when ONA's binary is installed, else why the shell cannot run."""
        return unavailable_reason()

    def start(self, env: ProcedureEnv, seed: int) -> None:
        """Start ``NAR shell`` and configure it as ONA's test configures the reasoner.

        ONA's shell always seeds its own random generator with 666; ``seed`` only
        affects the environment.
        """
        self.close()
        try:
            self._process = OnaProcess(self.command, timeout=self.timeout)
        except OnaUnavailable as exc:
            raise ReasonerUnavailable(str(exc)) from exc
        self._exchange(["*volume=0", *setup_commands(env)])

    def feed(self, feed: Feed) -> list[str]:
        """Send the feed and return the operations ONA executed while processing it."""
        lines = []
        for item in feed:
            if isinstance(item, int):
                if item > 0:
                    lines.append(str(item))
            elif item.strip():
                lines.append(item.strip())
        return self._exchange(lines) if lines else []

    def close(self) -> None:
        """End the child process: politely with ``quit``, by force if it misbehaved."""
        process, self._process = self._process, None
        if process is not None:
            process.close()

    def _exchange(self, lines: list[str]) -> list[str]:
        """Write lines, read the reply; the operations executed in it."""
        if self._process is None:
            raise ReasonerError("ONA's shell is not running")
        try:
            reply = self._process.exchange(lines)
        except OnaError as exc:
            raise ReasonerError(str(exc)) from exc
        return [found.group(1) for line in reply if (found := _EXECUTED.match(line))]


def _set_first(obj: Any, names: Sequence[str], value: Any) -> bool:
    """Set the first of ``names`` that ``obj`` has; report whether one was set."""
    for name in names:
        if obj is not None and hasattr(obj, name):
            setattr(obj, name, value)
            return True
    return False


def _clock(nar: Any) -> int | None:
    """The NAR's current time, whatever the attribute is called, or None."""
    for name in ("current_time", "time", "currentTime"):
        value = getattr(nar, name, None)
        if isinstance(value, int):
            return value
    return None


class RobocogNar:
    """robocog's own NAR, configured with the same shell commands as :class:`OnaShell`.

    ``seed`` seeds the NAR's random generator (motor babbling).

    ``add_input`` is expected to cost one cycle per belief or goal, as ONA's shell does;
    when the engine's clock shows it does not, one cycle is run after each input.
    """

    name = "robocog"
    _probe: str | None | bool = False  # False = not probed yet
    _needs_cycle = False  # add_input does not advance the clock

    def __init__(self, seed: int = 666) -> None:
        self.seed = seed
        self.nar: Any = None
        self._executed: list[str] = []
        self._cycle_after_input = False

    @classmethod
    def unavailable_reason(cls) -> str | None:
        """None when robocog's NAR learns and executes procedures, else the reason.

        The probe is the smallest sensorimotor task: given ``<(a &/ ^left) =/> g>``,
        the event ``a`` and the goal ``g``, the reasoner must execute ``^left``.
        """
        if cls._probe is False:
            cls._probe = cls._run_probe()
        return cls._probe  # type: ignore[return-value]

    @classmethod
    def _run_probe(cls) -> str | None:
        try:
            from robocog.nars import NAR  # type: ignore[attr-defined]
        except ImportError as exc:
            return f"robocog.nars has no NAR yet ({exc})"
        fired: list[object] = []
        try:
            nar = NAR(seed=1)
            nar.register_operation("^left", lambda args=None: fired.append(args))
            _set_first(getattr(nar, "config", None), ("motor_babbling_chance",), 0.0)
            nar.add_input("<(a &/ ^left) =/> g>.")
            before = _clock(nar)
            nar.add_input("a. :|:")
            cls._needs_cycle = before is not None and _clock(nar) == before
            nar.add_input("g! :|:")
            nar.cycles(5)
        except NotImplementedError as exc:
            return f"robocog.nars lacks the sensorimotor half ({exc or 'not implemented'})"
        except Exception as exc:  # noqa: BLE001 - any failure means the engine is not ready
            return f"robocog.nars failed the procedure probe ({type(exc).__name__}: {exc})"
        if not fired:
            return "robocog.nars did not execute ^left for <(a &/ ^left) =/> g>, a. :|:, g! :|:"
        return None

    def start(self, env: ProcedureEnv, seed: int) -> None:
        """A fresh NAR with the environment's operations and babbling chance.

        The NAR's own seed is the one given at construction (666 by default, the seed
        ONA's shell always uses), not the world's ``seed``: both reasoners then draw the
        same random numbers, and in the deterministic Cartpole an exact port of ONA
        reproduces ONA's run count for count.
        """
        reason = self.unavailable_reason()
        if reason:
            raise ReasonerUnavailable(reason)
        from robocog.nars import NAR  # type: ignore[attr-defined]

        self.nar = NAR(seed=self.seed)
        self._executed = []
        try:
            for command in setup_commands(env):
                self.nar.add_input(command)
            for op in env.operations:
                self.nar.register_operation(op, self._recorder(op))
        except Exception as exc:  # noqa: BLE001 - report any refusal as a reasoner failure
            raise ReasonerError(f"robocog's NAR refused the set-up: {exc}") from exc
        self._cycle_after_input = self._needs_cycle

    def _recorder(self, op: str) -> Callable[..., None]:
        def record(args: object = None) -> None:
            self._executed.append(op)

        return record

    def feed(self, feed: Feed) -> list[str]:
        """Input the lines and run the cycles; return the operations executed."""
        self._executed = []
        for item in feed:
            try:
                if isinstance(item, int):
                    if item > 0:
                        self.nar.cycles(item)
                else:
                    self.nar.add_input(item)
                    if self._cycle_after_input:
                        self.nar.cycles(1)
            except Exception as exc:  # noqa: BLE001 - the run fails, the benchmark goes on
                raise ReasonerError(
                    f"robocog's NAR failed on {item!r}: {type(exc).__name__}: {exc}"
                ) from exc
        return self._executed

    def close(self) -> None:
        """Drop the NAR."""
        self.nar = None


class PolicyReasoner:
    """Answers every goal input with ``policy(env)``: an operation name or None.

    It sees the world itself rather than the events, so it is a yardstick, not a
    learner: a perfect policy shows what the rules allow, a random one what chance gives.
    """

    def __init__(self, policy: Callable[[ProcedureEnv], str | None], name: str = "policy") -> None:
        self.policy = policy
        self.name = name
        self.env: ProcedureEnv | None = None

    def start(self, env: ProcedureEnv, seed: int) -> None:
        """Remember the world the policy looks at."""
        self.env = env

    def feed(self, feed: Feed) -> list[str]:
        """One decision per goal line in the feed."""
        assert self.env is not None, "start() first"
        executed = []
        for item in feed:
            if isinstance(item, str) and item.rstrip().endswith(("! :|:", "!")):
                op = self.policy(self.env)
                if op:
                    executed.append(op)
        return executed

    def close(self) -> None:
        """Nothing to release."""
        self.env = None


class TracingReasoner:
    """Wraps a reasoner and writes what it was fed and what it did to a Narsese file.

    The file replays in ONA's shell (operations appear as ``//executed ^op`` comments
    after the feed that caused them), so two reasoners' runs of one world can be diffed
    line by line to find where their decisions part.
    """

    def __init__(self, inner: Reasoner, path: str | os.PathLike[str]) -> None:
        self.inner = inner
        self.name = inner.name
        self.path = path
        self._out: Any = None

    def start(self, env: ProcedureEnv, seed: int) -> None:
        """Open the trace, write the configuration, start the wrapped reasoner."""
        self._out = open(self.path, "w", encoding="utf-8")  # noqa: SIM115 - closed in close()
        self._out.write(f"//{env.name} seed={seed} reasoner={self.inner.name}\n")
        self._out.write("\n".join(setup_commands(env)) + "\n")
        self.inner.start(env, seed)

    def feed(self, feed: Feed) -> list[str]:
        """Pass the feed on and record it with the operations it caused."""
        executed = self.inner.feed(feed)
        for item in feed:
            self._out.write(f"{item}\n")
        for op in executed:
            self._out.write(f"//executed {op}\n")
        return executed

    def close(self) -> None:
        """Close the wrapped reasoner and the trace file."""
        self.inner.close()
        if self._out is not None:
            self._out.close()
            self._out = None
