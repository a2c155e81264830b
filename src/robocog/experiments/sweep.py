"""Sweeps: every combination of a few settings, many seeded missions each, on one machine
or a Ray cluster, into a table that survives being interrupted.

The garbage paper (Hammer et al.) compares its two minds at one point: sunny light, 30
runs each. Whether NARS's lead holds as detection worsens or grasps get harder takes
thousands of missions. A sweep names the settings to vary (``--vary detection=0.5:0.95:0.05``),
the minds and how many missions per point; every mission is one task whose result
depends only on its mind, its settings and its seed, so the table is the same whether
the missions ran in this process, in a local process pool or as Ray tasks, in whatever
order they finished.

The table is JSON lines: a header line with the sweep's full description and the
robocog version, then one flat row per mission, appended (and flushed) as it comes. A
sweep started again with the same description skips the missions already in the file,
so a killed sweep resumes where it stopped; a file of another sweep is refused.
"""

from __future__ import annotations

import dataclasses
import itertools
import json
import math
import os
import signal
import threading
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from robocog import __version__

#: a sweep's table format; a file of another format is refused, not guessed at
FORMAT = 1
#: bounds on what a sweep may ask for and what a table line may hold
MAX_VALUES_PER_AXIS = 1000
MAX_MISSIONS = 1_000_000
MAX_LINE_BYTES = 64 * 1024


class SweepError(ValueError):
    """A sweep that cannot be run as asked, or a table that is not this sweep's."""


# -- the grid -----------------------------------------------------------------------


@dataclass(frozen=True)
class Axis:
    """One varied setting and its values, in order."""

    name: str
    values: tuple[float, ...]


def parse_axis(text: str) -> Axis:
    """``name=start:stop:step`` (both ends included) or ``name=v1,v2,...``.

    Values are rounded to ten decimals so ``0.5:0.95:0.05`` gives 0.55, not
    0.5500000000000002, and a resumed sweep finds the same keys.
    """
    name, sep, spec = text.partition("=")
    name = name.strip()
    if not sep or not name or not spec.strip():
        raise SweepError(f"--vary {text!r}: write NAME=START:STOP:STEP or NAME=V1,V2,...")
    try:
        if ":" in spec:
            parts = [float(p) for p in spec.split(":")]
            if len(parts) != 3:
                raise SweepError(f"--vary {text!r}: a range is START:STOP:STEP")
            start, stop, step = parts
            if not all(math.isfinite(p) for p in parts) or step <= 0 or stop < start:
                raise SweepError(f"--vary {text!r}: need finite START <= STOP and STEP > 0")
            count = math.floor((stop - start) / step + 1e-9) + 1
            if count > MAX_VALUES_PER_AXIS:
                raise SweepError(f"--vary {text!r}: {count} values, at most {MAX_VALUES_PER_AXIS}")
            values = [round(start + i * step, 10) for i in range(count)]
        else:
            values = [float(v) for v in spec.split(",") if v.strip()]
    except ValueError as exc:
        if isinstance(exc, SweepError):
            raise
        raise SweepError(f"--vary {text!r}: {exc}") from exc
    if not values or len(values) > MAX_VALUES_PER_AXIS:
        raise SweepError(f"--vary {text!r}: between 1 and {MAX_VALUES_PER_AXIS} values")
    if not all(math.isfinite(v) for v in values):
        raise SweepError(f"--vary {text!r}: values must be finite numbers")
    if len(set(values)) != len(values):
        raise SweepError(f"--vary {text!r}: a value is repeated")
    return Axis(name, tuple(values))


@dataclass(frozen=True)
class Task:
    """One mission of a sweep: a mind, one point of the grid, a seed block and a run."""

    mind: str
    point: tuple[tuple[str, float], ...]
    seed: int
    run: int

    @property
    def key(self) -> str:
        """The row's identity in the table (and what a resumed sweep skips)."""
        params = ",".join(f"{k}={v!r}" for k, v in self.point)
        return f"{self.mind}|{params}|{self.seed}|{self.run}"


