"""ONA's parameters (Config.h), one attribute each, changeable per reasoner.

Names are ONA's in lower case, so a reader of ONA's documentation finds them.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, fields


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
    # printing
    print_derivations: bool = False
    print_input: bool = True
    volume_threshold: float = 0.0

    def update(self, **overrides: object) -> None:
        """Set parameters by name; unknown names are an error, not a silent typo."""
        names = {f.name for f in fields(self)}
        for k, v in overrides.items():
            if k not in names:
                raise KeyError(f"unknown NAR parameter {k!r}")
            setattr(self, k, type(getattr(self, k))(v))

    def as_dict(self) -> dict[str, object]:
        """All parameters by name."""
        return asdict(self)
