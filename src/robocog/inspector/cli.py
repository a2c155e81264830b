"""``robocog inspect FILE`` and the ``--inspect [PORT]`` option of the run commands.

``--inspect`` starts the page before the run and hooks every loop the run makes; the
address is printed (with a token when ``--host`` is not a loopback address). When the
run is over and the terminal is interactive, the page stays up with the last world and
mind until Ctrl-C, so they can still be questioned (``--inspect-exit`` ends at once).
``--inspect-record FILE`` writes the snapshots to a JSON-lines log that
``robocog inspect FILE`` shows again, with its timeline, without a robot.

Ctrl-C (SIGINT) and SIGTERM end both at any moment, while starting, running or
serving: the first one interrupts the main thread, the server and the log are then
closed (in a bounded time) and any further signal waits for that to finish, so that
neither a second Ctrl-C nor one arriving during the cleanup leaves a traceback, a
half-written log or a server thread behind.
"""

from __future__ import annotations

import argparse
import signal
import sys
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import FrameType
from typing import Any

from robocog.argtypes import EXISTING_FILE, NEW_FILE, PORT, positive_int

DEFAULT_PORT = 8765


class Stopped(KeyboardInterrupt):
    """SIGINT or SIGTERM, raised in the main thread so that every ``finally`` runs.

    A KeyboardInterrupt, so that code which ends on Ctrl-C ends the same way on SIGTERM.
    """

    def __init__(self, signum: int) -> None:
        super().__init__(signal.Signals(signum).name)
        self.signum = signum