@dataclass(frozen=True)
class SweepSpec:
    """Everything that decides a sweep's table; two sweeps with equal specs give equal
    tables, so it is the header a resumed sweep is checked against."""

    experiment: str
    axes: tuple[Axis, ...]
    minds: tuple[str, ...]
    runs: int
    seeds: int
    first_seed: int = 0
    #: fixed settings of the experiment (for example the garbage field's light)
    fixed: tuple[tuple[str, Any], ...] = ()

    def __post_init__(self) -> None:
        names = [a.name for a in self.axes]
        if len(set(names)) != len(names):
            raise SweepError("an axis is named twice")
        if not self.minds:
            raise SweepError("name at least one mind")
        if self.runs < 1 or self.seeds < 1:
            raise SweepError("--runs and --seeds must be at least 1")
        if self.missions > MAX_MISSIONS:
            raise SweepError(f"{self.missions} missions; a sweep runs at most {MAX_MISSIONS}")

    @property
    def points(self) -> list[tuple[tuple[str, float], ...]]:
        """Every combination of the axes' values, the first axis varying slowest."""
        names = [a.name for a in self.axes]
        return [
            tuple(zip(names, combo, strict=True))
            for combo in itertools.product(*(a.values for a in self.axes))
        ]

    @property
    def missions(self) -> int:
        """How many missions the whole sweep runs."""
        per_point = len(self.minds) * self.runs * self.seeds
        return per_point * math.prod(len(a.values) for a in self.axes)

    def tasks(self) -> list[Task]:
        """Every mission, in a fixed order (the order the table is sorted into)."""
        blocks = range(self.first_seed, self.first_seed + self.seeds)
        return [
            Task(mind, point, seed, run)
            for point in self.points
            for mind in self.minds
            for seed in blocks
            for run in range(self.runs)
        ]

    def to_json(self) -> dict[str, Any]:
        """The header's description of the sweep."""
        return {
            "experiment": self.experiment,
            "axes": {a.name: list(a.values) for a in self.axes},
            "minds": list(self.minds),
            "runs": self.runs,
            "seeds": self.seeds,
            "first_seed": self.first_seed,
            "fixed": dict(self.fixed),
        }

    @classmethod
    def from_json(cls, doc: Any) -> SweepSpec:
        """The spec of a table's header, checked field by field."""
        if not isinstance(doc, dict):
            raise SweepError("the header's sweep is not an object")
        try:
            axes = tuple(Axis(str(k), tuple(float(v) for v in vs)) for k, vs in doc["axes"].items())
            return cls(
                experiment=str(doc["experiment"]),
                axes=axes,
                minds=tuple(str(m) for m in doc["minds"]),
                runs=int(doc["runs"]),
                seeds=int(doc["seeds"]),
                first_seed=int(doc.get("first_seed", 0)),
                fixed=tuple(sorted(dict(doc.get("fixed", {})).items())),
            )
        except (KeyError, TypeError, ValueError, AttributeError) as exc:
            raise SweepError(f"the header's sweep is malformed: {exc}") from exc


# -- the studies: what one mission of each experiment is -------------------------------


@dataclass(frozen=True)
class Study:
    """How one experiment runs a single mission of a sweep."""

    name: str
    #: the minds (or, for the planner, search modes) it can compare
    minds: tuple[str, ...]
    #: settings that may be varied, name -> type (float or int)
    settings: dict[str, type]
    #: the row's column whose mean is the success rate
    success: str
    #: (mind, settings, mission seed) -> the mission's outcome as a flat dict
    mission: Callable[[str, dict[str, Any], int], dict[str, Any]]
    #: the fixed settings this study takes from the command line, with defaults
    fixed: dict[str, Any] = dataclasses.field(default_factory=dict)
    #: the experiment seed -> the mission seeds of its runs
    seeds: Callable[[int, int], list[int]] = lambda seed, runs: [
        seed * 1000 + i for i in range(runs)
    ]
    #: the fixed settings -> every setting of the world in effect where no axis varies it
    base: Callable[[dict[str, Any]], dict[str, Any]] = lambda fixed: dict(fixed)
    #: settings -> None, or ValueError/TypeError naming the one out of range: run on every
    #: value of every axis before the first mission, so that a bad value is one line at the
    #: start, not an error in a worker process after the sweep has begun
    validate: Callable[[dict[str, Any]], None] = lambda settings: None


def _numeric_fields(config_type: type) -> dict[str, type]:
    """The settings of a world's config dataclass that are single numbers."""
    kinds = {"float": float, "int": int, "float | None": float}
    return {
        f.name: kinds[str(f.type)] for f in dataclasses.fields(config_type) if str(f.type) in kinds
    }


