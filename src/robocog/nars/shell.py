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
import signal
import sys
import tempfile
from pathlib import Path
from types import FrameType
from typing import TextIO

from robocog.argtypes import EXISTING_DIR_STR, EXISTING_FILE_STR, NEW_FILE_STR, int_range

from . import memfile
from .config import (
    BYTES_PER_CONCEPT,
    DEFAULT_MEMORY_BYTES,
    ENGINE_BYTES,
    ONA_CONCEPTS_MAX,
    ONA_VERSIONS,
    RANGES,
    concepts_for_memory,
    parse_size,
)
from .memfile_io import sweep_stale
from .nar import NAR
from .narsese import NarseseError


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the shell's arguments."""
    parser.add_argument(
        "--load", type=EXISTING_FILE_STR, metavar="FILE", help="start from a memory saved earlier"
    )
    parser.add_argument(
        "--save",
        type=NEW_FILE_STR,
        metavar="FILE",
        help="save the memory here at the end, or when interrupted (SIGINT, SIGTERM)",
    )
    parser.add_argument(
        "--memory-dir",
        type=EXISTING_DIR_STR,
        metavar="DIR",
        help="the folder where '*save NAME' and '*load NAME' lines may write and read "
        "(without it those lines are refused)",
    )
    parser.add_argument(
        "--memory",
        type=memory_argument,
        metavar="SIZE",
        help="memory budget from which the concept capacity follows, e.g. 500MB or 2GB "
        f"(default {DEFAULT_MEMORY_BYTES >> 20}MB), or 'ona' for ONA's {ONA_CONCEPTS_MAX} "
        "concepts; --set concepts_max=N overrides it",
    )
    parser.add_argument(
        "--ona",
        choices=list(ONA_VERSIONS),
        default=None,
        help=f"follow this ONA version's behaviour (default {SHELL_ONA}; a memory given "
        "to --load keeps its own unless --ona is given)",
    )
    parser.add_argument(
        "--seed",
        type=int_range(-(2**63), 2**63 - 1),
        default=666,
        help="random seed (ONA's is 666)",
    )
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


#: the ONA version the shell follows unless ``--ona`` says otherwise (docs/nars.md: why)
SHELL_ONA = "0.9.3"

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


def capacity(memory: str | None) -> int:
    """The concept capacity of ``--memory`` (None: the default budget; ``ona``: ONA's)."""
    if memory is None:
        return concepts_for_memory(DEFAULT_MEMORY_BYTES)
    if memory.strip().lower() == "ona":
        return ONA_CONCEPTS_MAX
    return concepts_for_memory(parse_size(memory))


