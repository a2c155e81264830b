"""ONA's parameters (Config.h), one attribute each, changeable per reasoner.

Names are ONA's in lower case, so a reader of ONA's documentation finds them.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, fields

#: the largest time (cycle, occurrence time, stamp id) the reasoner accepts: far beyond
#: any run (a million cycles a second for thirty years), and small enough that sums of
#: two such times stay exact in a double and within a 64-bit C long (compiled engine)
MAX_TIME = 10**15


@dataclass(slots=True)
class Config:
    """Parameters of one reasoner; defaults are ONA 0.9.2's."""

    # anticipation
    anticipation_threshold: float = 0.501
    anticipation_confidence: float = 0.01
    # decisions
    condition_threshold: float = 0.501
    decision_threshold: float = 0.501
    motor_babbling_chance: float = 0.2
    motor_babbling_suppression_threshold: float = 0.55
    babbling_ops: int = 10
    neg_goal_age_max: int = 20
    # attention
    event_durability: float = 0.9999
    concept_durability: float = 0.9
    belief_concept_match_target: int = 80
    concept_threshold_adaptation: float = 1e-6
    eternal_input_usage_boost: int = 1_000_000
    question_priming: float = 0.1
    event_belief_distance: int = 20
    similarity_distance: float = 1.0
    #: an event is paired with a related concept's recent event (within
    #: ``event_belief_distance``) even when that concept has no eternal belief.  ONA
    #: 0.9.2 gets this pairing by eternalizing every event; this keeps the pairing
    #: (event-to-event inference such as spatial categories) without the eternalized
    #: copies, which crowd out the eternal knowledge examples ask about.
    event_pairs_with_events: bool = True
    #: events also revise their concept's eternal belief (ONA 0.9.2 does; off by default)
    eternalize_events: bool = False
    #: derived intersections/differences, top-level images and conjunctions with
    #: dependent variables are kept only where their concept already exists.  Later
    #: ONA versions do this to save memory; ONA 0.9.2 (followed here) creates the
    #: concept, which is what lets event-level inference compose e.g.
    #: ``<([filled] & rectangle) --> (leftOf /1 {x})>`` from two fresh events.
    #: Compositions with variables keep the rule either way (they multiply fastest).
    compositions_need_concept: bool = False
    # temporal
    max_sequence_len: int = 2
    #: the most operations a decision runs (ONA's MAX_COMPOUND_OP_LEN, 1 in 0.9.2 and
    #: 0.9.3): an implication whose precondition ends in more, ``((a &/ ^x) &/ ^y) =/>
    #: g``, is not decided on (ONA stops with an assertion there); with more room its
    #: operations run in turn. Sequences of operations are not learned
    max_compound_op_len: int = 1
    precondition_consequence_distance: int = 20
    max_sequence_timediff: int = 20
    # space
    concepts_max: int = 4096
    cycling_belief_events_max: int = 40
    cycling_goal_events_max: int = 400
    cycling_goal_events_layers: int = 30
    operations_max: int = 10
    stamp_size: int = 10
    table_size: int = 20
    occurrence_time_index_size: int = 512
    # truth
    truth_projection_decay: float = 0.8
    min_confidence: float = 0.01
    # derivation
    semantic_inference_nal_level: int = 6
    allow_var_intro: bool = True
    top_k_declarative_implications: int = 20
    belief_last_used_tolerance: int = 5
    # ONA 0.9.3's additions (Config.h names); the defaults keep 0.9.2's behaviour and
    # ``ONA_VERSIONS["0.9.3"]`` switches them to 0.9.3's (see ``Config.for_ona``)
    #: a goal ``<X --> Y>`` (also with a product ``(X * Y)`` on the left) meets an
    #: inheritance or similarity belief sharing a side: the other side becomes a subgoal
    declarative_inheritance_subgoaling: bool = False
    #: a goal meets an eternal ``<pre ==> goal>`` belief: ``pre!`` is derived, or, when
    #: ``pre`` has just happened, the goal's event is predicted instead
    declarative_implications_subgoaling: bool = False
    #: every cycle, eternal beliefs made or revised in the last
    #: ``belief_last_used_tolerance`` cycles travel forward through the strongest
    #: ``top_k_declarative_implications`` ``==>`` beliefs, revising the consequence's
    #: eternal belief by deduction (ONA 0.9.3's DECLARATIVE_IMPLICATIONS_CYCLE_PROCESS;
    #: its half for events robocog does with either version)
    declarative_implications_cycle_process: bool = False
    #: anticipation for a plain event predicts from the precondition's event as it is,
    #: neither projected to now nor in sequence with an operation (0.9.3: a precondition
    #: seen long ago still promises its outcome, so every input counts a failure)
    anticipation_projects_precondition: bool = True
    #: a predicted ``(! x)`` outcome is the prediction of ``x`` with the negated truth,
    #: and counts as its own failure (0.9.3's negation handling in implication tables)
    anticipation_negated_outcomes: bool = False
    #: predictions are printed as derived events (ONA 0.9.3's Globals.h: not)
    print_predictions: bool = True
    #: ``<a =/> b>`` for simultaneous ``a`` and ``b`` (dt 0) may be induced
    allow_concurrent_implications: bool = True
    #: semantic inference concludes the conjunction ``(A && B)`` of its two premises
    #: (ONA 0.9.3's rule table; the belief of a concept, the stepping stone by which a
    #: ``==>`` with a conjunction for its condition meets two beliefs)
    plain_conjunctions: bool = False
    #: derived conjunctions (not input ones) are cycled as events too (ONA 0.9.3: kept
    #: as beliefs only)
    derived_conjunction_events: bool = True
    #: a derived conjunction or ``==>`` with an image anywhere in it enters only a
    #: concept that exists (0.9.3's Memory_AddEvent; 0.9.2 makes the concept)
    image_compounds_need_concept: bool = False
    #: a ``==>`` or ``<=>`` belief that only derivations made is a second premise of
    #: semantic inference (ONA 0.9.3, ALLOW_IMPLICATION_EVENTS 1, makes no concept for
    #: it: a derived ``==>`` lives in its consequence's links, which the declarative
    #: pass reads; an implication concept counts as input by the uses an eternal input
    #: adds, ``eternal_input_usage_boost``)
    derived_links_are_premises: bool = True
    #: the declarative pass deduces only from a belief and a link whose evidence is
    #: disjoint, as every other inference does (ONA 0.9.3 and 0.9.2 do not check it
    #: there, marked "TODO STAMP" in Decision_Anticipate: a deduction from shared
    #: evidence then revises or replaces a belief, input ones too, with a stamp that
    #: repeats an input, which later inference and answers refuse). Off in both
    #: presets; on, a large taxonomy keeps its answers in 0.9.3 mode
    declarative_pass_disjoint_evidence: bool = False
    #: derived beliefs other than temporal implications only enter concepts that exist
    #: (the shell's ``*restrictedconceptcreation``)
    restricted_concept_creation: bool = False
    # printing
    print_derivations: bool = False
    print_input: bool = True
    volume_threshold: float = 0.0

    @classmethod
    def for_ona(cls, version: str = "0.9.2", **overrides: object) -> Config:
        """The parameters of ONA ``version`` (a key of :data:`ONA_VERSIONS`), then
        ``overrides``; ValueError for a version robocog does not follow."""
        try:
            preset = ONA_VERSIONS[version]
        except KeyError:
            known = ", ".join(ONA_VERSIONS)
            raise ValueError(f"ONA version {version!r} is not one of {known}") from None
        c = cls()
        c.update(**preset)
        c.update(**overrides)
        return c

    def update(self, **overrides: object) -> None:
        """Set parameters by name; unknown names are an error, not a silent typo, and
        every value is checked before any is set, so a refused call changes nothing."""
        checked = {k: checked_value(k, v) for k, v in overrides.items()}
        for k, v in checked.items():
            setattr(self, k, v)

    def as_dict(self) -> dict[str, object]:
        """All parameters by name."""
        return asdict(self)