class StopSignals:
    """While entered, SIGINT and SIGTERM (each unless something else handles it) raise
    :class:`Stopped` once; a later signal only marks the stop, so that the cleanup the
    first one started is not itself cut short. ``cleaning()`` holds signals off in the
    same way around a cleanup that no signal started (the run ended by itself).

    A raise can be lost: a signal that lands while the interpreter runs a ``__del__``,
    a weakref callback (the import system's module locks have some) or the garbage
    collector is only printed as "Exception ignored", and the work goes on as if nothing
    had happened. So the stop is also remembered, and :meth:`check` raises it again at
    the points where the work can stop: each cycle of a watched loop, a pause, the lingering page,
    the steps of starting.

    Such a lost raise is not printed (the interpreter would show it as an "Exception
    ignored" with a traceback, on a Ctrl-C that ends the command cleanly anyway): while
    entered, ``sys.unraisablehook`` drops a :class:`Stopped` and counts it in ``lost``,
    and hands anything else to the hook that was there.

    Python delivers signals to the main thread only: entered from another thread this
    does nothing, and the default handling stays.
    """

    def __init__(self) -> None:
        self.stopping = False
        self.signum: int | None = None
        #: how many raises were lost (and not printed); :meth:`check` raises them again
        self.lost = 0
        self._before: dict[int, Any] = {}
        self._hook: Callable[[Any], object] | None = None

    def _unraisable(self, unraisable: Any) -> None:
        if isinstance(unraisable.exc_value, Stopped):
            self.lost += 1
            return
        hook = self._hook or sys.__unraisablehook__
        hook(unraisable)

    def _handle(self, signum: int, _frame: FrameType | None) -> None:
        if self.stopping:
            return
        self.stopping = True
        self.signum = signum
        raise Stopped(signum)

    @property
    def asked(self) -> bool:
        """True once a signal asked to stop."""
        return self.signum is not None

    def check(self) -> None:
        """Raise :class:`Stopped` if a signal asked to stop (its own raise may have been
        lost)."""
        if self.signum is not None:
            raise Stopped(self.signum)

    def __enter__(self) -> StopSignals:
        if threading.current_thread() is not threading.main_thread():
            return self
        # only where Python's default is in place: a SIGINT ignored (a job started in the
        # background) stays ignored, a SIGTERM the command handles (a bridge) its own
        for signum, default in (
            (signal.SIGINT, signal.default_int_handler),
            (signal.SIGTERM, signal.SIG_DFL),
        ):
            if signal.getsignal(signum) == default:
                self._before[signum] = signal.signal(signum, self._handle)
        if self._before:
            self._hook = sys.unraisablehook
            sys.unraisablehook = self._unraisable
        return self

    def __exit__(self, *exc: object) -> None:
        for signum, handler in self._before.items():
            signal.signal(signum, handler)
        if self._before and self._hook is not None:
            sys.unraisablehook = self._hook
            self._hook = None
        self._before.clear()

    @contextmanager
    def cleaning(self) -> Iterator[None]:
        """Signals during the block are taken as the stop already under way."""
        self.stopping = True
        yield


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The ``--inspect`` options, for any command that runs a robot loop."""
    group = parser.add_argument_group("inspector")
    group.add_argument(
        "--inspect",
        nargs="?",
        type=PORT,
        const=DEFAULT_PORT,
        default=None,
        metavar="PORT",
        help=f"serve the inspector page while running (port {DEFAULT_PORT} if not given, "
        "0 for any free one)",
    )
    group.add_argument(
        "--host",
        default="127.0.0.1",
        help="address the inspector binds (default 127.0.0.1; any other requires the printed token)",
    )
    group.add_argument(
        "--inspect-record",
        type=NEW_FILE,
        metavar="FILE",
        help="also write the snapshots as JSON lines",
    )
    group.add_argument(
        "--inspect-record-limit",
        type=positive_int(1_000_000, "MB"),
        default=200,
        metavar="MB",
        help="stop recording at this size (default 200 MB)",
    )
    group.add_argument(
        "--inspect-exit",
        action="store_true",
        help="close the page when the run ends (default: keep it until Ctrl-C when interactive)",
    )


class Session:
    """A running inspector with its server (and log): what ``--inspect`` gives a run."""

    def __init__(
        self,
        inspector: Any,
        server: Any,
        writer: Any = None,
        signals: StopSignals | None = None,
    ) -> None:
        self.inspector = inspector
        self.server = server
        self.writer = writer
        self.signals = signals or StopSignals()

    def watch(self, world: Any, mind: Any, loop: Any, label: str = "") -> Callable[[Any], None]:
        """:meth:`Inspector.watch`, whose ``on_step`` also ends the run on a signal whose
        own raise was lost."""
        on_step = self.inspector.watch(world, mind, loop, label)
        check = self.signals.check

        def step(done: Any) -> None:
            check()
            on_step(done)

        return step

    def watcher(self) -> Callable[..., Any]:
        """The hook for the experiment's loops, labelling each run by mind and seed."""

        def label(world: Any, mind: Any) -> str:
            name = getattr(mind, "name", type(mind).__name__)
            seed = getattr(world, "seed", None)
            return f"{name}" + (f", seed {seed}" if seed is not None else "")

        def hook(world: Any, mind: Any, loop: Any) -> Callable[[Any], None]:
            return self.watch(world, mind, loop, label(world, mind))

        return hook