def memory_argument(text: str) -> str:
    """``--memory``, checked while the command line is read: ``ona`` or a size the engine
    can run in (a size above what it can use is taken, and said so when the shell starts)."""
    try:
        capacity(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None
    return text


#: values ``--memory`` refuses, for the test that walks every option of every command
memory_argument.bad_values = ("-1", "0", "nan", "inf", "1KB", "abc", "1" + "0" * 20)  # type: ignore[attr-defined]


def _capped_note(memory: str | None) -> str | None:
    """The note that ``--memory`` asked for more than the engine holds, or None."""
    if memory is None or memory.strip().lower() == "ona":
        return None
    most = int(RANGES["concepts_max"][1])
    if parse_size(memory) <= ENGINE_BYTES + most * BYTES_PER_CONCEPT:
        return None
    gb = (ENGINE_BYTES + most * BYTES_PER_CONCEPT) / (1 << 30)
    return (
        f"robocog nar: --memory {memory}: the engine holds at most {most:,} concepts "
        f"(about {gb:.0f} GB); it takes that many"
    )


def check_save_path(path: str) -> str | None:
    """Why the memory cannot be saved at ``path`` (None if it can): checked before any
    input is read, so that a long session does not end in an unsaved memory."""
    target = Path(path)
    if target.is_dir():
        return f"--save {path}: is a directory"
    folder = target.parent
    if not folder.is_dir():
        return f"--save {path}: the folder {folder} does not exist"
    if target.exists() and not memfile.is_memory_file(target):
        return f"--save {path}: exists and is not a robocog memory; not overwritten"
    sweep_stale(target)
    try:  # a real write, since permission bits do not tell (root, read-only mounts)
        fd, probe = tempfile.mkstemp(dir=folder, prefix=f".{target.name}.", suffix=".tmp")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        return f"--save {path}: the folder {folder} is not writable ({exc.strerror or exc})"
    return None


class _Stop(BaseException):
    """Raised by the signal handler to leave a blocking read of the input."""


class _Signals:
    """SIGINT and SIGTERM end the session: a read of the input is left at once, a line
    in progress ends (a cycles line at its next slice of cycles, ``CYCLE_SLICE``), then
    the memory is saved when ``--save`` was given. Further signals change nothing: the
    session is already ending, and the save is not cut short (it replaces the file
    atomically, but a session must not end unsaved because a key was pressed twice).

    The handler raises only while the shell waits for input (``reading``), so a signal
    arriving anywhere else (at the end of the input, during a line or the save) is
    noted and acted on where the shell checks it, never a traceback."""

    def __init__(self) -> None:
        self.received: int | None = None
        self.reading = False
        self.old: dict[int, object] = {}

    def install(self) -> None:
        for sig in (signal.SIGINT, signal.SIGTERM):
            self.old[sig] = signal.signal(sig, self.handle)

    def ignore(self) -> None:
        """From now on signals are ignored (the final save must not be cut short)."""
        for sig in self.old:
            signal.signal(sig, signal.SIG_IGN)

    def restore(self) -> None:
        for sig, old in self.old.items():
            signal.signal(sig, old)  # type: ignore[arg-type]

    def handle(self, signum: int, frame: FrameType | None) -> None:
        if self.received is None:
            self.received = signum
        if self.reading:
            self.reading = False
            raise _Stop

    def stop_requested(self) -> bool:
        """Asked by the reasoner between slices of a cycles line."""
        return self.received is not None


def _decoded(raw: bytes, lineno: int) -> tuple[str | None, str | None]:
    """(the line, None) or (None, the error line for its first invalid UTF-8 byte)."""
    try:
        return raw.decode("utf-8"), None
    except UnicodeDecodeError as exc:
        column = len(raw[: exc.start].decode("utf-8", "replace")) + 1
        bad = raw[exc.start : exc.start + 1].hex()
        return None, f"Error: line {lineno}, column {column}: invalid UTF-8 byte 0x{bad}"


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
    if not -(1 << 63) <= args.seed < 1 << 63:
        print(f"robocog nar: --seed {args.seed}: out of range [-2**63, 2**63)", file=sys.stderr)
        return 2
    memory = getattr(args, "memory", None)
    if "concepts_max" not in overrides and (memory is not None or not args.load):
        try:
            overrides["concepts_max"] = capacity(memory)
        except ValueError as exc:
            print(f"robocog nar: --memory: {exc}", file=sys.stderr)
            return 2
        note = _capped_note(memory)
        if note is not None:
            print(note, file=sys.stderr)
    memory_dir = getattr(args, "memory_dir", None)
    if memory_dir is not None and not Path(memory_dir).is_dir():
        print(f"robocog nar: --memory-dir {memory_dir}: not a directory", file=sys.stderr)
        return 2
    if args.save:
        problem = check_save_path(args.save)
        if problem is not None:
            print(f"robocog nar: {problem}", file=sys.stderr)
            return 2
    try:
        ona = getattr(args, "ona", None)
        if args.load:
            nar = NAR.load(args.load)
            if ona is not None:
                nar.config.update(**ONA_VERSIONS[ona])
            nar.config.update(**overrides)
            nar.memory.capacity = nar.config.concepts_max
        else:
            nar = NAR(seed=args.seed, ona=ona or SHELL_ONA, **overrides)
    except (OSError, ValueError, KeyError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else exc
        print(f"robocog nar: {message}", file=sys.stderr)
        return 2
    if memory_dir is not None:
        nar.memory_dir = Path(memory_dir)
    # The reasoner's garbage is acyclic: reference counting frees it (a 1,000-link
    # taxonomy leaves ~900 objects in cycles, 20,000 random lines none). Yet each
    # collection of the youngest generation walks into the long-lived concepts and cost
    # ~15-20 ms, a fifth of the run in all; so the cycle collector runs only after a
    # million objects have been added net, which bounds whatever cycles there are.
    # (for the session only: a caller running the shell in its own process gets its
    # collector's thresholds back)
    if sys.stdin.isatty():  # a person at the keyboard (never in a pipe, where ONA says nothing)
        from robocog.nars import ENGINE

        print(
            f"robocog nar: a NARS shell speaking ONA's protocol ({ENGINE} engine); type Narsese, "
            "a number to run that many cycles, Ctrl-D to end",
            file=sys.stderr,
        )
    before = gc.get_threshold()
    gc.set_threshold(1_000_000, 20, 100)
    try:
        return _session(nar, args)
    finally:
        gc.set_threshold(*before)


def _session(nar: NAR, args: argparse.Namespace) -> int:
    """The session proper: lines in, output out, the memory saved at the end."""
    out = sys.stdout
    if hasattr(out, "reconfigure"):
        # whatever the locale, output is UTF-8 (as input is), never an encoding error
        out.reconfigure(encoding="utf-8", errors="backslashreplace")
    nar.output = lambda line: out.write(line + "\n")
    nar.config.print_derivations = True
    signals = _Signals()
    nar.stop_requested = signals.stop_requested
    signals.install()
    lines = iter(sys.stdin.buffer)
    lineno = 0

    def read_input() -> str | None:
        # an operation's result (``*setopstdin``): the next lines belong to it
        nonlocal lineno
        raw = next(lines, None)
        if raw is None:
            return None
        lineno += 1
        return _decoded(raw, lineno)[0]

    nar.read_input = read_input
    try:
        while signals.received is None:
            signals.reading = True
            try:
                raw = next(lines, None)
            finally:
                signals.reading = False
            if raw is None:
                break
            lineno += 1
            if _line(nar, raw, lineno, out):
                break
        signals.reading = False
    except _Stop:
        pass
    signals.ignore()
    nar.stop_requested = None
    nar.read_input = None
    code = 0 if signals.received is None else 128 + signals.received
    if args.save:
        try:
            nar.save(args.save)
        except (OSError, ValueError) as exc:
            print(f"robocog nar: {exc}", file=sys.stderr)
            code = code or 1
    if not args.quiet:
        for line in nar.statistics():
            out.write(line + "\n")
    try:
        out.flush()
    except BrokenPipeError:
        pass
    if getattr(args, "exit_when_done", False):
        # a full memory is millions of objects; freeing them one by one at exit takes
        # a fifth of a short run, and the operating system reclaims them at once
        sys.stderr.flush()
        os._exit(code)
    signals.restore()
    return code


def _line(nar: NAR, raw: bytes, lineno: int, out: TextIO) -> bool:
    """Process one input line; True when the session ends (``quit``, a closed output)."""
    text, error = _decoded(raw, lineno)
    write = out.write
    if text is None:
        write(error + "\n")
        return False
    line = text.rstrip()
    if line == "quit":
        return True
    try:
        nar.add_input(line)
    except BrokenPipeError:
        # the reader of our output has gone (``| head``): stop quietly, still saving
        os.dup2(os.open(os.devnull, os.O_WRONLY), out.fileno())
        return True
    except NarseseError as exc:
        write(f"Error: line {lineno}, column {exc.column}: {exc.message}\n")
    except RecursionError:
        write(f"Error: line {lineno}, column 1: term nested too deeply\n")
    except Exception as exc:  # noqa: BLE001 - the shell must outlive any one line
        write(f"Error: line {lineno}, column 1: internal error: {exc!r}\n")
    return False
