"""``robocog agent FILE.asl``: run one AgentSpeak agent until it is idle.

The agent is named after the file (``hello.asl`` runs as ``hello``). ``.print`` output
goes to stdout as ``[name] text``, exactly as Jason prints it; warnings and parse
errors go to stderr, so that stdout holds only what the program printed.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the arguments of ``robocog agent``."""
    parser.add_argument("file", help="AgentSpeak program (.asl)")
    parser.add_argument("--name", help="agent name (default: the file name without .asl)")
    parser.add_argument(
        "--max-cycles",
        type=int,
        default=None,
        help="stop after this many reasoning cycles (default: run until idle)",
    )
    parser.add_argument(
        "--beliefs", action="store_true", help="print the final belief base on stderr"
    )


def run(args: argparse.Namespace) -> int:
    """Parse, run until idle, and report parse errors with line and column."""
    from robocog.bdi.agent import Agent
    from robocog.bdi.parser import ParseError, read_source

    path = Path(args.file)
    if not path.is_file():
        print(f"robocog agent: cannot read {path}: no such file", file=sys.stderr)
        return 2
    try:
        text = read_source(path)
    except ParseError as exc:
        print(f"robocog agent: {exc}", file=sys.stderr)
        return 1
    out = sys.stdout

    def printer(name: str, line: str) -> None:
        out.write(f"[{name}] {line}\n")

    try:
        agent = Agent(text, args.name or path.stem, file=str(path), printer=printer)
    except ParseError as exc:
        print(f"robocog agent: {exc}", file=sys.stderr)
        return 1
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 20000))
    agent.run(args.max_cycles)
    out.flush()
    if args.beliefs:
        for b in agent.beliefs():
            print(repr(b), file=sys.stderr)
    return 0
