"""``robocog nar``: ONA's shell protocol on stdin/stdout.

Each input line is Narsese, a bare number of cycles, a ``*command`` or a ``//comment``;
output lines are ONA's (``Input:``, ``Derived:``, ``Answer:``, ...), so ONA's example
files and scoring tools work unchanged. A bad line prints one error naming its line and
column and the reasoner goes on with its memory intact.
"""

from __future__ import annotations

import argparse
import gc
import os
import sys

from .nar import NAR
from .narsese import NarseseError


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the shell's arguments."""
    parser.add_argument("--load", metavar="FILE", help="start from a memory saved earlier")
    parser.add_argument("--save", metavar="FILE", help="save the memory here at the end")
    parser.add_argument("--seed", type=int, default=666, help="random seed (ONA's is 666)")
    parser.add_argument(
        "--set",
        metavar="NAME=VALUE",
        action="append",
        default=[],
        help="set a parameter, e.g. --set concepts_max=20000 (repeatable)",
    )
    parser.add_argument("--quiet", action="store_true", help="no Statistics block at the end")
    # only the command line ends the process itself (see the end of ``run``)
    parser.set_defaults(exit_when_done=True)


_BOOLEANS = {"true": True, "false": False, "yes": True, "no": False, "on": True, "off": False}


def _value(text: str) -> object:
    """A ``--set`` value: a boolean word in any case, an integer or a float."""
    if text.lower() in _BOOLEANS:
        return _BOOLEANS[text.lower()]
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"--set: {text!r} is not a number or true/false") from None


def run(args: argparse.Namespace) -> int:
    """Read stdin until EOF or ``quit``, printing ONA's output lines."""
    overrides = {}
    try:
        for item in args.set:
            k, _, v = item.partition("=")
            overrides[k.strip()] = _value(v.strip())
    except ValueError as exc:
        print(f"robocog nar: {exc}", file=sys.stderr)
        return 2
    try:
        if args.load:
            nar = NAR.load(args.load)
            nar.config.update(**overrides)
            nar.memory.capacity = nar.config.concepts_max
        else:
            nar = NAR(seed=args.seed, **overrides)
    except (OSError, ValueError, KeyError) as exc:
        print(f"robocog nar: {exc}", file=sys.stderr)
        return 2
    # The reasoner's garbage is acyclic: reference counting frees it (a 1,000-link
    # taxonomy leaves ~900 objects in cycles, 20,000 random lines none). Yet each
    # collection of the youngest generation walks into the long-lived concepts and cost
    # ~15-20 ms, a fifth of the run in all; so the cycle collector runs only after a
    # million objects have been added net, which bounds whatever cycles there are.
    gc.set_threshold(1_000_000, 20, 100)
    out = sys.stdout
    nar.output = lambda line: out.write(line + "\n")
    nar.config.print_derivations = True
    for lineno, raw in enumerate(sys.stdin, start=1):
        line = raw.rstrip()
        if line == "quit":
            break
        try:
            nar.add_input(line)
        except BrokenPipeError:
            # the reader of our output has gone (``| head``): stop quietly, still saving
            os.dup2(os.open(os.devnull, os.O_WRONLY), out.fileno())
            break
        except NarseseError as exc:
            out.write(f"Error: line {lineno}, column {exc.column}: {exc.message}\n")
        except RecursionError:
            out.write(f"Error: line {lineno}, column 1: term nested too deeply\n")
        except Exception as exc:  # noqa: BLE001 - the shell must outlive any one line
            out.write(f"Error: line {lineno}, column 1: internal error: {exc!r}\n")
    if args.save:
        nar.save(args.save)
    if not args.quiet:
        for line in nar.statistics():
            out.write(line + "\n")
    out.flush()
    if getattr(args, "exit_when_done", False):
        # a full memory is millions of objects; freeing them one by one at exit takes
        # a fifth of a short run, and the operating system reclaims them at once
        sys.stderr.flush()
        os._exit(0)
    return 0