#: the ONA versions whose behaviour a reasoner can take (``NAR(ona=...)``, ``robocog nar
#: --ona``): the parameters that differ from the defaults, which are ONA 0.9.2's. 0.9.3
#: changed Config.h's MAX_SEQUENCE_LEN (2 -> 3) and TABLE_SIZE (20 -> 120) and added the
#: switches above; RESTRICTED_CONCEPT_CREATION and ALLOW_CONCURRENT_IMPLICATIONS keep
#: their values, and ALLOW_ETERNALIZATION's 0 is robocog's ``eternalize_events`` False
#: in both (docs/nars.md, "ONA 0.9.3", says what is not followed).
ONA_VERSIONS: dict[str, dict[str, object]] = {
    "0.9.2": {},
    "0.9.3": {
        "max_sequence_len": 3,
        "table_size": 120,
        "declarative_inheritance_subgoaling": True,
        "declarative_implications_subgoaling": True,
        "declarative_implications_cycle_process": True,
        "anticipation_projects_precondition": False,
        "anticipation_negated_outcomes": True,
        "print_predictions": False,
        "plain_conjunctions": True,
        "derived_conjunction_events": False,
        "image_compounds_need_concept": True,
        "derived_links_are_premises": False,
    },
}

#: parameters a memory saved before they existed lacks: such a memory takes the default
NEWER_PARAMETERS = frozenset(
    {
        "declarative_inheritance_subgoaling",
        "declarative_implications_subgoaling",
        "declarative_implications_cycle_process",
        "anticipation_projects_precondition",
        "anticipation_negated_outcomes",
        "print_predictions",
        "allow_concurrent_implications",
        "restricted_concept_creation",
        "plain_conjunctions",
        "derived_conjunction_events",
        "max_compound_op_len",
        "image_compounds_need_concept",
        "derived_links_are_premises",
        "declarative_pass_disjoint_evidence",
    }
)

