"""Saved memories: a versioned data format that holds data and nothing else.

A memory file is gzip-compressed JSON (plain JSON is read too). Terms are written as
Narsese text and read back by ``narsese.read_canonical`` (the printed form only, without
the grammar: thousands of terms a file); everything else is numbers,
strings, lists and objects, checked for type, range and size before any of it reaches
a reasoner, so a file from anywhere can at worst be refused. The layout, field by
field, is documented in ``docs/nars.md`` ("Saved memories").

Earlier versions of robocog pickled the memory. Reading a pickle can run any code its
author chose, so such files are recognised by their first byte and refused with a
message on how to convert one that is trusted (``tools/convert_pickle_memory.py``).
"""

from __future__ import annotations

import json
import os
from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any, Protocol

from robocog import __version__
from robocog.limits import MESSAGE_CHARS, clip

from .config import MAX_TIME, NEWER_PARAMETERS, Config, checked_value
from .event import BELIEF, ETERNAL, GOAL, Event, Implication
from .memfile_checks import Bad as _Bad
from .memfile_checks import boolean as _bool
from .memfile_checks import check as _check
from .memfile_checks import float_in as _float
from .memfile_checks import int_in as _int
from .memfile_checks import list_of as _list
from .memfile_checks import object_of as _obj
from .memfile_checks import show as _show
from .memfile_checks import string as _str
from .memfile_io import FORMAT, MemoryFileError, read_file, zlib_gzip
from .memfile_io import is_memory_file as is_memory_file  # (for the shell)
from .memfile_io import path_in as path_in  # (for the *save/*load commands)
from .memfile_io import write_file as write_file  # (for NAR.save)
from .memory import Concept, EventQueue, Memory
from .narsese import parse_pattern, read_canonical
from .state import DEFAULT_OPERATIONS
from .table import Table, restored_table
from .terms import Term
from .truth import Truth

VERSION = 1
#: bounds on what a file may make the reader hold beyond its size (see memfile_io): one
#: term's text, one operation's name
MAX_TERM_CHARS = 65_536
MAX_NAME_CHARS = 1_024
#: the clock and stamp ids a file may hold. The reasoner takes input until its clock or
#: its stamp ids reach MAX_TIME (``*currenttime`` and ``*stampid`` set at most that), and
#: a cycles line runs at most MAX_CYCLES_PER_LINE past it: twice MAX_TIME leaves room
#: for any session, so every memory a session reaches can be saved and loaded back
CLOCK_MAX = 2 * MAX_TIME
#: an event's times: the clock plus or minus a ``dt`` (at most MAX_TIME either way)
EVENT_TIME_MIN = -2 * MAX_TIME
EVENT_TIME_MAX = 4 * MAX_TIME


class _State(Protocol):
    """What :func:`encode` reads of a reasoner (the attributes of ``NAR``)."""

    config: Config
    seed: int
    memory: Memory
    time: int
    stamp_base: int
    concept_threshold: float
    matched_total: int
    process_id: int
    op_names: list[str]
    stats: dict[str, int]
    pending_questions: dict[Term, None]
    time_index: deque[Concept]
    table_index: dict[int, dict[Concept, None]]
    links_by_subject: dict[Term, dict[Term, None]]
    general_links: dict[Term, None]
    goal_layers: list[EventQueue]
    recent_goal_concepts: dict[Concept, None]

    def random_state(self) -> int: ...


@dataclass
class Snapshot:
    """A reasoner's state as read from a file, every object built and checked."""

    config: dict[str, object]
    seed: int
    rand: int
    time: int
    stamp_base: int
    concept_threshold: float
    matched_total: int
    process_id: int
    op_names: list[str]
    stats: dict[str, int]
    pending_questions: dict[Term, None]
    memory: Memory
    time_index: deque[Concept]
    table_index: dict[int, dict[Concept, None]]
    links_by_subject: dict[Term, dict[Term, None]]
    general_links: dict[Term, None]
    goal_layers: list[EventQueue]
    recent_goal_concepts: dict[Concept, None]
    robocog_version: str = field(default="")


