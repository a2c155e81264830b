"""The garbage-collection experiment of Hammer et al. (Section V.C-D): minds compared on one field.

Each run puts a fresh, seeded field in front of a fresh mind and lets the sense-decide-
act loop run until the route is complete or the battery is spent. What a run reports is
read off the world afterwards: which objects ended in the trailer and, for the others,
why not (detection, grasp, decision, time). The same seeds are used for every mind, so
the minds meet the same objects in the same light.

A second phase lets NARS do several rounds of the same field, where trash accumulates
at some checkpoints more than at others, and then asks it where it has seen trash:
``<<({SELF} * {?1}) --> at> =/> <trash --> [see]>>?``.
"""

from __future__ import annotations

import statistics
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field, replace
from functools import partial
from typing import Any

from robocog.minds import registry
from robocog.robot.loop import Loop, Step
from robocog.robot.protocols import Mind
from robocog.worlds.garbage import GarbageConfig, GarbageField

#: a hook that watches each loop an experiment makes (the inspector's): called with the
#: world, the mind and the loop before it runs, it returns the loop's ``on_step`` or None
Watch = Callable[[Any, Mind, Loop], Callable[[Step], None] | None]

#: Table II of Hammer et al.: success rate over 30 runs each, sunny light
PAPER: dict[str, float] = {"NARS": 0.68, "BDI": 0.56}
CAUSES: tuple[str, ...] = ("detection", "grasp", "decision", "time")
#: the JSON keys whose values depend on the machine rather than on seeds and settings
TIMING_KEYS: frozenset[str] = frozenset({"wall_seconds", "reason_p50_ms", "reason_p99_ms"})


@dataclass(frozen=True)
class MindSpec:
    """How to make a mind for a world, and how to ask whether it can run at all."""

    name: str
    make: Callable[[GarbageField, int], Mind]
    probe: Callable[[], str | None] = lambda: None


@dataclass
class RunResult:
    """One mission of one mind."""

    seed: int
    objects: int
    collected: int
    causes: dict[str, int]
    pick_attempts: int
    futile_picks: int
    futile_seconds: float
    sim_seconds: float
    cycles: int
    reason_p50_ms: float
    reason_p99_ms: float
    trajectory: list[tuple[float, float]] = field(default_factory=list, repr=False)
    items: list[dict[str, Any]] = field(default_factory=list, repr=False)
    notes: list[str] = field(default_factory=list)
    #: the mind's evidence for picking at the end of the run: "trash" (the background
    #: rule) and each tipped instance it formed a hypothesis for -> (frequency, confidence)
    evidence: dict[str, tuple[float, float]] = field(default_factory=dict)
    tipped: list[str] = field(default_factory=list)

    @property
    def rate(self) -> float:
        """Share of the placed objects that ended in the trailer."""
        return self.collected / self.objects if self.objects else 0.0


