"""``robocog inspect FILE`` and the ``--inspect [PORT]`` option of the run commands.

``--inspect`` starts the page before the run and hooks every loop the run makes; the
address is printed (with a token when ``--host`` is not a loopback address). When the
run is over and the terminal is interactive, the page stays up with the last world and
mind until Ctrl-C, so they can still be questioned (``--inspect-exit`` ends at once).
``--inspect-record FILE`` writes the snapshots to a JSON-lines log that
``robocog inspect FILE`` shows again, with its timeline, without a robot.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

DEFAULT_PORT = 8765


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The ``--inspect`` options, for any command that runs a robot loop."""
    group = parser.add_argument_group("inspector")
    group.add_argument(
        "--inspect",
        nargs="?",
        type=int,
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
        "--inspect-record", type=Path, metavar="FILE", help="also write the snapshots as JSON lines"
    )
    group.add_argument(
        "--inspect-record-limit",
        type=int,
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

    def __init__(self, inspector: Any, server: Any, writer: Any = None) -> None:
        self.inspector = inspector
        self.server = server
        self.writer = writer

    def watcher(self) -> Callable[..., Any]:
        """The hook for the experiment's loops, labelling each run by mind and seed."""

        def label(world: Any, mind: Any) -> str:
            name = getattr(mind, "name", type(mind).__name__)
            seed = getattr(world, "seed", None)
            return f"{name}" + (f", seed {seed}" if seed is not None else "")

        return self.inspector.watcher(label)


@contextmanager
def session(args: argparse.Namespace, source: str = "") -> Iterator[Session | None]:
    """The inspector for a run when ``--inspect`` was given, else None."""
    port = getattr(args, "inspect", None)
    if port is None:
        yield None
        return
    try:
        from robocog.inspector.server import InspectorServer
    except ModuleNotFoundError as exc:  # pragma: no cover - depends on the install
        raise SystemExit(
            f"--inspect needs the inspect extra: pip install 'robocog[inspect]' ({exc})"
        ) from exc
    from robocog.inspector.hub import Inspector
    from robocog.inspector.snapshot import LogWriter

    inspector = Inspector()
    server = InspectorServer(inspector, host=args.host, port=port)
    try:
        url = server.start()
    except OSError as exc:
        raise SystemExit(f"the inspector cannot listen on {args.host}:{port}: {exc}") from exc
    print(f"inspector: {url}", flush=True)
    if server.token:
        print(
            "inspector: bound beyond loopback; the token above is required on every request",
            flush=True,
        )
    writer = None
    if args.inspect_record is not None:
        try:
            writer = LogWriter(
                inspector.history,
                args.inspect_record,
                source=source,
                max_bytes=max(1, args.inspect_record_limit) << 20,
            )
        except OSError as exc:
            server.stop()
            raise SystemExit(f"the inspector cannot write {args.inspect_record}: {exc}") from exc
    live = Session(inspector, server, writer)
    try:
        yield live
        if not args.inspect_exit and sys.stdin.isatty():
            print(f"inspector: the run is over; the page stays at {url} until Ctrl-C", flush=True)
            try:
                inspector.linger()
            except KeyboardInterrupt:
                pass
    finally:
        inspector.close()
        if writer is not None:
            writer.close()
            print(f"inspector: {writer.written} snapshots in {args.inspect_record}", flush=True)
        server.stop()


# ---- robocog inspect FILE --------------------------------------------------------------


def configure(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``robocog inspect``."""
    parser.add_argument("file", type=Path, help="a log written with --inspect-record")
    parser.add_argument(
        "--port", type=int, default=DEFAULT_PORT, help=f"default {DEFAULT_PORT}; 0 for any"
    )
    parser.add_argument(
        "--host", default="127.0.0.1", help="default 127.0.0.1 (others need the token)"
    )
    parser.add_argument(
        "--check", action="store_true", help="only read and check the log, print what it holds"
    )


def run(args: argparse.Namespace) -> int:
    """Serve a recorded run's page until Ctrl-C (or only check the file)."""
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
        f" from {head.get('source') or 'a run'}{ended}"
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
    inspector.history = history
    inspector.live = False
    inspector.run_label = f"recorded: {args.file.name}"
    server = InspectorServer(inspector, host=args.host, port=args.port)
    try:
        url = server.start()
    except OSError as exc:
        print(f"robocog inspect: cannot listen on {args.host}:{args.port}: {exc}", file=sys.stderr)
        return 2
    print(f"inspector: {url} (Ctrl-C to stop)", flush=True)
    try:
        inspector.linger()
    except KeyboardInterrupt:
        pass
    finally:
        server.stop()
    return 0