def _garbage_mission(mind: str, settings: dict[str, Any], seed: int) -> dict[str, Any]:
    from robocog.experiments.garbage import default_minds, run_once
    from robocog.worlds.garbage import GarbageConfig

    spec = default_minds([mind])[0]
    why = spec.probe()
    if why:
        raise SweepError(f"mind {mind} cannot run: {why}")
    run = run_once(spec, GarbageConfig(**settings), seed)
    return {
        "objects": run.objects,
        "collected": run.collected,
        "rate": run.rate,
        **{f"missed_{cause}": n for cause, n in run.causes.items()},
        "pick_attempts": run.pick_attempts,
        "futile_picks": run.futile_picks,
        "futile_seconds": round(run.futile_seconds, 3),
        "sim_seconds": round(run.sim_seconds, 3),
        "cycles": run.cycles,
    }


def _room_mission(mind: str, settings: dict[str, Any], seed: int) -> dict[str, Any]:
    from robocog.experiments.room_exit import run_once
    from robocog.worlds.room import RoomConfig

    run = run_once(seed, mind, RoomConfig(**settings), keep_route=False)
    return {
        "outcome": run.outcome,
        "left_room": float(run.left_room),
        "exited": run.exited,
        "looks": run.looks,
        "opposite_looks": run.opposite_looks,
        "commands": run.commands,
        "sim_seconds": round(run.sim_seconds, 3),
    }


def _assembly_mission(mode: str, settings: dict[str, Any], seed: int) -> dict[str, Any]:
    from robocog.experiments.assembly import run_sequence

    sequence = str(settings.pop("sequence", "tables"))
    run = run_sequence(sequence, seed=seed, mode=mode, **settings)
    return {
        "reached": float(run.reached),
        "requests": len(run.requests),
        "requests_reached": sum(r.reached for r in run.requests),
        "replans": sum(r.record.replans for r in run.requests),
        "failed_grasps": sum(r.failed_grasps for r in run.requests),
        "arm_seconds": round(sum(r.arm_seconds for r in run.requests), 3),
    }


def _plain(config: Any) -> dict[str, Any]:
    """A world's config as JSON-ready settings."""
    return json.loads(json.dumps(dataclasses.asdict(config), default=str))


def _check_assembly(settings: dict[str, Any]) -> None:
    rate = settings.get("failure_rate", 0.0)
    if not 0.0 <= rate <= 1.0:
        raise ValueError(f"failure_rate must be a probability in [0, 1], not {rate!r}")
    if settings.get("sequence", "tables") not in ("tables", "whole"):
        raise ValueError(f"sequence is tables or whole, not {settings['sequence']!r}")


def studies() -> dict[str, Study]:
    """The experiments a sweep can run, by name."""
    from robocog.worlds.garbage import GarbageConfig
    from robocog.worlds.room import RoomConfig

    return {
        "garbage": Study(
            "garbage",
            ("nars", "bdi", "ona"),
            _numeric_fields(GarbageConfig),
            "rate",
            _garbage_mission,
            fixed={"light": "sunny"},
            base=lambda fixed: _plain(GarbageConfig(**fixed)),
            validate=lambda settings: GarbageConfig(**settings) and None,
        ),
        "room-exit": Study(
            "room-exit",
            ("bdi", "reference"),
            _numeric_fields(RoomConfig),
            "left_room",
            _room_mission,
            base=lambda fixed: _plain(RoomConfig(**fixed)),
            validate=lambda settings: RoomConfig(**settings) and None,
        ),
        "assembly": Study(
            "assembly",
            ("astar", "first", "quick"),
            {"failure_rate": float},
            "reached",
            _assembly_mission,
            fixed={"sequence": "tables"},
            validate=_check_assembly,
        ),
    }


def check(spec: SweepSpec) -> Study:
    """The spec's study, once its minds and axes are known to it."""
    table = studies()
    if spec.experiment not in table:
        raise SweepError(f"unknown experiment {spec.experiment!r}: choose {', '.join(table)}")
    study = table[spec.experiment]
    for mind in spec.minds:
        if mind not in study.minds:
            raise SweepError(
                f"{spec.experiment} has no mind {mind!r}: choose {', '.join(study.minds)}"
            )
    for axis in spec.axes:
        if axis.name not in study.settings:
            known = ", ".join(sorted(study.settings))
            raise SweepError(f"{spec.experiment} has no setting {axis.name!r} to vary: {known}")
    for name, _value in spec.fixed:
        if name not in study.fixed:
            raise SweepError(f"{spec.experiment} has no fixed setting {name!r}")
    _check_values(spec, study)
    return study


