"""ONA's shell commands (``*volume=0``, ``*setopname 1 ^left``, ...) as one table.

Each command is a name, a parser that turns its argument text into a checked value (or
refuses it with a message and the column at fault) and a handler that applies the
value. A line is parsed whole before its handler runs, so a refused line changes
nothing in the reasoner. The table lives apart from ``nar.py`` so that each command's
checks are in one place, and apart from ``shell.py`` (the ``robocog nar`` program,
which builds reasoners) so that the reasoner can run commands without importing it.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from .config import MAX_TIME, checked_value
from .memfile import MemoryFileError, is_operation_name, path_in
from .narsese import NarseseError, parse_term

if TYPE_CHECKING:
    from .nar import NAR


class CommandError(ValueError):
    """A refused command line; ``column`` is 1-based, counted on the whole line."""

    def __init__(self, column: int, message: str) -> None:
        super().__init__(message)
        self.column = column
        self.message = message


@dataclass(frozen=True, slots=True)
class Command:
    """One shell command: how its argument is checked and what it does."""

    name: str
    #: (argument text, reasoner) -> the checked value; raises ValueError with the reason
    parse: Callable[[str, NAR], object]
    #: (reasoner, checked value) -> None
    run: Callable[[NAR, object], None]
    help: str


_INT = re.compile(r"[+-]?[0-9]{1,30}")
_FLOAT = re.compile(r"[+-]?([0-9]{1,30}(\.[0-9]{0,30})?|\.[0-9]{1,30})([eE][+-]?[0-9]{1,4})?")


def parse_int(text: str, lo: int, hi: int, what: str) -> int:
    """A whole number in ``[lo, hi]``, written in ASCII digits."""
    if not _INT.fullmatch(text):
        raise ValueError(f"{what} is a whole number, not {text[:40]!r}")
    v = int(text)
    if not lo <= v <= hi:
        raise ValueError(f"{what}={text[:40]} is out of range [{lo}, {hi}]")
    return v


def parse_float(text: str, lo: float, hi: float, what: str) -> float:
    """A finite number in ``[lo, hi]`` (no ``nan``, no ``inf``)."""
    if not _FLOAT.fullmatch(text):
        raise ValueError(f"{what} is a number, not {text[:40]!r}")
    v = float(text)
    if not math.isfinite(v) or not lo <= v <= hi:
        raise ValueError(f"{what}={text[:40]} is out of range [{lo:g}, {hi:g}]")
    return v


def _none(arg: str, nar: NAR) -> None:
    if arg:
        raise ValueError(f"takes no argument, got {arg[:40]!r}")


def _anything(arg: str, nar: NAR) -> None:
    return None


def _parameter(name: str, what: str) -> Callable[[str, NAR], object]:
    """A parser for the value of config parameter ``name`` (its range is the config's)."""

    def parse(arg: str, nar: NAR) -> object:
        v = parse_float(arg, -math.inf, math.inf, what) if arg else None
        if v is None:
            raise ValueError(f"*{what}= needs a value")
        return checked_value(name, v)

    return parse


def _setter(name: str) -> Callable[[NAR, object], None]:
    def run(nar: NAR, value: object) -> None:
        setattr(nar.config, name, value)

    return run


def _flag(what: str) -> Callable[[str, NAR], bool]:
    """A parser for ``*what=true`` / ``*what=false``."""

    def parse(arg: str, nar: NAR) -> bool:
        if arg not in ("true", "false"):
            raise ValueError(f"*{what}= is true or false")
        return arg == "true"

    return parse


def _volume(arg: str, nar: NAR) -> float:
    return parse_float(arg, 0.0, 100.0, "volume")


def _set_volume(nar: NAR, v: object) -> None:
    nar.config.print_derivations = True
    nar.config.volume_threshold = 1.0 - float(v) / 100.0  # type: ignore[arg-type]


def _babbling(arg: str, nar: NAR) -> float:
    if arg == "true":
        return 0.2  # ONA's MOTOR_BABBLING_CHANCE_INITIAL
    if arg == "false":
        return 0.0
    return parse_float(arg, 0.0, 1.0, "motorbabbling")


def _babblingops(arg: str, nar: NAR) -> int:
    return parse_int(arg, 1, nar.config.operations_max, "babblingops")


def _time(arg: str, nar: NAR) -> int:
    return parse_int(arg, 1, MAX_TIME, "currenttime")


def _set_time(nar: NAR, v: object) -> None:
    nar.time = v  # type: ignore[assignment]


def _stampid(arg: str, nar: NAR) -> int:
    return parse_int(arg, 1, MAX_TIME, "stampid")


def _set_stampid(nar: NAR, v: object) -> None:
    nar.stamp_base = v  # type: ignore[assignment]


def _setopname(arg: str, nar: NAR) -> tuple[int, str]:
    parts = arg.split()
    if len(parts) != 2:
        raise ValueError("*setopname takes an operation number and a name: *setopname 1 ^left")
    k = parse_int(parts[0], 1, nar.config.operations_max, "operation number")
    if not is_operation_name(parts[1]):
        raise ValueError(f"{parts[1][:40]!r} is not an operation name (^name)")
    return k, parts[1]


def _run_setopname(nar: NAR, v: object) -> None:
    k, name = v  # type: ignore[misc]
    nar.name_operation(k, name)


def _setopstdin(arg: str, nar: NAR) -> int:
    return parse_int(arg.strip(), 1, nar.config.operations_max, "operation number")


def _run_setopstdin(nar: NAR, v: object) -> None:
    """ONA's ``*setopstdin K``: operation K (by its name now) takes its result from the
    input. When it runs, it prints ``//Operation result product expected:``, then
    reads a line ``0`` and a line with a term (e.g. ``(fridge * 10_20)``), which its
    arguments' second component is unified with (see ``decision``); it fails (the
    rest of a compound operation is not run) when the input has no such lines."""
    k: int = v  # type: ignore[assignment]
    if len(nar.op_names) < k:
        nar.name_operation(k, f"^op{k}")
    nar.register_operation(nar.op_names[k - 1], _result_from_input(nar))


def _result_from_input(nar: NAR) -> Callable[[object], object]:
    def read(_arg: object = None) -> object:
        nar.emit("//Operation result product expected: ")
        reader = nar.read_input
        if reader is None:
            return False
        sync = reader()
        if sync is None or sync.strip() != "0":
            return False
        line = reader()
        if line is None:
            return False
        try:
            return parse_term(line.strip())
        except (NarseseError, RecursionError):
            return False

    return read


def _concepts(nar: NAR, v: object) -> None:
    for c in nar.memory:
        nar.emit(nar.concept_line(c))


def _stats(nar: NAR, v: object) -> None:
    for line in nar.statistics():
        nar.emit(line)


def _file(arg: str, nar: NAR) -> object:
    if not arg:
        raise ValueError("a file name is needed")
    return path_in(nar.memory_dir, arg)


def _save(nar: NAR, path: object) -> None:
    nar.save(path)  # type: ignore[arg-type]


def _load(nar: NAR, path: object) -> None:
    nar.restore(path)  # type: ignore[arg-type]


def _reset(nar: NAR, v: object) -> None:
    nar.reset()


def _concurrent(nar: NAR, v: object) -> None:
    nar.time = max(1, nar.time - 1)


def _ignored(nar: NAR, v: object) -> None:
    """Accepted for compatibility with ONA's scripts; no effect on this reasoner."""


_TABLE: list[Command] = [
    Command("reset", _none, _reset, "forget everything"),
    Command("volume", _volume, _set_volume, "0..100: how much of the derivations to print"),
    Command("motorbabbling", _babbling, _setter("motor_babbling_chance"), "true/false or 0..1"),
    Command("babblingops", _babblingops, _setter("babbling_ops"), "how many operations to try"),
    Command(
        "decisionthreshold",
        _parameter("decision_threshold", "decisionthreshold"),
        _setter("decision_threshold"),
        "0..1",
    ),
    Command(
        "anticipationconfidence",
        _parameter("anticipation_confidence", "anticipationconfidence"),
        _setter("anticipation_confidence"),
        "0..1",
    ),
    Command(
        "questionpriming",
        _parameter("question_priming", "questionpriming"),
        _setter("question_priming"),
        "0..1",
    ),
    Command(
        "similaritydistance",
        _parameter("similarity_distance", "similaritydistance"),
        _setter("similarity_distance"),
        "a distance >= 0",
    ),
    Command("currenttime", _time, _set_time, "set the current time (>= 1)"),
    Command("stampid", _stampid, _set_stampid, "set the next input's stamp id (>= 1)"),
    Command("setopname", _setopname, _run_setopname, "K ^name: name operation K"),
    Command(
        "setopstdin",
        _setopstdin,
        _run_setopstdin,
        "K: operation K reads its result from the input (a line 0, then a term)",
    ),
    Command("concepts", _none, _concepts, "print every concept"),
    Command("stats", _none, _stats, "print the statistics"),
    Command("save", _file, _save, "FILE: save the memory in the memory directory"),
    Command("load", _file, _load, "FILE: load a memory from the memory directory"),
    Command("concurrent", _none, _concurrent, "the next input happens with the last one"),
]
_TABLE.append(
    Command(
        "restrictedconceptcreation",
        _flag("restrictedconceptcreation"),
        _setter("restricted_concept_creation"),
        "true/false: derived beliefs and goals only for existing concepts",
    )
)
for _name in (
    "setoparg",
    "setvalue",
    "space",
    "query",
    "stampimport",
    "cycling_belief_events",
    "cycling_goal_events",
    "opconfig",
    "inverted_atom_index",
    "occurrence_time_index",
):
    _TABLE.append(Command(_name, _anything, _ignored, "accepted for compatibility; no effect"))

#: name -> command
COMMANDS: dict[str, Command] = {c.name: c for c in _TABLE}
_NAME = re.compile(r"\*([A-Za-z_]+)")


def split(line: str) -> tuple[Command, str, int]:
    """(command, argument text, the argument's column) of a ``*`` line, or CommandError."""
    m = _NAME.match(line)
    if m is None:
        raise CommandError(2, "a command name follows '*'")
    cmd = COMMANDS.get(m.group(1))
    if cmd is None:
        raise CommandError(2, f"unknown command *{m.group(1)[:40]}")
    rest = line[m.end() :]
    col = m.end() + 1
    stripped = rest.lstrip()
    if stripped.startswith("="):
        col += len(rest) - len(stripped) + 1
        rest = stripped[1:]
    col += len(rest) - len(rest.lstrip())
    return cmd, rest.strip(), col


def execute(nar: NAR, line: str) -> None:
    """Run one ``*`` line on ``nar``; a refused line raises NarseseError and changes
    nothing."""
    try:
        cmd, arg, col = split(line)
    except CommandError as exc:
        raise NarseseError(1, exc.column, exc.message) from None
    try:
        value = cmd.parse(arg, nar)
    except (ValueError, KeyError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
        raise NarseseError(1, col, f"*{cmd.name}: {message}") from None
    try:
        cmd.run(nar, value)
    except (MemoryFileError, OSError) as exc:
        raise NarseseError(1, col, f"*{cmd.name}: {exc}") from None
