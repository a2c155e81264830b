"""One reasoning cycle as numbered steps (ONA's Cycle_Perform), and many of them.

Functions over a :class:`~robocog.nars.state.Reasoner`. Each step is one function of the
modules below: ``sensorimotor`` for a selected belief event, ``decision`` for goals,
``inference`` for the declarative rules; ``memorize`` stores what they conclude.
"""

from __future__ import annotations

from . import decision, declarative, links, memorize, sensorimotor
from .event import ETERNAL, Event
from .inference import Derivation, apply_double, apply_single, rule_table, special
from .memory import Concept
from .stamp import has_duplicate, merge, overlap
from .state import Reasoner, emit, shows


def cycles(s: Reasoner, n: int) -> None:
    """Run ``n`` inference cycles."""
    # capacities follow the configuration, so ``nar.config.concepts_max = N`` works
    s.memory.capacity = s.config.concepts_max
    s.memory.belief_events.capacity = s.config.cycling_belief_events_max
    for _ in range(n):
        cycle(s)


def cycle(s: Reasoner) -> None:
    """One cycle, in ONA's order of work (Cycle_Perform)."""
    # 1. Select the strongest cycling belief event (input and derived alike)
    popped = s.memory.belief_events.pop()
    if popped is not None:
        priority, e = popped
        s.stats["selected"] += 1
        if shows(s, priority):
            emit(s, "Selected: " + e.line(priority))
        # 2. Process it as an event in time: temporal and procedural induction with the
        #    recent events, sequences, anticipation (Cycle_ProcessBeliefEvents)
        if e.occurrence_time != ETERNAL:
            sc = s.memory.find(e.term)
            if sc is not None:
                sc.selected_time = s.time
            sensorimotor.process_belief_event(s, e, priority)
    # 3. Let the events that just happened travel forward through ==> and <=> beliefs,
    #    and (ONA 0.9.3) the fresh eternal beliefs through ==> beliefs
    links.forward_links(s)
    if s.config.declarative_implications_cycle_process:
        declarative.forward_eternal(s, memorize.on_new_belief)
    # 4. Process the goals layer by layer, deriving subgoals, until one is decided on;
    #    execute it and feed its event back as input, with one more cycle
    #    (Cycle_ProcessAndInferGoalEvents, Decision_Execute)
    d = decision.process_goals(s)
    if d is not None:
        executed = decision.execute(s, d)
        while executed is not None:  # (the operations of a compound one in turn)
            memorize.add_event(s, executed, 1.0, is_input=True)
            cycles(s, 1)
            executed = decision.execute_next(s, d)
        decision.assume_untried_failure(s, d)
    # 5. Infer with the selected event and the related concepts' beliefs (Cycle_Inference)
    if popped is not None:
        semantic_inference(s, popped[1], popped[0])
    # 6. Forget a little: the cycling events' priorities decay (Cycle_RelativeForgetting;
    #    a concept's priority decays lazily, see ``Concept.priority_at``)
    durability = s.config.event_durability  # (read once for the queues of every layer)
    s.memory.belief_events.decay(durability)
    for q in s.goal_layers:
        q.decay(durability)
    # 7. The clock advances
    s.time += 1


def semantic_inference(s: Reasoner, e: Event, priority: float) -> None:
    """The selected event with the single-premise rules, then with the belief (or the
    recent event) of each related concept above the adaptive priority threshold, at
    most ``belief_concept_match_target`` of them; conclusions go to ``memorize``."""
    cfg = s.config
    table = rule_table(cfg.semantic_inference_nal_level, cfg.plain_conjunctions)
    now = s.time
    # a stamp counting one input twice refuses every conclusion drawn with it, so
    # such a premise (pair) is skipped whole rather than conclusion by conclusion
    if not has_duplicate(e.stamp):
        single = Derivation(s, e.occurrence_time, e.stamp, priority, 1.0)
        apply_single(table, e.term, e.truth, single)
    s.process_id += 1
    avg = s.matched_total / now
    s.concept_threshold = min(
        1.0,
        max(
            0.0,
            s.concept_threshold
            + (avg - cfg.belief_concept_match_target) * cfg.concept_threshold_adaptation,
        ),
    )
    chosen: list[tuple[Concept, float]] = s.memory.related_above(
        e.term,
        now,
        cfg.concept_durability,
        s.concept_threshold,
        cfg.belief_concept_match_target,
        0 if cfg.derived_links_are_premises else cfg.eternal_input_usage_boost,
    )
    s.matched_total += len(chosen)
    spikes_alone = cfg.event_pairs_with_events
    # read once for every concept below (nothing in the loop changes them)
    timed = e.occurrence_time != ETERNAL
    distance = cfg.event_belief_distance
    stamp_size = cfg.stamp_size
    c: Concept
    cp: float
    belief: Event | None
    for c, cp in chosen:
        belief = c.belief
        if (
            timed
            and c.belief_spike is not None
            and abs(e.occurrence_time - c.belief_spike.occurrence_time) < distance
            and (belief is not None or spikes_alone)
        ):
            belief = c.belief_spike.projected(e.occurrence_time)
        elif belief is None:
            continue
        if overlap(e.stamp, belief.stamp):
            continue
        c.use(now, False, 0)
        stamp = merge(e.stamp, belief.stamp, stamp_size)
        if has_duplicate(stamp):
            continue
        d = Derivation(s, e.occurrence_time, stamp, priority, cp)
        apply_double(table, e.term, c.term, e.truth, belief.truth, d)
        special(e.term, c.term, e.truth, belief.truth, d)
        special(c.term, e.term, belief.truth, e.truth, d)