_UNIT = (0.0, 1.0)
#: the accepted range of each numeric parameter (inclusive). Values outside would make a
#: reasoner divide by zero, loop without end, or allocate without bound, so they are
#: refused where they enter (``--set``, shell commands, memory files), never clipped.
RANGES: dict[str, tuple[float, float]] = {
    "anticipation_threshold": _UNIT,
    "anticipation_confidence": _UNIT,
    "condition_threshold": _UNIT,
    "decision_threshold": _UNIT,
    "motor_babbling_chance": _UNIT,
    "motor_babbling_suppression_threshold": _UNIT,
    "babbling_ops": (1, 10_000),
    "neg_goal_age_max": (0, MAX_TIME),
    "event_durability": _UNIT,
    "concept_durability": _UNIT,
    "belief_concept_match_target": (1, 1_000_000),
    "concept_threshold_adaptation": _UNIT,
    "eternal_input_usage_boost": (0, MAX_TIME),
    "question_priming": _UNIT,
    "event_belief_distance": (0, MAX_TIME),
    "similarity_distance": (0.0, 1e6),
    "max_sequence_len": (1, 16),
    "max_compound_op_len": (1, 16),
    "precondition_consequence_distance": (0, MAX_TIME),
    "max_sequence_timediff": (0, MAX_TIME),
    "concepts_max": (1, 100_000_000),
    "cycling_belief_events_max": (1, 1_000_000),
    "cycling_goal_events_max": (1, 1_000_000),
    "cycling_goal_events_layers": (1, 1_000),
    "operations_max": (1, 10_000),
    "stamp_size": (1, 1_000),
    "table_size": (1, 100_000),
    "occurrence_time_index_size": (1, 10_000_000),
    "truth_projection_decay": _UNIT,
    "min_confidence": _UNIT,
    "semantic_inference_nal_level": (1, 9),
    "top_k_declarative_implications": (0, 1_000_000),
    "belief_last_used_tolerance": (0, MAX_TIME),
    "volume_threshold": _UNIT,
}

_TYPES: dict[str, type] = {f.name: type(f.default) for f in fields(Config)}


