"""The reasoner's state: everything one NARS holds, declared in one place.

As in ONA, where the memory, the cycling event queues and the indexes are explicit data
and ``Cycle.c``, ``Decision.c``, ``Inference.c`` are functions over them, the engine's
modules are functions taking a :class:`Reasoner` as their first argument:
``sensorimotor`` (temporal induction, anticipation, the implication tables),
``decision`` (goals and operations), ``memorize`` (how an event enters memory),
``inference`` (a premise pair's conclusions), ``cycle`` (the numbered steps of one
cycle). None of them keeps state of its own; :class:`~robocog.nars.nar.NAR` is the
public face, a ``Reasoner`` with the methods a caller uses.

This module sits below all of them and imports none. Every attribute is declared here
with its type (and, for the compiled engine, with its C layout in ``state.pxd``), so a
field the cycle reads is a struct read there rather than a dictionary lookup.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .config import Config
from .memory import EventQueue, Memory
from .terms import Term

if TYPE_CHECKING:
    from .event import Event
    from .memory import Concept
    from .sensorimotor import _Pattern

#: ONA's operation slots, named until an operation is registered in their place
DEFAULT_OPERATIONS = (
    "^left",
    "^right",
    "^up",
    "^down",
    "^say",
    "^pick",
    "^drop",
    "^go",
    "^activate",
    "^deactivate",
)


class Reasoner:
    """The whole state of one reasoner: memory, clock, indexes, caches and outputs."""

    __slots__ = (
        "config",
        "seed",
        "rand_state",
        "answer_cbs",
        "derivation_cbs",
        "execution_cbs",
        "output",
        "operations",
        "memory_dir",
        "memory",
        "time",
        "stamp_base",
        "concept_threshold",
        "matched_total",
        "op_names",
        "process_id",
        "stats",
        "pending_questions",
        "time_index",
        "table_index",
        "links_by_subject",
        "general_links",
        "consequences",
        "fresh_beliefs",
        "fresh_shapes",
        "fresh_order",
        "fresh_swept",
        "strongest",
        "goal_layers",
        "recent_goal_concepts",
        "unified",
        "measured",
        "groups",
        "outcomes",
        "patterns",
    )

    def __init__(self, config: Config, seed: int) -> None:
        # -- what a reset keeps: parameters, randomness, the outside world's hooks
        self.config: Config = config
        self.seed: int = seed
        #: ONA's ``myrand`` state (see :func:`rand`)
        self.rand_state: int = seed
        self.answer_cbs: list[Callable[[Event], None]] = []
        self.derivation_cbs: list[Callable[[Event], None]] = []
        self.execution_cbs: list[Callable[[str, Term | None], None]] = []
        #: where output lines go (None: nowhere)
        self.output: Callable[[str], None] | None = None
        #: operation name -> what runs it (None: a name without an action)
        self.operations: dict[str, Callable[[Term | None], object] | None] = {}
        #: where ``*save``/``*load`` lines may write and read (None: they are refused)
        self.memory_dir: Path | None = None
        # -- the reasoner's knowledge and clock (``clear`` sets them)
        self.memory: Memory
        self.time: int
        self.stamp_base: int
        #: the adaptive priority a concept needs to be matched with a selected event
        self.concept_threshold: float
        self.matched_total: int
        #: operation names by id - 1 (ONA's operation slots)
        self.op_names: list[str]
        self.process_id: int
        self.stats: dict[str, int]
        #: unanswered questions, oldest first (see ``questions.pend``)
        self.pending_questions: dict[Term, None]
        # -- sensorimotor indexes
        #: concepts that received an event, newest first (a bounded FIFO)
        self.time_index: deque[Concept]
        #: op id -> concepts with implications in that table
        self.table_index: dict[int, dict[Concept, None]]
        #: declarative links by subject: ground subject -> {link term}; general ones apart
        self.links_by_subject: dict[Term, dict[Term, None]]
        self.general_links: dict[Term, None]
        #: (a cache) link -> for each side as the condition, event term -> the other
        #: side instantiated for that term, or None (``links.forward_links``)
        self.consequences: dict[Term, tuple[dict[Term, Term | None], dict[Term, Term | None]]]
        #: concepts whose eternal belief was made or revised lately (oldest first), for
        #: ONA 0.9.3's declarative pass (``declarative_implications_cycle_process``)
        self.fresh_beliefs: dict[Concept, list]
        #: the fresh concepts filed by the condition shapes their terms may instantiate,
        #: and a count of the notes so far that orders them (``declarative``)
        self.fresh_shapes: dict[object, dict[Concept, None]]
        self.fresh_order: int
        #: how many shapes were filed after their last sweep (``declarative._sweep``)
        self.fresh_swept: int
        #: (a cache) the ``==>`` beliefs that pass last used, its links in order and
        #: their index by condition (``declarative.strongest_links``), or None
        self.strongest: tuple | None
        # -- goals
        #: ONA's cycling goal events, one queue per layer
        self.goal_layers: list[EventQueue]
        #: concepts that recently received a goal (newest last), for the negative-outcome veto
        self.recent_goal_concepts: dict[Concept, None]
        # -- goal caches (pure functions of their keys)
        #: (general, specific) -> unify(general, specific), for goals' preconditions
        self.unified: dict[tuple[Term, Term], dict[Term, Term] | None]
        #: term -> whether it names a measured value (``decision._has_measurement``)
        self.measured: dict[Term, bool]
        # -- sensorimotor caches (pure functions of their keys, or rebuilt on demand)
        #: the time index's concepts grouped by term shape (``sensorimotor.spike_groups``),
        #: or None until anticipation first needs them
        self.groups: dict[object, dict[Concept, None]] | None
        #: (link, precondition instance) -> the link's consequence for that instance
        self.outcomes: dict[tuple[Term, Term], Term]
        #: precondition with variables -> where its instances are found
        self.patterns: dict[Term, _Pattern]
        clear(self)


def clear(s: Reasoner) -> None:
    """Forget everything (ONA's ``*reset``): memory, clock, indexes, goals and caches;
    the configuration, the random state and the hooks stay."""
    c = s.config
    s.memory = Memory(c.concepts_max, c.operations_max, c.table_size, c.cycling_belief_events_max)
    s.time = 1
    s.stamp_base = 1
    s.concept_threshold = 0.0
    s.matched_total = 0
    s.op_names = list(DEFAULT_OPERATIONS)
    s.process_id = 0
    s.stats = {"inputs": 0, "derived": 0, "selected": 0, "answers": 0}
    s.pending_questions = {}
    s.time_index = deque(maxlen=c.occurrence_time_index_size)
    s.table_index = {}
    s.links_by_subject = {}
    s.general_links = {}
    s.goal_layers = [
        EventQueue(c.cycling_goal_events_max) for _ in range(c.cycling_goal_events_layers)
    ]
    s.recent_goal_concepts = {}
    clear_caches(s)


def clear_caches(s: Reasoner) -> None:
    """Empty the sensorimotor and goal caches and the fresh beliefs of the declarative
    pass (after a reset, or when a saved state is taken: a memory file keeps neither)."""
    s.consequences = {}
    s.unified = {}
    s.measured = {}
    s.groups = None
    s.outcomes = {}
    s.patterns = {}
    s.fresh_beliefs = {}
    s.fresh_shapes = {}
    s.fresh_order = 0
    s.fresh_swept = 0
    s.strongest = None


def rand(s: Reasoner) -> int:
    """ONA's ``myrand``: the POSIX example LCG, 0..32767."""
    s.rand_state = (s.rand_state * 1103515245 + 12345) & 0xFFFFFFFFFFFFFFFF
    return (s.rand_state // 65536) % 32768


def emit(s: Reasoner, line: str) -> None:
    """Write one output line (to ``output``, if set)."""
    if s.output is not None:
        s.output(line)


def shows(s: Reasoner, priority: float) -> bool:
    """Whether a derivation of ``priority`` is printed (ONA's volume)."""
    return s.config.print_derivations and priority > s.config.volume_threshold


#: entries a remembered-results cache of the reasoner holds before it starts afresh
CACHE_SIZE = 4096

#: a cache's bound (a C long when compiled; see state.pxd)
Size = int


def remember(cache: dict, key: Any, value: Any, size: Size = CACHE_SIZE) -> Any:
    """Store ``value`` under ``key`` in ``cache``, emptied first when it holds ``size``
    entries, and return it. The reasoner's caches hold pure functions of their keys, so
    starting afresh only costs recomputation, and a cache never outgrows its bound."""
    if len(cache) >= size:
        cache.clear()
    cache[key] = value
    return value