@dataclass
class MindResult:
    """All runs of one mind, or why it could not run."""

    name: str
    runs: list[RunResult] = field(default_factory=list)
    unavailable: str | None = None
    error: str | None = None

    @property
    def ok(self) -> bool:
        """The mind ran every run it was asked to."""
        return self.unavailable is None and self.error is None

    @property
    def success_rate(self) -> float | None:
        """Objects collected over objects placed, pooled over the runs."""
        placed = sum(r.objects for r in self.runs)
        return sum(r.collected for r in self.runs) / placed if placed else None

    def pick_evidence(self) -> dict[str, Any]:
        """The end-of-run evidence for picking, over the runs that report it."""
        general = [r.evidence["trash"] for r in self.runs if "trash" in r.evidence]
        tipped = [
            r.evidence[i] for r in self.runs for i in r.tipped if i in r.evidence and i != "trash"
        ]
        out: dict[str, Any] = {}
        if general:
            out["background_rule"] = {
                "runs": len(general),
                "mean_frequency": statistics.fmean(f for f, _c in general),
                "mean_confidence": statistics.fmean(c for _f, c in general),
            }
        tipped_total = sum(len(r.tipped) for r in self.runs if r.evidence)
        if tipped_total:
            out["tipped_instances"] = {
                "tipped": tipped_total,
                "with_hypothesis": len(tipped),
                "mean_frequency": statistics.fmean(f for f, _c in tipped) if tipped else None,
            }
        return out

    def notes(self) -> list[str]:
        """What the mind had to adapt for its engine, once each."""
        return list(dict.fromkeys(n for r in self.runs for n in r.notes))

    def causes(self) -> dict[str, int]:
        """Objects missed, by cause, over all runs."""
        out = dict.fromkeys(CAUSES, 0)
        for r in self.runs:
            for k, v in r.causes.items():
                out[k] = out.get(k, 0) + v
        return out

    def summary(self) -> dict[str, Any]:
        """The JSON entry of this mind."""
        rates = [r.rate for r in self.runs]
        entry: dict[str, Any] = {
            "success_rate": self.success_rate,
            "runs": len(self.runs),
            "status": "ok" if self.ok else ("unavailable" if self.unavailable else "error"),
        }
        if self.unavailable:
            entry["reason"] = self.unavailable
        if self.error:
            entry["reason"] = self.error
        notes = self.notes()
        if notes:
            entry["notes"] = notes
        evidence = self.pick_evidence()
        if evidence:
            entry["pick_evidence"] = evidence
        if self.runs:
            entry.update(
                {
                    "objects": sum(r.objects for r in self.runs),
                    "collected": sum(r.collected for r in self.runs),
                    "run_rate_stdev": statistics.pstdev(rates),
                    "failures": self.causes(),
                    "pick_attempts": sum(r.pick_attempts for r in self.runs),
                    "futile_picks": sum(r.futile_picks for r in self.runs),
                    "futile_seconds": round(sum(r.futile_seconds for r in self.runs), 1),
                    "mean_mission_seconds": round(
                        statistics.fmean(r.sim_seconds for r in self.runs), 1
                    ),
                    "reason_p50_ms": round(
                        statistics.median(r.reason_p50_ms for r in self.runs), 3
                    ),
                    "reason_p99_ms": round(max(r.reason_p99_ms for r in self.runs), 3),
                }
            )
            if self.name in PAPER:
                entry["paper"] = PAPER[self.name]
        return entry


@dataclass
class Accumulation:
    """What NARS says about where trash is seen, after several rounds."""

    rounds: int
    answer: tuple[str, float, float] | None
    ranking: list[tuple[str, float, float, float]]
    seen_per_place: dict[str, int]
    hotspots: list[str]
    unavailable: str | None = None
    mind: str = "NARS"
    #: the field's own count per checkpoint: arrivals, and arrivals with trash in view
    arrivals: dict[str, int] = field(default_factory=dict)
    arrivals_with_trash: dict[str, int] = field(default_factory=dict)

    def trash_share(self, place: str) -> float | None:
        """Share of the arrivals at ``place`` with trash in view (None if never there)."""
        n = self.arrivals.get(place, 0)
        return self.arrivals_with_trash.get(place, 0) / n if n else None

    @property
    def hotspots_first(self) -> bool | None:
        """Whether the places NARS ranks first are the hotspots of the field."""
        if not self.ranking or not self.hotspots:
            return None
        top = [r[0] for r in self.ranking[: len(self.hotspots)]]
        return set(top) == set(self.hotspots)


@dataclass
class ExperimentResult:
    """Everything a report is written from."""

    config: GarbageConfig
    seed: int
    runs: int
    minds: dict[str, MindResult]
    accumulation: Accumulation | None = None
    wall_seconds: float = 0.0
    #: "2d" or "mujoco"; the physical field adds what its camera measured
    world: str = "2d"
    extra: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        """The JSON document of ``--json``: one entry per mind under ``minds``."""
        from robocog import __version__

        config = asdict(self.config)
        config["hotspots"] = {str(k): v for k, v in self.config.hotspots.items()}
        doc: dict[str, Any] = {
            "experiment": "garbage",
            "robocog_version": __version__,
            "light": self.config.light,
            "seed": self.seed,
            "runs": self.runs,
            "config": config,
            "minds": {name: m.summary() for name, m in self.minds.items()},
            "paper": PAPER,
            "wall_seconds": round(self.wall_seconds, 2),
            "world": self.world,
        }
        doc.update(self.extra)
        acc = self.accumulation
        if acc is not None:
            doc["question"] = {
                "text": "<<({SELF} * {?1}) --> at> =/> <trash --> [see]>>?",
                "asked": acc.mind,
                "rounds": acc.rounds,
                "answer": None
                if acc.answer is None
                else {
                    "statement": acc.answer[0],
                    "frequency": acc.answer[1],
                    "confidence": acc.answer[2],
                },
                "ranking": [
                    {"place": p, "frequency": f, "confidence": c, "expectation": e}
                    for p, f, c, e in acc.ranking
                ],
                "seen_per_place": acc.seen_per_place,
                "arrivals": {
                    p: {"arrivals": n, "with_trash_in_view": acc.arrivals_with_trash.get(p, 0)}
                    for p, n in acc.arrivals.items()
                },
                "hotspots": acc.hotspots,
                "hotspots_first": acc.hotspots_first,
                "unavailable": acc.unavailable,
            }
        return doc