# ------------------------------------------------------------------------- writing
class _Writer:
    """Numbers each distinct term, event and implication once, so that shared objects
    stay shared after loading (an event can be a concept's belief and queued at once,
    and a later change to one must show in the other, as in the running reasoner)."""

    def __init__(self) -> None:
        self.terms: dict[Term, int] = {}
        self.events: dict[int, int] = {}
        self.event_rows: list[dict[str, object]] = []
        self.imps: dict[int, int] = {}
        self.imp_rows: list[dict[str, object]] = []
        self.keep: list[object] = []  # holds numbered objects alive, so ids stay unique

    def term(self, t: Term) -> int:
        i = self.terms.get(t)
        if i is None:
            i = self.terms[t] = len(self.terms)
        return i

    def event(self, e: Event | None) -> int | None:
        if e is None:
            return None
        i = self.events.get(id(e))
        if i is None:
            i = self.events[id(e)] = len(self.event_rows)
            self.keep.append(e)
            self.event_rows.append(
                {
                    "term": self.term(e.term),
                    "type": e.type,
                    "truth": [e.truth.f, e.truth.c],
                    "stamp": list(e.stamp),
                    "occurrence_time": e.occurrence_time,
                    "creation_time": e.creation_time,
                    "dt": e.dt,
                    "processed": bool(e.processed),
                    "is_input": bool(e.is_input),
                }
            )
        return i

    def imp(self, m: Implication) -> int:
        i = self.imps.get(id(m))
        if i is None:
            i = self.imps[id(m)] = len(self.imp_rows)
            self.keep.append(m)
            self.imp_rows.append(
                {
                    "term": self.term(m.term),
                    "truth": [m.truth.f, m.truth.c],
                    "stamp": list(m.stamp),
                    "dt": m.dt,
                    "creation_time": m.creation_time,
                    "source": None if m.source is None else self.term(m.source),
                }
            )
        return i

    def table(self, t: Table | None) -> dict[str, object] | None:
        if t is None:
            return None
        return {"size": t.size, "items": [self.imp(m) for m in t.items]}

    def queue(self, q: EventQueue) -> dict[str, object]:
        return {
            "capacity": q.capacity,
            "items": [[p, self.event(e)] for p, e in zip(q.prio, q.events, strict=True)],
        }

    def concept(self, c: Concept, in_memory: bool) -> dict[str, object]:
        tables = c.precondition_beliefs
        return {
            "id": c.id,
            "term": self.term(c.term),
            "in_memory": in_memory,
            "use_count": c.use_count,
            "last_used": c.last_used,
            "belief": self.event(c.belief),
            "belief_spike": self.event(c.belief_spike),
            "predicted_belief": self.event(c.predicted_belief),
            "goal_spike": self.event(c.goal_spike),
            "precondition_beliefs": None if tables is None else [self.table(t) for t in tables],
            "implication_links": self.table(c.implication_links),
            "priority": c.priority,
            "priority_time": c.priority_time,
            "selected_time": c.selected_time,
            "process_id": c.process_id,
            "timed": bool(c.timed),
        }