def checked_value(name: str, value: object) -> object:
    """``value`` as parameter ``name`` holds it, or ValueError/KeyError saying why not.

    Booleans stay booleans (an integer is not taken for one, nor one for an integer);
    numbers must be finite and within :data:`RANGES`; a float for an integer parameter
    must be whole."""
    kind = _TYPES.get(name)
    if kind is None:
        raise KeyError(f"unknown NAR parameter {name!r}")
    if kind is bool:
        if not isinstance(value, bool):
            raise ValueError(f"{name} is true or false, not {value!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise ValueError(f"{name} is a number, not {value!r}")
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"{name} must be a finite number, not {value!r}")
    lo, hi = RANGES[name]
    if not lo <= value <= hi:
        shown = repr(value) if len(repr(value)) <= 40 else f"{repr(value)[:40]}..."
        raise ValueError(f"{name}={shown} is out of range [{lo:g}, {hi:g}]")
    if kind is int:
        if value != int(value):
            raise ValueError(f"{name} is a whole number, not {value!r}")
        return int(value)
    return float(value)


#: what the shell's memory budget is spent on (``robocog nar --memory``), measured with
#: the pure-Python engine on the 10,000-link taxonomy of ``benchmarks/nars_core.py``:
#: peak resident memory 254 / 509 MiB holding 48,525 / 189,128 concepts (capacities
#: 50,000 / 200,000), i.e. about 1.9 KiB per concept (its term, index entries, beliefs
#: and events), rounded up to 2 KiB, over about 160 MiB that the interpreter, the
#: engine, the rule tables, the caches the input fills and the garbage awaiting the
#: cycle collector take. The compiled engine's objects are smaller, so the same budget
#: leaves it room to spare.
BYTES_PER_CONCEPT = 2048
ENGINE_BYTES = 160 << 20
#: the shell's budget when none is given: room for 49,152 concepts, enough for the
#: taxonomy's 10,000 links (which need about 12,000)
DEFAULT_MEMORY_BYTES = 256 << 20
#: ONA's concept capacity of 0.9.3 (``--memory ona``); the v0.9.2 tag's Config.h has 16,384,
#: robocog's 0.9.2 defaults keep 4,096, the capacity its recorded traces were made with
ONA_CONCEPTS_MAX = 4096
_UNITS = {"": 1, "b": 1, "k": 1 << 10, "kb": 1 << 10, "m": 1 << 20, "mb": 1 << 20}
_UNITS |= {"g": 1 << 30, "gb": 1 << 30, "t": 1 << 40, "tb": 1 << 40}


def parse_size(text: str) -> int:
    """Bytes of a size such as ``500MB``, ``1.5GB``, ``800M`` or ``1048576`` (binary
    units: 1 MB = 2^20 bytes); ValueError for anything else."""
    s = text.strip().lower().replace(" ", "")
    digits = s.rstrip("kmgtb")
    unit = s[len(digits) :]
    if unit not in _UNITS or not digits or len(digits) > 20:
        raise ValueError(f"{text!r} is not a size such as 500MB or 2GB")
    try:
        value = float(digits)
    except ValueError:
        raise ValueError(f"{text!r} is not a size such as 500MB or 2GB") from None
    if not math.isfinite(value) or value <= 0:
        raise ValueError(f"{text!r} is not a positive size")
    return int(value * _UNITS[unit])


def concepts_for_memory(budget: int) -> int:
    """The concept capacity a memory budget of ``budget`` bytes pays for."""
    least = ENGINE_BYTES + ONA_CONCEPTS_MAX * BYTES_PER_CONCEPT
    if budget < least:
        raise ValueError(
            f"a memory of {budget >> 20} MB is too small: the engine takes about "
            f"{ENGINE_BYTES >> 20} MB and ONA's {ONA_CONCEPTS_MAX} concepts "
            f"{ONA_CONCEPTS_MAX * BYTES_PER_CONCEPT >> 20} MB more (use --memory ona "
            "or --set concepts_max=N for less)"
        )
    hi = int(RANGES["concepts_max"][1])
    return min(hi, (budget - ENGINE_BYTES) // BYTES_PER_CONCEPT)