def _check_values(spec: SweepSpec, study: Study) -> None:
    """Every value of every axis, and the fixed settings, as the world would take them."""
    fixed = dict(spec.fixed)
    try:
        study.validate(dict(fixed))
    except (ValueError, TypeError) as exc:
        raise SweepError(str(exc)) from None
    for axis in spec.axes:
        kind = study.settings[axis.name]
        for value in axis.values:
            if not math.isfinite(value):
                raise SweepError(f"--vary {axis.name}: {value} is not a finite number")
            if kind is int and value != int(value):
                raise SweepError(f"--vary {axis.name}={value:g}: {axis.name} is a whole number")
            try:
                study.validate({**fixed, axis.name: int(value) if kind is int else value})
            except (ValueError, TypeError) as exc:
                raise SweepError(f"--vary {axis.name}={value:g}: {exc}") from None


def run_task(spec_doc: dict[str, Any], task: Task) -> dict[str, Any]:
    """One mission as a table row; the function every executor runs, in any process."""
    spec = SweepSpec.from_json(spec_doc)
    study = check(spec)
    settings: dict[str, Any] = dict(spec.fixed)
    for name, value in task.point:
        settings[name] = int(value) if study.settings[name] is int else value
    mission_seed = study.seeds(task.seed, task.run + 1)[task.run]
    outcome = study.mission(task.mind, settings, mission_seed)
    return {
        "key": task.key,
        "mind": task.mind,
        **dict(task.point),
        "seed": task.seed,
        "run": task.run,
        "mission_seed": mission_seed,
        **outcome,
    }


# -- the table ----------------------------------------------------------------------


def header(spec: SweepSpec) -> dict[str, Any]:
    """The table's first line."""
    return {"format": FORMAT, "robocog_version": __version__, "sweep": spec.to_json()}


def read_table(path: Path, spec: SweepSpec | None = None) -> tuple[SweepSpec, list[dict[str, Any]]]:
    """The spec and rows of a table, checked line by line.

    A last line without its newline is a write cut short by a kill: it is left out
    (and :func:`open_table` cuts it off before appending). Any other bad line is an
    error naming the file, line and column.
    """
    data = path.read_bytes()
    lines = data.split(b"\n")
    complete = lines[:-1]  # the text after the last newline was never finished
    if not complete:
        raise SweepError(f"{path}: empty, not a sweep table")
    rows: list[dict[str, Any]] = []
    found: SweepSpec | None = None
    keys: set[str] = set()
    for number, raw in enumerate(complete, start=1):
        if len(raw) > MAX_LINE_BYTES:
            raise SweepError(f"{path}:{number}:1: line longer than {MAX_LINE_BYTES} bytes")
        try:
            doc = json.loads(raw.decode("utf-8"))
        except UnicodeDecodeError as exc:
            raise SweepError(f"{path}:{number}:{exc.start + 1}: not UTF-8") from exc
        except json.JSONDecodeError as exc:
            raise SweepError(f"{path}:{number}:{exc.colno}: {exc.msg}") from exc
        if not isinstance(doc, dict):
            raise SweepError(f"{path}:{number}:1: a line must be a JSON object")
        if number == 1:
            if doc.get("format") != FORMAT:
                raise SweepError(f"{path}:1:1: not a sweep table of format {FORMAT}")
            found = SweepSpec.from_json(doc.get("sweep"))
            if spec is not None and found != spec:
                raise SweepError(
                    f"{path}: holds another sweep ({json.dumps(found.to_json())}); "
                    "choose another --out or start over with --fresh"
                )
            keys = {t.key for t in found.tasks()}
            continue
        key = doc.get("key")
        if key not in keys:
            raise SweepError(f"{path}:{number}:1: a row that is not a mission of this sweep")
        rows.append(doc)
    assert found is not None
    return found, rows