def encode(nar: _State) -> bytes:
    """The reasoner's whole state as the bytes of a memory file.

    A state the reader would refuse is not written: a clock or stamp id past
    ``CLOCK_MAX`` (only a program driving the reasoner past MAX_TIME itself gets there)
    raises MemoryFileError saying so."""
    for what, value in (("time", nar.time), ("next stamp id", nar.stamp_base)):
        if not 1 <= value <= CLOCK_MAX:
            raise MemoryFileError(
                f"the reasoner's {what} {value} is outside [1, {CLOCK_MAX}] (CLOCK_MAX), "
                "which no memory file holds; not saved (*reset starts the clock again)"
            )
    w = _Writer()
    mem = nar.memory
    live = list(mem.concepts.values())
    live_ids = {id(c) for c in live}
    # concepts that left the memory yet are still referred to (the recent goal
    # concepts keep theirs until they age out) are saved beside the others
    extra: dict[int, Concept] = {}
    referred: Iterable[Concept] = (
        *nar.time_index,
        *(c for d in nar.table_index.values() for c in d),
        *nar.recent_goal_concepts,
    )
    for c in referred:
        if id(c) not in live_ids:
            extra[id(c)] = c
    concepts = [w.concept(c, True) for c in live] + [w.concept(c, False) for c in extra.values()]
    doc: dict[str, Any] = {
        "format": FORMAT,
        "version": VERSION,
        "robocog": __version__,
        "config": nar.config.as_dict(),
        "reasoner": {
            "seed": nar.seed,
            "rand": nar.random_state(),
            "time": nar.time,
            "stamp_base": nar.stamp_base,
            "concept_threshold": nar.concept_threshold,
            "matched_total": nar.matched_total,
            "process_id": nar.process_id,
            "stats": dict(nar.stats),
        },
        "operations": list(nar.op_names),
        "memory": {
            "capacity": mem.capacity,
            "operations": mem.operations,
            "table_size": mem.table_size,
            "next_concept_id": mem.next_concept_id,
            "evictions": mem.evictions,
        },
        "concepts": concepts,
        "belief_events": w.queue(mem.belief_events),
        "goal_layers": [w.queue(q) for q in nar.goal_layers],
        "pending_questions": [w.term(t) for t in nar.pending_questions],
        "time_index": {
            "size": nar.time_index.maxlen,
            "concepts": [c.id for c in nar.time_index],
        },
        "table_index": [[op, [c.id for c in d]] for op, d in nar.table_index.items()],
        "links_by_subject": [
            [w.term(s), [w.term(t) for t in d]] for s, d in nar.links_by_subject.items()
        ],
        "general_links": [w.term(t) for t in nar.general_links],
        "recent_goal_concepts": [c.id for c in nar.recent_goal_concepts],
    }
    # the tables refer to events, implications and terms by their place in these lists
    doc["events"] = w.event_rows
    doc["implications"] = w.imp_rows
    doc["terms"] = [str(t) for t in w.terms]
    text = json.dumps(doc, separators=(",", ":"), allow_nan=False, ensure_ascii=False)
    return zlib_gzip(text.encode("utf-8"))


# ------------------------------------------------------------------------- reading


def load_file(path: str | os.PathLike[str]) -> Snapshot:
    """Read, check and build the state saved at ``path``."""
    return decode(read_file(path), str(path))


def _no_constants(name: str) -> object:
    raise ValueError(f"{name} is not a number a memory may hold")


def decode(data: bytes, source: str = "memory") -> Snapshot:
    """Build the state from a memory file's JSON text, checking every field."""
    try:
        doc = json.loads(data.decode("utf-8"), parse_constant=_no_constants)
    except UnicodeDecodeError as exc:
        raise MemoryFileError(f"{source}: not UTF-8 text at byte {exc.start}") from None
    except RecursionError:
        raise MemoryFileError(f"{source}: nested too deeply") from None
    except ValueError as exc:
        raise MemoryFileError(f"{source}: not valid JSON: {clip(str(exc), 200)}") from None
    try:
        return _Reader(doc).snapshot()
    except _Bad as exc:
        where, what = clip(exc.where, 200), clip(exc.what, MESSAGE_CHARS)
        raise MemoryFileError(f"{source}: {where}: {what}") from None


_TOP = (
    "format",
    "version",
    "robocog",
    "config",
    "reasoner",
    "operations",
    "memory",
    "concepts",
    "belief_events",
    "goal_layers",
    "pending_questions",
    "time_index",
    "table_index",
    "links_by_subject",
    "general_links",
    "recent_goal_concepts",
    "events",
    "implications",
    "terms",
)
_EVENT = (
    "term",
    "type",
    "truth",
    "stamp",
    "occurrence_time",
    "creation_time",
    "dt",
    "processed",
    "is_input",
)
_IMP = ("term", "truth", "stamp", "dt", "creation_time", "source")
_CONCEPT = (
    "id",
    "term",
    "in_memory",
    "use_count",
    "last_used",
    "belief",
    "belief_spike",
    "predicted_belief",
    "goal_spike",
    "precondition_beliefs",
    "implication_links",
    "priority",
    "priority_time",
    "selected_time",
    "process_id",
    "timed",
)
_STATS = ("inputs", "derived", "selected", "answers")
#: bounds on list lengths: what the largest accepted configuration can hold
_MAX_ITEMS = 200_000_000
_MAX_STAMP = 1_000