def frame_budget(config: GarbageConfig, rounds: int = 1) -> int:
    """Loop cycles enough for the whole mission (each frame takes at least one frame time)."""
    return int(rounds * config.mission_time / config.frame_seconds) + 10


#: makes the field of one mission: the 2D field, or the physical one
WorldFactory = Callable[[GarbageConfig, int], GarbageField]


def run_once(
    spec: MindSpec,
    config: GarbageConfig,
    seed: int,
    keep_path: bool = False,
    watch: Watch | None = None,
    make_world: WorldFactory | None = None,
) -> RunResult:
    """One mission of a fresh mind on a fresh field (``watch`` hooks its loop;
    ``make_world`` makes the field, the 2D one by default)."""
    world = (make_world or _field)(config, seed)
    mind = spec.make(world, seed)
    loop = Loop(world, mind)
    on_step = watch(world, mind, loop) if watch else None
    evidence: dict[str, tuple[float, float]] = {}
    try:
        loop.run(frame_budget(config), until=lambda: world.done, on_step=on_step)
        ask = getattr(mind, "pick_evidence", None)
        if callable(ask):
            tipped = [t.instance for t in world.objects() if not t.upright]
            evidence = ask(tipped)
    finally:
        close = getattr(mind, "close", None)
        if callable(close):
            close()
        release = getattr(world, "close", None)
        if callable(release):
            release()
    causes = dict.fromkeys(CAUSES, 0)
    items = []
    for t in world.objects():
        cause = world.failure_cause(t)
        if cause:
            causes[cause] += 1
        items.append(
            {
                "instance": t.instance,
                "x": t.x,
                "y": t.y,
                "checkpoint": t.checkpoint,
                "collected": t.collected,
                "cause": cause,
                "upright": t.upright,
            }
        )
    stats = loop.stats.summary()
    return RunResult(
        seed=seed,
        objects=len(world.objects()),
        collected=world.collected(),
        causes=causes,
        pick_attempts=sum(t.pick_attempts for t in world.objects()),
        futile_picks=sum(t.picks_while_tipped for t in world.objects()),
        futile_seconds=world.futile_seconds,
        sim_seconds=world.time(),
        cycles=loop.cycles,
        reason_p50_ms=stats["reason_p50_ms"],
        reason_p99_ms=stats["reason_p99_ms"],
        trajectory=list(world.trajectory) if keep_path else [],
        items=items if keep_path else [],
        notes=list(getattr(mind, "notes", [])),
        evidence=evidence,
        tipped=[t.instance for t in world.objects() if not t.upright],
    )


def _field(config: GarbageConfig, seed: int) -> GarbageField:
    return GarbageField(config, seed=seed)


def run_mind(
    spec: MindSpec,
    config: GarbageConfig,
    seeds: Sequence[int],
    advance: Callable[[], None] | None = None,
    watch: Watch | None = None,
    make_world: WorldFactory | None = None,
) -> MindResult:
    """Every run of one mind; a mind that cannot run is reported, not raised.

    Every seed is run: what a result holds never depends on how fast the machine was.
    """
    result = MindResult(spec.name)
    try:
        why = spec.probe()
    except Exception as exc:  # a probe of an engine under construction may fail anyhow
        why = f"{type(exc).__name__}: {exc}"
    if why:
        result.unavailable = why
        return result
    for i, seed in enumerate(seeds):
        try:
            result.runs.append(
                run_once(spec, config, seed, keep_path=i == 0, watch=watch, make_world=make_world)
            )
        except Exception as exc:
            result.error = f"run {i} (seed {seed}) failed: {type(exc).__name__}: {exc}"
            break
        if advance:
            advance()
    return result


