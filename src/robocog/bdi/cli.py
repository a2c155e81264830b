"""``robocog agent FILE.asl|PROJECT.mas2j [MORE.asl ...]``: run AgentSpeak until idle.

One ``.asl`` file runs one agent, named after the file (``hello.asl`` runs as
``hello``); several run as one system of agents; a Jason project (``.mas2j``) runs the
agents it declares. ``.print`` output goes to stdout as ``[name] text``, exactly as Jason
prints it; warnings and errors go to stderr, so that stdout holds only what the
programs printed. ``--max-cycles`` and ``--timeout`` bound a program that never ends.
"""

from __future__ import annotations

import argparse
import importlib
import signal
import sys
from pathlib import Path

from robocog.argtypes import EXISTING_FILE_STR, positive_int, seconds


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the arguments of ``robocog agent``."""
    parser.add_argument(
        "file",
        nargs="+",
        type=EXISTING_FILE_STR,
        help="AgentSpeak program(s) (.asl), or one Jason project (.mas2j)",
    )
    parser.add_argument("--name", help="agent name of a single .asl (default: the file name)")
    parser.add_argument(
        "--max-cycles",
        type=positive_int(),
        default=None,
        help="stop after this many reasoning cycles (default: run until idle)",
    )
    parser.add_argument(
        "--timeout", type=seconds(), default=None, help="stop after this many seconds of wall time"
    )
    parser.add_argument(
        "--env",
        metavar="MODULE.CLASS",
        help="a Python environment class for the agents' actions (see docs/bdi.md)",
    )
    parser.add_argument(
        "--beliefs", action="store_true", help="print the final belief base on stderr"
    )
    parser.add_argument(
        "--clock",
        choices=("real", "virtual"),
        default="real",
        help="time of .wait, .at and deadlines: the wall clock, as in Jason (default), or a "
        "virtual clock that jumps to the next timer (the same run on any machine)",
    )


class _OutOfTime(BaseException):
    """Raised by the --timeout alarm; a BaseException, so no handler of the agent's own
    (which turns errors of a plan into failure events) can swallow it."""


def _out_of_time(*_: object) -> None:
    raise _OutOfTime


def _environment(spec: str):  # noqa: ANN202 - the user's environment object
    module, _, name = spec.rpartition(".")
    if not module:
        raise ValueError(f"--env {spec}: write MODULE.CLASS")
    return getattr(importlib.import_module(module), name)()


def run(args: argparse.Namespace) -> int:
    """Parse, run until idle, and report errors with file, line and column."""
    from robocog.bdi.agent import Agent
    from robocog.bdi.parser import ParseError, read_source
    from robocog.bdi.project import build, read_project, run_files

    paths = [Path(f) for f in args.file]
    for path in paths:
        if not path.is_file():
            print(f"robocog agent: cannot read {path}: no such file", file=sys.stderr)
            return 2
    out = sys.stdout

    def printer(name: str, line: str) -> None:
        out.write(f"[{name}] {line}\n")

    environment = None
    try:
        if args.env:
            environment = _environment(args.env)
    except (ImportError, AttributeError, ValueError, TypeError) as exc:
        print(f"robocog agent: --env {args.env}: {exc}", file=sys.stderr)
        return 2
    if args.timeout is not None:
        signal.signal(signal.SIGALRM, _out_of_time)
        signal.setitimer(signal.ITIMER_REAL, max(0.001, args.timeout))
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 20000))
    try:
        if len(paths) == 1 and paths[0].suffix != ".mas2j":
            agent = Agent(
                read_source(paths[0]), args.name or paths[0].stem, file=str(paths[0]),
                printer=printer,
            )  # fmt: skip
            if environment is not None:
                agent.environment = environment
            cycles = agent.run(args.max_cycles, real_time=args.clock == "real")
            agents = [agent]
            cut = args.max_cycles is not None and cycles >= args.max_cycles and not agent.is_idle()
        else:
            project = paths[0].suffix == ".mas2j"
            if project and len(paths) > 1:
                print("robocog agent: a .mas2j project runs alone", file=sys.stderr)
                return 2
            real_time = args.clock == "real"
            if project:
                notes: list[str] = []
                mas = build(read_project(paths[0]), printer, environment, notes)
                for note in notes:
                    print(f"robocog agent: {note}", file=sys.stderr)
                mas.run(args.max_cycles, real_time=real_time)
            else:
                mas = run_files(paths, printer, args.max_cycles, environment, real_time=real_time)
            agents = list(mas.agents.values())
            cut = args.max_cycles is not None and not mas.stopped and not mas.is_idle()
    except ParseError as exc:
        print(f"robocog agent: {exc}", file=sys.stderr)
        return 1
    except _OutOfTime:
        out.flush()
        print(f"robocog agent: stopped after {args.timeout} s (--timeout)", file=sys.stderr)
        return 3
    finally:
        if args.timeout is not None:
            signal.setitimer(signal.ITIMER_REAL, 0)
    out.flush()
    if args.beliefs:
        for agent in agents:
            for b in agent.beliefs():
                print(f"{agent.name}: {b!r}", file=sys.stderr)
    if cut:
        # as --timeout: the program did not end by itself, and the exit status says so
        print(
            f"robocog agent: stopped after {args.max_cycles} cycles (--max-cycles), not idle",
            file=sys.stderr,
        )
        return 3
    return 0