class _Reader:
    """Checks a decoded document field by field and builds the objects it describes."""

    def __init__(self, doc: object) -> None:
        self.doc = _obj(doc, "file", _TOP) if isinstance(doc, dict) else None
        if not (self.doc is not None):
            raise _Bad("file", "is not a JSON object")

    def snapshot(self) -> Snapshot:
        d = self.doc
        assert d is not None
        if not (d["format"] == FORMAT):
            raise _Bad("format", f"{_show(d['format'])} is not {FORMAT!r}")
        v = _int(d["version"], "version", 0, 1 << 30)
        if not (v == VERSION):
            raise _Bad("version", f"version {v}; this robocog reads version {VERSION}")
        version = _str(d["robocog"], "robocog", 64)
        config = self.config(d["config"])
        self.terms = self.term_list(d["terms"])
        self.truths: dict[tuple[float, float], Truth] = {}
        self.event_list = [
            self.event(x, f"events[{i}]", config)
            for i, x in enumerate(_list(d["events"], "events", _MAX_ITEMS))
        ]
        self.imp_list = [
            self.imp(x, f"implications[{i}]", config)
            for i, x in enumerate(_list(d["implications"], "implications", _MAX_ITEMS))
        ]
        r = _obj(d["reasoner"], "reasoner", (*_TIMES, "seed", "rand", "concept_threshold", "stats"))
        m = _obj(
            d["memory"],
            "memory",
            ("capacity", "operations", "table_size", "next_concept_id", "evictions"),
        )
        now = _int(r["time"], "reasoner.time", 1, CLOCK_MAX)
        memory = Memory(
            _int(m["capacity"], "memory.capacity", 1, 100_000_000),
            _int(m["operations"], "memory.operations", 1, 10_000),
            _int(m["table_size"], "memory.table_size", 1, 100_000),
            1,
        )
        next_id = _int(m["next_concept_id"], "memory.next_concept_id", 1, MAX_TIME)
        concepts, by_id = self.concepts(d["concepts"], memory, next_id)
        memory.restore(
            [c for c, live in concepts if live],
            next_id,
            _int(m["evictions"], "memory.evictions", 0, MAX_TIME),
        )
        memory.belief_events = self.queue(d["belief_events"], "belief_events")
        goal_layers = [
            self.queue(q, f"goal_layers[{i}]")
            for i, q in enumerate(_list(d["goal_layers"], "goal_layers", 1_000))
        ]
        if not (bool(goal_layers)):
            raise _Bad("goal_layers", "is empty")
        ti = _obj(d["time_index"], "time_index", ("size", "concepts"))
        size = _int(ti["size"], "time_index.size", 1, 10_000_000)
        ids = _list(ti["concepts"], "time_index.concepts", size)
        time_index: deque[Concept] = deque(
            (self.concept_ref(x, by_id, f"time_index.concepts[{i}]") for i, x in enumerate(ids)),
            maxlen=size,
        )
        table_index: dict[int, dict[Concept, None]] = {}
        for i, row in enumerate(_list(d["table_index"], "table_index", 10_001)):
            where = f"table_index[{i}]"
            pair = _list(row, where, 2)
            if not (len(pair) == 2):
                raise _Bad(where, "is not [operation, concepts]")
            op = _int(pair[0], where + "[0]", 0, memory.operations)
            cs = _list(pair[1], where + "[1]", _MAX_ITEMS)
            table_index[op] = {
                self.concept_ref(x, by_id, f"{where}[1][{j}]"): None for j, x in enumerate(cs)
            }
        links: dict[Term, dict[Term, None]] = {}
        for i, row in enumerate(_list(d["links_by_subject"], "links_by_subject", _MAX_ITEMS)):
            where = f"links_by_subject[{i}]"
            pair = _list(row, where, 2)
            if not (len(pair) == 2):
                raise _Bad(where, "is not [subject, links]")
            ts = _list(pair[1], where + "[1]", _MAX_ITEMS)
            links[self.term(pair[0], where + "[0]")] = {
                self.term(x, f"{where}[1][{j}]"): None for j, x in enumerate(ts)
            }
        general = {
            self.term(x, f"general_links[{i}]"): None
            for i, x in enumerate(_list(d["general_links"], "general_links", _MAX_ITEMS))
        }
        pending = {
            self.term(x, f"pending_questions[{i}]"): None
            for i, x in enumerate(_list(d["pending_questions"], "pending_questions", 10_000))
        }
        recent = {
            self.concept_ref(x, by_id, f"recent_goal_concepts[{i}]"): None
            for i, x in enumerate(_list(d["recent_goal_concepts"], "recent_goal_concepts", 10_000))
        }
        stats = _obj(r["stats"], "reasoner.stats", _STATS)
        # (a reasoner starts with the default names, however few operations it allows)
        most = max(config["operations_max"], len(DEFAULT_OPERATIONS))  # type: ignore[call-overload]
        ops = _list(d["operations"], "operations", most)
        op_names = [self.op_name(x, f"operations[{i}]") for i, x in enumerate(ops)]
        return Snapshot(
            config=config,
            seed=_int(r["seed"], "reasoner.seed", -(1 << 63), (1 << 64) - 1),
            rand=_int(r["rand"], "reasoner.rand", -(1 << 63), (1 << 64) - 1),
            time=now,
            stamp_base=_int(r["stamp_base"], "reasoner.stamp_base", 1, CLOCK_MAX),
            concept_threshold=_float(r["concept_threshold"], "reasoner.concept_threshold", 0, 1),
            matched_total=_int(r["matched_total"], "reasoner.matched_total", 0, 1 << 62),
            process_id=_int(r["process_id"], "reasoner.process_id", 0, 1 << 62),
            op_names=op_names,
            stats={k: _int(stats[k], f"reasoner.stats.{k}", 0, 1 << 62) for k in _STATS},
            pending_questions=pending,
            memory=memory,
            time_index=time_index,
            table_index=table_index,
            links_by_subject=links,
            general_links=general,
            goal_layers=goal_layers,
            recent_goal_concepts=recent,
            robocog_version=version,
        )

    # --------------------------------------------------------------- pieces
    def config(self, v: object) -> dict[str, object]:
        defaults = Config().as_dict()
        names = defaults.keys()
        if isinstance(v, dict):
            # a memory saved before a parameter existed has that parameter's default
            v = {k: defaults[k] for k in NEWER_PARAMETERS if k not in v} | v
        c = _obj(v, "config", tuple(names))
        out: dict[str, object] = {}
        for k in names:
            try:
                out[k] = checked_value(k, c[k])
            except (ValueError, KeyError) as exc:
                raise _Bad(f"config.{k}", str(exc)) from None
            if isinstance(out[k], int) and not isinstance(out[k], bool):
                # a whole float would pass ``checked_value``; the file holds integers
                if not (isinstance(c[k], int)):
                    raise _Bad(f"config.{k}", f"{c[k]!r} is not an integer")
        return out

    def term_list(self, v: object) -> list[Term]:
        out: list[Term] = []
        for i, x in enumerate(_list(v, "terms", _MAX_ITEMS)):
            where = f"terms[{i}]"
            text = _str(x, where, MAX_TERM_CHARS)
            try:
                # the printed form only, read without the grammar (a memory holds
                # thousands of terms); anything else is refused
                t = read_canonical(text)
            except RecursionError:
                raise _Bad(where, "term nested too deeply") from None
            except ValueError as exc:
                raise _Bad(
                    where, f"{text[:80]!r} is not a Narsese term in canonical form ({exc})"
                ) from None
            out.append(t)
        return out

    def term(self, v: object, where: str) -> Term:
        i = _int(v, where, 0, len(self.terms) - 1)
        return self.terms[i]

    def truth(self, v: object, where: str) -> Truth:
        pair = _list(v, where, 2)
        if not (len(pair) == 2):
            raise _Bad(where, "is not [frequency, confidence]")
        f = _float(pair[0], where + "[0]", 0.0, 1.0)
        c = _float(pair[1], where + "[1]", 0.0, 1.0)
        if not (c < 1.0):
            raise _Bad(where + "[1]", "a confidence is below 1")
        t = self.truths.get((f, c))
        if t is None:
            t = self.truths[f, c] = Truth(f, c)
        return t

    def stamp(self, v: object, where: str) -> tuple[int, ...]:
        ids = _list(v, where, _MAX_STAMP)
        return tuple(_int(x, f"{where}[{i}]", 0, CLOCK_MAX) for i, x in enumerate(ids))

    def event(self, v: object, where: str, config: dict[str, object]) -> Event:
        # The fast path: an event as robocog writes it (fields in the writer's order, of
        # the writer's types, every value in range) is built without a call per field;
        # anything else goes the checked way below, which says what is wrong.
        if type(v) is dict and tuple(v) == _EVENT:
            term, kind, truth, stamp, occ, created, dt, processed, is_input = v.values()
            terms = self.terms
            if (
                type(term) is int
                and 0 <= term < len(terms)
                and (kind == BELIEF or kind == GOAL)
                and type(occ) is int
                and EVENT_TIME_MIN <= occ <= EVENT_TIME_MAX
                and type(created) is int
                and EVENT_TIME_MIN <= created <= EVENT_TIME_MAX
                and type(dt) is float
                and -MAX_TIME <= dt <= MAX_TIME
                and (processed is True or processed is False)
                and (is_input is True or is_input is False)
                and type(stamp) is list
                and len(stamp) <= _MAX_STAMP
                and all(type(x) is int and 0 <= x <= CLOCK_MAX for x in stamp)
                and type(truth) is list
                and len(truth) == 2
            ):
                f, c = truth
                t = self.truths.get((f, c)) if type(f) is float and type(c) is float else None
                if t is None and type(f) is float and type(c) is float:
                    if 0.0 <= f <= 1.0 and 0.0 <= c < 1.0:
                        t = self.truths[f, c] = Truth(f, c)
                if t is not None:
                    return Event(
                        terms[term],
                        kind,
                        t,
                        tuple(stamp),
                        ETERNAL if occ == ETERNAL else occ,
                        created,
                        dt,
                        processed,
                        is_input,
                    )
        return self._checked_event(v, where)

    def _checked_event(self, v: object, where: str) -> Event:
        e = _obj(v, where, _EVENT)
        kind = e["type"]
        if kind not in (BELIEF, GOAL):
            raise _Bad(where + ".type", f"{_show(kind)} is not '.' or '!'")
        occ = _int(e["occurrence_time"], where + ".occurrence_time", EVENT_TIME_MIN, EVENT_TIME_MAX)
        return Event(
            self.term(e["term"], where + ".term"),
            kind,
            self.truth(e["truth"], where + ".truth"),
            self.stamp(e["stamp"], where + ".stamp"),
            ETERNAL if occ == ETERNAL else occ,
            _int(e["creation_time"], where + ".creation_time", EVENT_TIME_MIN, EVENT_TIME_MAX),
            _float(e["dt"], where + ".dt", -MAX_TIME, MAX_TIME),
            _bool(e["processed"], where + ".processed"),
            _bool(e["is_input"], where + ".is_input"),
        )

    def imp(self, v: object, where: str, config: dict[str, object]) -> Implication:
        m = _obj(v, where, _IMP)
        source = m["source"]
        return Implication(
            self.term(m["term"], where + ".term"),
            self.truth(m["truth"], where + ".truth"),
            self.stamp(m["stamp"], where + ".stamp"),
            _float(m["dt"], where + ".dt", -MAX_TIME, MAX_TIME),
            _int(m["creation_time"], where + ".creation_time", EVENT_TIME_MIN, EVENT_TIME_MAX),
            None if source is None else self.term(source, where + ".source"),
        )

    def event_ref(self, v: object, where: str) -> Event | None:
        if v is None:
            return None
        return self.event_list[_int(v, where, 0, len(self.event_list) - 1)]

    def table(self, v: object, where: str) -> Table | None:
        if v is None:
            return None
        t = _obj(v, where, ("size", "items"))
        size = _int(t["size"], where + ".size", 1, 100_000)
        items = [
            self.imp_list[_int(x, f"{where}.items[{i}]", 0, len(self.imp_list) - 1)]
            for i, x in enumerate(_list(t["items"], where + ".items", size))
        ]
        keys = {(m.term, m.dt == 0.0) for m in items}
        if not (len(keys) == len(items)):
            raise _Bad(where, "holds one link of a kind twice")
        return restored_table(size, items)

    def concepts(
        self, v: object, memory: Memory, next_id: int
    ) -> tuple[list[tuple[Concept, bool]], dict[int, Concept]]:
        out: list[tuple[Concept, bool]] = []
        by_id: dict[int, Concept] = {}
        seen_terms: set[Term] = set()
        last_id = 0
        events = self.event_list
        n_events = len(events)
        n_terms = len(self.terms)
        ops, size = memory.operations, memory.table_size
        for i, x in enumerate(_list(v, "concepts", _MAX_ITEMS)):
            # the fast path: a concept as robocog writes it, without tables (most are),
            # with every field of its type and in range; else the checked way below
            if type(x) is dict and tuple(x) == _CONCEPT:
                (cid, term_i, live, uses, last, b, bs, pb, gs, pre, links, prio, pt, st, pid,
                 timed) = x.values()  # fmt: skip
                if (
                    type(cid) is int
                    and 1 <= cid < next_id
                    and cid not in by_id
                    and type(term_i) is int
                    and 0 <= term_i < n_terms
                    and (live is True or live is False)
                    and (not live or cid > last_id)
                    and type(uses) is int
                    and 0 <= uses <= 1 << 62
                    and type(last) is int
                    and EVENT_TIME_MIN <= last <= EVENT_TIME_MAX
                    and pre is None
                    and links is None
                    and type(prio) is float
                    and 0.0 <= prio <= 1.0
                    and type(pt) is int
                    and 0 <= pt <= EVENT_TIME_MAX
                    and type(st) is int
                    and 0 <= st <= EVENT_TIME_MAX
                    and type(pid) is int
                    and 0 <= pid <= 1 << 62
                    and (timed is True or timed is False)
                    and all(
                        e is None or (type(e) is int and 0 <= e < n_events) for e in (b, bs, pb, gs)
                    )
                ):
                    term = self.terms[term_i]
                    if live:
                        if term in seen_terms:
                            raise _Bad(f"concepts[{i}].term", f"{term} has two concepts")
                        seen_terms.add(term)
                        last_id = cid
                    c = Concept(cid, term, 0, ops, size)
                    c.use_count = uses
                    c.last_used = last
                    c.belief = None if b is None else events[b]
                    c.belief_spike = None if bs is None else events[bs]
                    c.predicted_belief = None if pb is None else events[pb]
                    c.goal_spike = None if gs is None else events[gs]
                    c.priority = prio
                    c.priority_time = pt
                    c.selected_time = st
                    c.process_id = pid
                    c.timed = timed
                    by_id[cid] = c
                    out.append((c, live))
                    continue
            where = f"concepts[{i}]"
            d = _obj(x, where, _CONCEPT)
            cid = _int(d["id"], where + ".id", 1, next_id - 1)
            if not (cid not in by_id):
                raise _Bad(where + ".id", f"{cid} occurs twice")
            live = _bool(d["in_memory"], where + ".in_memory")
            term = self.term(d["term"], where + ".term")
            if live:
                # the memory's order is the order concepts were made in (eviction ties
                # and the order of related concepts follow it)
                if not (cid > last_id):
                    raise _Bad(where + ".id", "concepts in memory are not in order")
                if not (term not in seen_terms):
                    raise _Bad(where + ".term", f"{term} has two concepts")
                seen_terms.add(term)
                last_id = cid
            c = Concept(cid, term, 0, memory.operations, memory.table_size)
            c.use_count = _int(d["use_count"], where + ".use_count", 0, 1 << 62)
            c.last_used = _int(d["last_used"], where + ".last_used", EVENT_TIME_MIN, EVENT_TIME_MAX)
            for slot in ("belief", "belief_spike", "predicted_belief", "goal_spike"):
                setattr(c, slot, self.event_ref(d[slot], f"{where}.{slot}"))
            tables = d["precondition_beliefs"]
            if tables is not None:
                ts = _list(tables, where + ".precondition_beliefs", memory.operations + 1)
                _check(
                    len(ts) == memory.operations + 1,
                    where + ".precondition_beliefs",
                    f"holds {len(ts)} tables, not {memory.operations + 1}",
                )
                built = [
                    self.table(t, f"{where}.precondition_beliefs[{j}]") for j, t in enumerate(ts)
                ]
                if not (None not in built):
                    raise _Bad(where + ".precondition_beliefs", "a table is null")
                c.precondition_beliefs = built  # type: ignore[assignment]
            c.implication_links = self.table(d["implication_links"], where + ".implication_links")
            c.priority = _float(d["priority"], where + ".priority", 0.0, 1.0)
            c.priority_time = _int(d["priority_time"], where + ".priority_time", 0, EVENT_TIME_MAX)
            c.selected_time = _int(d["selected_time"], where + ".selected_time", 0, EVENT_TIME_MAX)
            c.process_id = _int(d["process_id"], where + ".process_id", 0, 1 << 62)
            c.timed = _bool(d["timed"], where + ".timed")
            by_id[cid] = c
            out.append((c, live))
        return out, by_id

    def concept_ref(self, v: object, by_id: dict[int, Concept], where: str) -> Concept:
        cid = _int(v, where, 1, MAX_TIME)
        c = by_id.get(cid)
        if not (c is not None):
            raise _Bad(where, f"no concept has id {cid}")
        return c  # type: ignore[return-value]

    def queue(self, v: object, where: str) -> EventQueue:
        q = _obj(v, where, ("capacity", "items"))
        cap = _int(q["capacity"], where + ".capacity", 1, 1_000_000)
        items = _list(q["items"], where + ".items", cap)
        queue = EventQueue(cap)
        for i, row in enumerate(items):
            w = f"{where}.items[{i}]"
            pair = _list(row, w, 2)
            if not (len(pair) == 2):
                raise _Bad(w, "is not [priority, event]")
            prio = _float(pair[0], w + "[0]", 0.0, 1.0)
            e = self.event_ref(pair[1], w + "[1]")
            if not (e is not None):
                raise _Bad(w + "[1]", "is null")
            queue.push(e, prio)  # type: ignore[arg-type]
        return queue

    def op_name(self, v: object, where: str) -> str:
        name = _str(v, where, MAX_NAME_CHARS)
        if not (is_operation_name(name)):
            raise _Bad(where, f"{name[:80]!r} is not an operation name")
        return name


_TIMES = ("time", "stamp_base", "matched_total", "process_id")


def is_operation_name(name: str) -> bool:
    """True for ``^name`` where ``name`` is a Narsese name (letters, digits, ``_``)."""
    if len(name) < 2 or len(name) > MAX_NAME_CHARS or name[0] != "^":
        return False
    try:
        t = parse_pattern(name)
    except Exception:  # noqa: BLE001 - not a term at all
        return False
    return t.op is None and str(t) == name