def learn_accumulation(
    spec: MindSpec,
    config: GarbageConfig,
    seed: int,
    rounds: int,
    watch: Watch | None = None,
    on_round: Callable[[int], None] | None = None,
) -> Accumulation:
    """Let a NARS mind collect for several rounds of one field, then ask where trash is
    seen (the mind must offer ``ask``, ``trash_places`` and ``new_round``).

    Each round is one run of the test procedure on the same field with the same mind:
    the field starts the robot again from its corner with fresh objects, and the mind
    keeps everything it has learned. The ranking is the mind's evidence for
    ``<<({SELF} * {p}) --> at> =/> <trash --> [see]>>`` per checkpoint, by expectation;
    the field's own count of arrivals with trash in view is returned beside it.
    ``on_round`` is told each round's number as it ends.
    """
    from robocog.minds.nars_mind import TRASH_QUESTION

    hotspots_idx = sorted(config.hotspots, key=lambda i: -config.hotspots[i])
    # One battery per round: a round ends with its route or its battery, never later.
    long_config = replace(config, mission_time=config.mission_time * (rounds + 1))
    world = GarbageField(long_config, seed=seed)
    hotspots = [world.route[i] for i in hotspots_idx if i < len(world.route)]
    why = spec.probe()
    if why:
        return Accumulation(rounds, None, [], {}, hotspots, unavailable=why, mind=spec.name)
    mind: Any = spec.make(world, seed)
    loop = Loop(world, mind)
    on_step = watch(world, mind, loop) if watch else None
    seen: dict[str, int] = dict.fromkeys(world.route, 0)
    try:
        for r in range(rounds):
            if r:
                world.new_round()
                mind.new_round()
            ends = world.time() + config.mission_time
            loop.run(
                frame_budget(config),
                until=lambda e=ends: world.route_complete or world.time() > e,
                on_step=on_step,
            )
            for t in world.objects(world.rounds):
                if t.times_seen:
                    seen[t.checkpoint] += 1
            if on_round:
                on_round(r + 1)
        answer = mind.ask(TRASH_QUESTION)
        ranking = mind.trash_places()
    finally:
        close = getattr(mind, "close", None)
        if callable(close):
            close()
    return Accumulation(
        world.rounds,
        answer,
        ranking,
        seen,
        hotspots,
        mind=spec.name,
        arrivals=dict(world.arrivals),
        arrivals_with_trash=dict(world.arrivals_with_trash),
    )


#: the minds of the paper's comparison: registry name -> the name the reports use
LABELS: dict[str, str] = {"nars": "NARS", "bdi": "BDI", "ona": "ONA"}


def default_minds(names: Sequence[str] = ("nars", "bdi")) -> list[MindSpec]:
    """The minds of the paper's comparison, by name: nars, bdi, and ona (NarsMind with
    ONA 0.9.2 as its reasoner, the peer system, when its ``NAR`` command is installed),
    each made by :mod:`robocog.minds.registry` with the route of the field as its places."""
    specs = []
    for name in names:
        key = name.lower()
        if key not in LABELS:
            raise ValueError(f"unknown mind {name!r}: choose nars, bdi or ona")
        specs.append(MindSpec(LABELS[key], partial(_make, key), partial(registry.probe, key)))
    return specs


def _make(name: str, world: GarbageField, seed: int) -> Mind:
    return registry.make(registry.MindConfig(name, seed, places=tuple(world.route)))


def run_experiment(
    specs: Sequence[MindSpec],
    runs: int = 30,
    seed: int = 0,
    config: GarbageConfig | None = None,
    rounds: int = 0,
    advance: Callable[[], None] | None = None,
    watch: Watch | None = None,
    on_round: Callable[[int], None] | None = None,
    make_world: WorldFactory | None = None,
) -> ExperimentResult:
    """Every mind on the same ``runs`` seeds; then, if ``rounds``, NARS's learning phase.

    The result depends on the seeds and the configuration alone; only ``wall_seconds``
    and the cycle-time figures tell how long it took. ``watch`` hooks every loop (the
    inspector's ``--inspect``); ``advance`` is called after each run, ``on_round`` after
    each learning round.
    """
    import time

    start = time.perf_counter()
    config = config or GarbageConfig()
    seeds = mission_seeds(seed, runs)
    minds = {s.name: run_mind(s, config, seeds, advance, watch, make_world) for s in specs}
    accumulation = None
    learners = [s for s in specs if s.name in ("NARS", "ONA")]
    ready = [s for s in learners if minds[s.name].ok] or learners
    if rounds > 0 and ready:
        try:
            accumulation = learn_accumulation(ready[0], config, seed, rounds, watch, on_round)
        except Exception as exc:
            accumulation = Accumulation(
                rounds, None, [], {}, [], unavailable=f"{type(exc).__name__}: {exc}"
            )
    return ExperimentResult(config, seed, runs, minds, accumulation, time.perf_counter() - start)


def mission_seeds(seed: int, runs: int) -> list[int]:
    """The field seeds of ``runs`` missions from experiment seed ``seed`` (shared by every
    mind, so the minds meet the same fields; a sweep uses the same numbering)."""
    return [seed * 1000 + i for i in range(runs)]
