"""The ``robocog`` command.

Each subcommand lives in the package that owns it and is imported only when it is run,
so that ``robocog nar`` starts without loading the planner or the plotting stack. A
subcommand module provides ``configure(parser)`` to declare its arguments and
``run(args) -> int`` to do the work.
"""

from __future__ import annotations

# Only what the interpreter has loaded already: a Ctrl-C while this module is imported
# would otherwise end in a traceback (``main`` takes over at once, see there)
import signal
import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import argparse
    from collections.abc import Sequence

#: name -> (module, one-line help)
COMMANDS: dict[str, tuple[str, str]] = {
    "demo": ("robocog.experiments.demo", "run the garbage-collection demo with both minds"),
    "experiment": ("robocog.experiments.cli", "run one of the papers' case studies"),
    "sweep": ("robocog.experiments.sweep_cli", "run an experiment over a grid of settings"),
    "train": (
        "robocog.experiments.train_cli",
        "train a learned part (the physical field's detector)",
    ),
    "nar": ("robocog.nars.shell", "NARS shell speaking ONA's protocol on stdin/stdout"),
    "agent": ("robocog.bdi.cli", "run an AgentSpeak (Jason) program until it is idle"),
    "atomese": ("robocog.atomspace.cli", "load Atomese files and evaluate queries"),
    "plan": ("robocog.experiments.plan_cli", "plan pick/place/stack/unstack tasks"),
    "bridge": ("robocog.bridges.cli", "drive a real robot over ROS 2 or ROS 1"),
    "sim": ("robocog.sim.cli", "serve an embedded world as a ROS 2 robot"),
    "replay": ("robocog.bridges.replay", "feed a recorded run's percepts to a mind"),
    "build": (
        "robocog.nars.build",
        "compile the NARS engine with Cython (a few minutes; NARS then runs about 4x faster)",
    ),
    "inspect": (
        "robocog.inspector.cli",
        "show a run recorded with --inspect-record in the inspector",
    ),
}


def _load(name: str):  # noqa: ANN202 - a module object
    import importlib

    module_name = COMMANDS[name][0]
    try:
        return importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        if exc.name and module_name.startswith(exc.name):
            raise SystemExit(
                f"robocog {name}: this command is not available in this build"
            ) from exc
        raise


def _parser_class() -> type[argparse.ArgumentParser]:
    """argparse's parser whose errors are one line: what was wrong and where the help is.

    (argparse prints the whole usage first, which for most commands is longer than the
    error and pushes it out of sight.) Every subcommand's parser, nested ones too, is of
    this class, as argparse makes subparsers of their parent's class. Made when the
    command line is read, since argparse is imported only then (see the imports)."""
    import argparse
    from typing import NoReturn

    class Parser(argparse.ArgumentParser):
        def error(self, message: str) -> NoReturn:  # noqa: D102 - argparse's hook
            self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")

    return Parser


def build_parser(argv: Sequence[str]) -> argparse.ArgumentParser:
    """Build the top-level parser; only the chosen subcommand's module is imported."""

    from robocog import __version__

    parser = _parser_class()(
        prog="robocog",
        description="A reasoning mind for robots: NARS, AgentSpeak and an AtomSpace planner.",
    )
    parser.add_argument("--version", action="version", version=f"robocog {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    chosen = next((a for a in argv if not a.startswith("-")), None)
    for name, (_module, help_text) in COMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        if name == chosen:
            _load(name).configure(p)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``robocog`` console script."""
    argv = list(sys.argv[1:] if argv is None else argv)
    # while the command's modules are imported (a second or more), Ctrl-C ends the
    # process quietly: an interrupt inside an import would otherwise print a traceback
    # from whichever module it hit
    before = signal.getsignal(signal.SIGINT)
    if before is signal.default_int_handler:
        signal.signal(signal.SIGINT, _quit_quietly)
    try:
        parser = build_parser(argv)
        args = parser.parse_args(argv)
        if args.command is None:
            parser.print_help()
            return 2
        module = _load(args.command)
        if before is signal.default_int_handler:
            signal.signal(signal.SIGINT, before)
        return int(module.run(args) or 0)
    except Exception as exc:
        # the last guard of "no traceback reaches a user": an error no command turned into
        # its own message is still one line, with the way to see where it came from
        import os

        if os.environ.get("ROBOCOG_TRACEBACK"):
            raise
        name = " ".join(["robocog", *argv[:1]]) if argv and argv[0] in COMMANDS else "robocog"
        text = " ".join(str(exc).split())
        text = text if len(text) <= 300 else text[:297] + "..."
        print(
            f"{name}: error: {type(exc).__name__}: {text} "
            "(ROBOCOG_TRACEBACK=1 shows where it happened)",
            file=sys.stderr,
        )
        return 1
    except KeyboardInterrupt as stop:
        # Ctrl-C (or a SIGTERM a command turned into the same) ends a command without a
        # traceback, with the shell's code for it: 128 + the signal's number
        return 128 + int(getattr(stop, "signum", signal.SIGINT))


def _quit_quietly(signum: int, frame: object) -> None:
    """SIGINT before a command runs: leave at once with 130, without a word."""
    sys.stderr.flush()
    import os

    os._exit(128 + signum)


if __name__ == "__main__":
    sys.exit(main())