def open_table(path: Path, spec: SweepSpec, fresh: bool = False) -> list[dict[str, Any]]:
    """The rows already done (none for a new table); the file ready for appending."""
    if path.exists() and not fresh:
        _spec, rows = read_table(path, spec)
        data = path.read_bytes()
        end = data.rfind(b"\n") + 1
        if end != len(data):  # a row cut short by a kill: drop it, it runs again
            with path.open("r+b") as f:
                f.truncate(end)
        return rows
    path.parent.mkdir(parents=True, exist_ok=True)
    from robocog.atomic import write_text

    write_text(path, json.dumps(header(spec)) + "\n")
    return []


def sorted_rows(spec: SweepSpec, rows: Iterable[dict[str, Any]]) -> list[dict[str, Any]]:
    """Rows in the sweep's task order, one per mission (a row written twice counts once)."""
    order = {t.key: i for i, t in enumerate(spec.tasks())}
    unique = {r["key"]: r for r in rows}
    return sorted(unique.values(), key=lambda r: order[r["key"]])


# -- the executors ------------------------------------------------------------------

Executor = Callable[[dict[str, Any], Sequence[Task]], Iterator[dict[str, Any]]]


def in_process(spec_doc: dict[str, Any], tasks: Sequence[Task]) -> Iterator[dict[str, Any]]:
    """Each mission in this process, one after another."""
    for task in tasks:
        yield run_task(spec_doc, task)


def process_pool(jobs: int) -> Executor:
    """Missions in ``jobs`` worker processes of this machine, yielded as they finish."""

    def execute(spec_doc: dict[str, Any], tasks: Sequence[Task]) -> Iterator[dict[str, Any]]:
        from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

        with ProcessPoolExecutor(max_workers=jobs) as pool:
            pending = {pool.submit(run_task, spec_doc, t) for t in tasks}
            while pending:
                done, pending = wait(pending, return_when=FIRST_COMPLETED)
                for future in done:
                    yield future.result()

    return execute


def ray_cluster(address: str | None, cpus: int | None = None) -> Executor:
    """Missions as Ray tasks, one each, on the cluster at ``address`` (``auto`` for the
    one ``ray start`` runs here) or, with no address, on a local Ray started for the
    sweep with ``cpus`` CPUs. Ray moves tasks and rows between its own processes of the
    cluster the user set up; nothing from outside it is read."""

    def execute(spec_doc: dict[str, Any], tasks: Sequence[Task]) -> Iterator[dict[str, Any]]:
        try:
            import ray
        except ImportError as exc:
            raise SweepError("--ray needs Ray: pip install 'robocog[cluster]'") from exc
        started = not ray.is_initialized()
        # Ray's start sets a SIGTERM handler of its own (it ends the process) and leaves
        # it after its shutdown: the process's own are put back then
        handlers = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
        if started:
            if address:
                ray.init(address=address, log_to_driver=False)
            else:
                ray.init(num_cpus=cpus, include_dashboard=False, log_to_driver=False)
        try:
            remote = ray.remote(run_task)
            pending = [remote.remote(spec_doc, t) for t in tasks]
            while pending:
                done, pending = ray.wait(pending, num_returns=1)
                yield from ray.get(done)
        finally:
            if started:
                ray.shutdown()
                if threading.current_thread() is threading.main_thread():
                    for sig, handler in handlers.items():
                        if handler is not None:  # (None: set outside Python)
                            signal.signal(sig, handler)

    return execute


def run_sweep(
    spec: SweepSpec,
    table: Path,
    execute: Executor = in_process,
    fresh: bool = False,
    advance: Callable[[int], None] | None = None,
) -> list[dict[str, Any]]:
    """Run the missions not yet in ``table``, appending each row as it comes; return
    every row in task order. ``advance`` is told how many missions were already done,
    then called once per mission."""
    check(spec)
    done = open_table(table, spec, fresh)
    have = {r["key"] for r in done}
    todo = [t for t in spec.tasks() if t.key not in have]
    if advance:
        advance(len(have))
    rows = list(done)
    if todo:
        with table.open("a", encoding="utf-8") as f:
            for row in execute(spec.to_json(), todo):
                f.write(json.dumps(row) + "\n")
                f.flush()
                os.fsync(f.fileno())
                rows.append(row)
                if advance:
                    advance(1)
    return sorted_rows(spec, rows)