@contextmanager
def session(args: argparse.Namespace, source: str = "") -> Iterator[Session | None]:
    """The inspector for a run when ``--inspect`` was given, else None.

    A signal during the run (or while the page lingers after it) reaches the run as a
    KeyboardInterrupt after the server and the log are closed."""
    port = getattr(args, "inspect", None)
    if port is None:
        yield None
        return
    with StopSignals() as signals:
        try:
            from robocog.inspector.server import InspectorServer
        except ModuleNotFoundError as exc:  # pragma: no cover - depends on the install
            raise SystemExit(
                f"--inspect needs the inspect extra: pip install 'robocog[inspect]' ({exc})"
            ) from exc
        from robocog.inspector.hub import Inspector
        from robocog.inspector.snapshot import LogWriter

        inspector = Inspector()
        inspector.interrupted = lambda: signals.asked
        server = InspectorServer(inspector, host=args.host, port=port)
        writer = None
        try:
            try:
                url = server.start(check=signals.check)
            except OSError as exc:
                raise SystemExit(
                    f"the inspector cannot listen on {args.host}:{port}: {exc}"
                ) from exc
            print(f"inspector: {url}", flush=True)
            if server.token:
                print(
                    "inspector: bound beyond loopback; the token above is required on every request",
                    flush=True,
                )
            if args.inspect_record is not None:
                try:
                    writer = LogWriter(
                        inspector.history,
                        args.inspect_record,
                        source=source,
                        max_bytes=max(1, args.inspect_record_limit) << 20,
                    )
                except OSError as exc:
                    raise SystemExit(
                        f"the inspector cannot write {args.inspect_record}: {exc}"
                    ) from exc
            signals.check()
            yield Session(inspector, server, writer, signals)
            signals.check()
            if not args.inspect_exit and sys.stdin.isatty():
                print(
                    f"inspector: the run is over; the page stays at {url} until Ctrl-C",
                    flush=True,
                )
                try:
                    inspector.linger()
                except KeyboardInterrupt:
                    pass
        finally:
            with signals.cleaning():
                inspector.close()
                if writer is not None:
                    writer.close()
                    print(
                        f"inspector: {writer.written} snapshots in {args.inspect_record}",
                        flush=True,
                    )
                server.stop()


# ---- robocog inspect FILE --------------------------------------------------------------


def configure(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``robocog inspect``."""
    parser.add_argument("file", type=EXISTING_FILE, help="a log written with --inspect-record")
    parser.add_argument(
        "--port", type=PORT, default=DEFAULT_PORT, help=f"default {DEFAULT_PORT}; 0 for any"
    )
    parser.add_argument(
        "--host", default="127.0.0.1", help="default 127.0.0.1 (others need the token)"
    )
    parser.add_argument(
        "--check", action="store_true", help="only read and check the log, print what it holds"
    )


def run(args: argparse.Namespace) -> int:
    """Serve a recorded run's page until Ctrl-C or SIGTERM (or only check the file).

    Stopped while serving, as it is meant to end, it answers 0; stopped while it still
    reads the log or starts the server, 128 + the signal's number."""
    with StopSignals() as signals:
        server = None
        serving = False
        try:
            from robocog.inspector.snapshot import LogError, read_log

            try:
                head, history = read_log(args.file)
            except (OSError, LogError) as exc:
                print(f"robocog inspect: {exc}", file=sys.stderr)
                return 2
            first, last = history.bounds()
            ended = f", ended early: {head['end']}" if "end" in head else ""
            print(
                f"{args.file}: {len(history)} snapshots (seq {first}..{last}), recorded {head.get('created', '?')}"
                f" from {head.get('source') or 'a run'}{ended}",
                flush=True,
            )
            if args.check:
                return 0
            try:
                from robocog.inspector.server import InspectorServer
            except ModuleNotFoundError as exc:  # pragma: no cover - depends on the install
                print(f"robocog inspect: needs the inspect extra ({exc})", file=sys.stderr)
                return 2
            from robocog.inspector.hub import Inspector

            inspector = Inspector()
            inspector.interrupted = lambda: signals.asked
            inspector.history = history
            inspector.live = False
            inspector.run_label = f"recorded: {args.file.name}"
            server = InspectorServer(inspector, host=args.host, port=args.port)
            signals.check()
            try:
                url = server.start(check=signals.check)
            except OSError as exc:
                print(
                    f"robocog inspect: cannot listen on {args.host}:{args.port}: {exc}",
                    file=sys.stderr,
                )
                return 2
            signals.check()
            serving = True
            print(f"inspector: {url} (Ctrl-C to stop)", flush=True)
            inspector.linger()
            return 0
        except KeyboardInterrupt:
            if serving:
                return 0  # how a served page is meant to end
            raise  # robocog's command answers 128 + the signal's number (robocog.cli)
        finally:
            if server is not None:
                with signals.cleaning():
                    server.stop()
