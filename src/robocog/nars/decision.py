"""Goals and decisions (Algorithm 1 of the NARS robot paper, ONA's Decision.c).

Functions over a :class:`~robocog.nars.state.Reasoner`. A goal event looks up the implications whose
consequence it is, in its concept's per-operation tables; an implication whose
precondition has just happened yields a desire for its operation. The most desired
operation above the decision threshold is executed; otherwise the preconditions become
subgoals one layer down. Motor babbling tries a random operation now and then, unless a
learned one is already desired enough.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from . import goalreasoning
from . import truth as tf
from .declarative import declarative_links
from .event import BELIEF, GOAL, Event, Implication, revised_or_chosen
from .sensorimotor import add_implication, executable, split_precondition
from .stamp import fmt, merge
from .state import Reasoner, emit, rand, remember, shows
from .terms import SEQUENCE, Term, atom
from .truth import Truth, expectation
from .unify import apply, may_unify, unify

if TYPE_CHECKING:
    from .memory import Concept


@dataclass(slots=True)
class Decision:
    """An operation to execute and why."""

    desire: float
    op: Term
    implication: Implication | None = None
    precondition: Event | None = None
    babbled: bool = False
    #: the specialization of a general implication that has no evidence of its own yet
    missing_specific: Term | None = None
    #: the operations to execute before ``op``, in order, when the implication's
    #: precondition ends in several, ``((a &/ ^x) &/ ^y)`` (ONA's compound operations)
    before: tuple[Term, ...] = ()
    #: how many of ``before`` ran (see :func:`execute_next`)
    done: int = 0


def _measurement(a: Term) -> tuple[str, float] | None:
    """``B_0.8`` -> ("B", 0.8): a name carrying a measured value."""
    name = a.name
    if a.op is not None or name is None or "_" not in name:
        return None
    head, _, value = name.rpartition("_")
    try:
        return head, float(value)
    except ValueError:
        return None


def _has_measurement(s: Reasoner, t: Term) -> bool:
    found = s.measured.get(t)
    if found is None:  # (a function of the term: every goal asks it of the same ones)
        found = remember(s.measured, t, _names_measurement(t))
    return found


def _names_measurement(t: Term) -> bool:
    return any(_measurement(a) is not None for a in t.atoms())


#: "not yet known" in the goal caches of the reasoner
_UNKNOWN = object()


def _unified(s: Reasoner, general: Term, specific: Term) -> dict[Term, Term] | None:
    """``unify(general, specific)``, remembered: nobody changes the bindings returned."""
    key = (general, specific)
    b = s.unified.get(key, _UNKNOWN)
    if b is _UNKNOWN:
        b = remember(s.unified, key, unify(general, specific))
    return b


def _numeric_similarity(general: Term, specific: Term, distance: float) -> float | None:
    """1 - |v1 - v2| / distance over differing measured names (product over them);
    None if the terms differ otherwise."""
    if general is specific:
        return 1.0
    if general.op is None or specific.op is None:
        m1, m2 = _measurement(general), _measurement(specific)
        if m1 is None or m2 is None or m1[0] != m2[0]:
            return None
        return max(0.0, 1.0 - abs(m1[1] - m2[1]) / distance)
    if general.op != specific.op or len(general.args) != len(specific.args):
        return None
    sim = 1.0
    for a, b in zip(general.args, specific.args, strict=True):
        s = _numeric_similarity(a, b, distance)
        if s is None:
            return None
        sim *= s
    return sim


def _self_operation(op: Term) -> bool:
    """``^op`` or ``<({SELF} * args) --> ^op>``: only operations of this system run."""
    if op.op is None:
        return True
    s = op.args[0]
    first = s.args[0] if s.op == "*" else s
    if first.op == "{}" and len(first.args) == 1:
        first = first.args[0]
    return first.name == "SELF"


def _ground(t: Term) -> bool:
    return not t.has_indep_var and not t.has_dep_var and not t.has_query_var


def _strip_operations(pre: Term) -> tuple[Term, tuple[Term, ...]]:
    """``((a &/ ^x) &/ ^y)`` -> (a, (^x, ^y)): the condition and the operations that
    end it, in the order they run (ONA's Narsese_GetPreconditionWithoutOp)."""
    ops: list[Term] = []
    while pre.op == SEQUENCE and pre.args[1].is_op:
        ops.append(pre.args[1])
        pre = pre.args[0]
    ops.reverse()
    return pre, tuple(ops)


def add_goal(s: Reasoner, g: Event, priority: float, layer: int) -> bool:
    """Queue ``g`` in goal layer ``layer`` unless an equal goal is queued anywhere."""
    layer = min(layer, len(s.goal_layers) - 1)
    for q in s.goal_layers:
        if q.contains(g):
            return False
    return s.goal_layers[layer].push(g, priority)


# ------------------------------------------------------------------ cycle
def process_goals(s: Reasoner) -> Decision | None:
    """Select the strongest goal of each layer, top layer first, until one yields a
    decision to execute (ONA's Cycle_ProcessAndInferGoalEvents); that decision, or None.
    The caller executes it (:func:`execute`) and feeds its event back as input."""
    for layer, q in enumerate(s.goal_layers):
        popped = q.pop()
        if popped is None:
            continue
        priority, g = popped
        if shows(s, priority):
            emit(s, "Selected: " + g.line(priority))
        d = _goal(s, g, priority, layer)
        if d is not None:
            return d
    return None


def _goal(s: Reasoner, g: Event, priority: float, layer: int) -> Decision | None:
    cfg = s.config
    now = s.time
    gp = g  # ONA uses the selected goal as it is (its deductions happen "now")
    if cfg.declarative_inheritance_subgoaling or cfg.declarative_implications_subgoaling:
        _declarative_goal_reasoning(s, g, priority, layer)  # ONA 0.9.3
    if g.term.op == SEQUENCE:
        _decompose_sequence(s, g.projected(now), priority, layer)
        return None
    if g.term.is_op and executable(g.term):
        if expectation(gp.truth) >= cfg.decision_threshold and _ground(g.term):
            return Decision(expectation(gp.truth), g.term)
        return None
    mem = s.memory
    c = mem.conceptualize(g.term, now)
    if c.goal_spike is None or gp.occurrence_time > c.goal_spike.occurrence_time:
        c.goal_spike = gp
    recent = s.recent_goal_concepts
    recent.pop(c, None)
    recent[c] = None
    while len(recent) > 64:
        del recent[next(iter(recent))]
    best = _suggest(s, gp, c)
    if best is not None and best.desire >= cfg.decision_threshold:
        return best
    _subgoals(s, gp, c, priority, layer)
    return None


def _declarative_goal_reasoning(s: Reasoner, g: Event, priority: float, layer: int) -> None:
    """ONA 0.9.3's Cycle_DeclarativeGoalReasoning (see :mod:`.goalreasoning`):
    subgoals from inheritance beliefs (queued in the first layer) and from
    ``==>`` beliefs (one layer below this goal's), or predictions of the goal."""
    cfg = s.config
    now = s.time
    mem = s.memory
    size = cfg.stamp_size
    if cfg.declarative_inheritance_subgoaling and g.term.op == "-->":
        beliefs = [c.belief for c in mem.related(g.term) if c.belief is not None]
        for sub in goalreasoning.inheritance_subgoals(g, beliefs, size):
            # into the first layer (ONA's layer of input goals: the next cycle's)
            _derive_goal(s, sub, priority * expectation(sub.projected(now).truth), -1)
    if not cfg.declarative_implications_subgoaling:
        return
    links = []
    for link in declarative_links(s):
        lc = mem.find(link)
        if link.op == "==>" and lc is not None and lc.belief is not None:
            links.append((link, lc.belief.truth, lc.belief.stamp))
    if not links:
        return
    own = mem.find(g.term)
    distance = cfg.event_belief_distance

    def recent(pre: Term) -> Event | None:
        pc = mem.find(pre)
        b = pc.belief_spike if pc is not None else None
        return b if b is not None and now - b.occurrence_time < distance else None

    spike = own.goal_spike if own is not None else None
    goals, predictions = goalreasoning.implication_subgoals(g, spike, links, recent, now, size)
    for sub in goals:
        _derive_goal(s, sub, priority * expectation(sub.truth), layer)
    for pred in predictions:
        pc = mem.find(pred.term)
        if pc is not None:
            pc.predicted_belief = revised_or_chosen(pc.predicted_belief, pred, size)[0]


def _decompose_sequence(s: Reasoner, g: Event, priority: float, layer: int) -> None:
    """Goal ``(a &/ b)``: want the first component not yet fulfilled."""
    cfg = s.config
    now = s.time
    comps: list[Term] = []
    t = g.term
    while t.op == SEQUENCE:
        comps.insert(0, t.args[1])
        t = t.args[0]
    comps.insert(0, t)
    truth = g.truth
    stamp = g.stamp
    last_occ = -1
    for i, comp in enumerate(comps):
        c = s.memory.find(comp)
        spike = c.belief_spike if c is not None else None
        if spike is not None and spike.occurrence_time >= last_occ:
            pt = tf.projection(spike.truth, spike.occurrence_time, now)
            if expectation(pt) >= cfg.condition_threshold:
                if i == len(comps) - 1:
                    return  # all fulfilled
                truth = tf.goal_deduction(truth, pt)
                stamp = merge(stamp, spike.stamp, cfg.stamp_size)
                last_occ = spike.occurrence_time
                continue
        if i == 0:
            truth = tf.structural_deduction(truth)
        sub = Event(comp, GOAL, truth, stamp, now, now)
        _derive_goal(s, sub, priority * expectation(truth), layer)
        return


def _preconditions(s: Reasoner, pre: Term) -> list[Event]:
    """Recent belief events that fulfil precondition ``pre`` (unifying variables)."""
    mem = s.memory
    c: Concept | None
    if _ground(pre):
        c = mem.find(pre)
        if c is not None and c.belief_spike is not None:
            return [c.belief_spike]
        if not _has_measurement(s, pre):
            return []
        # numeric similarity: B_0.8 stands in for B_0.9, weakened by their distance
        out_n: list[Event] = []
        dist = s.config.similarity_distance
        for c in s.time_index:
            b = c.belief_spike
            if b is None:
                continue
            sim = _numeric_similarity(pre, c.term, dist)
            if sim is not None and sim > 0.0:
                t = tf.analogy(b.truth, Truth(1.0, sim))
                out_n.append(Event(pre, b.type, t, b.stamp, b.occurrence_time, b.creation_time))
        return out_n
    out = []
    # (the tests are pure reads, so their order is free: ``may_unify`` refuses most
    # of the index's hundreds of terms without a call of unify, and the groundness
    # test is ``_ground`` written out)
    ct: Term
    for c in s.time_index:
        if c.belief_spike is None:
            continue
        ct = c.term
        if not may_unify(pre, ct):
            continue
        if ct.has_indep_var or ct.has_dep_var or ct.has_query_var:
            continue
        if _unified(s, pre, ct) is not None:
            out.append(c.belief_spike)
    return out


def _goal_concepts(s: Reasoner, g: Event, c: Concept) -> list[tuple[Concept, dict[Term, Term]]]:
    """The goal's concept and those whose (general) term the goal instantiates."""
    out: list[tuple[Concept, dict[Term, Term]]] = [(c, {})]
    seen = {c}
    general_goal = g.term.has_var
    gop = g.term.op
    post: Concept
    for table in s.table_index.values():
        for post in table:
            if post in seen:
                continue
            if gop is not None and post.term.op is not None and post.term.op != gop:
                continue  # what unify would refuse first, either way round
            if post.term.has_var:
                b = _unified(s, post.term, g.term)
                if b is not None:
                    seen.add(post)
                    out.append((post, b))
            elif general_goal and _unified(s, g.term, post.term) is not None:
                seen.add(post)  # a goal with variables is served by its instances
                out.append((post, {}))
    return out


def _suggest(s: Reasoner, g: Event, c: Concept) -> Decision | None:
    """Decision_Suggest: babbling or the best learned candidate."""
    cfg = s.config
    nops = len(s.op_names)
    babble: Decision | None = None
    r = rand(s)
    if r < int(cfg.motor_babbling_chance * 32767) and nops:
        k = 1 + rand(s) % min(cfg.babbling_ops, nops)
        babble = Decision(1.0, atom(s.op_names[k - 1]), babbled=True)
    best = _best_candidate(s, g, c)
    if babble is not None and (
        best is None or best.desire <= cfg.motor_babbling_suppression_threshold
    ):
        return babble
    return best


def _best_candidate(s: Reasoner, g: Event, c: Concept) -> Decision | None:
    """Decision_BestCandidate: the most desired operation over the implications into
    the goal whose precondition has a belief event; printed when above threshold."""
    cfg = s.config
    now = s.time
    nops = len(s.op_names)
    best: Decision | None = None
    best_cx = 10**9
    vetoes: dict[Term, bool] = {}
    # (declared for the compiled engine: concepts, links and events read as structs)
    post: Concept
    imp: Implication
    spike: Event
    for post, bind in _goal_concepts(s, g, c):
        tables = post.precondition_beliefs
        if tables is None:
            continue
        for opi in range(1, min(len(tables), nops + 1)):
            for imp in list(tables[opi].items):
                subj = apply(imp.term.args[0], bind) if bind else imp.term.args[0]
                pre, op = split_precondition(subj)
                if op is None:
                    continue
                before: tuple[Term, ...] = ()
                if pre.op == SEQUENCE and pre.args[1].is_op:
                    pre, before = _strip_operations(pre)
                    if len(before) >= cfg.max_compound_op_len:
                        continue  # more operations than a decision runs
                spikes = _preconditions(s, pre)
                if not spikes:
                    continue  # (most links: nothing to deduce from)
                gd = tf.goal_deduction(g.truth, imp.truth)
                for spike in spikes:
                    b2 = unify(pre, spike.term) or {}
                    op_g = apply(op, b2)
                    first: tuple[Term, ...] = ()
                    if before:
                        # a compound operation: a dependent variable of an argument
                        # may be bound by what an earlier operation returns
                        first = tuple([apply(x, b2) for x in before])
                        if not _compound_runs(first + (op_g,)):
                            continue
                    elif not _ground(op_g) or not _self_operation(op_g):
                        continue
                    base = apply(imp.term, bind) if bind else imp.term
                    spec = apply(base, b2) if b2 else base
                    missing = None
                    if imp.term.has_var and not (before and not _ground(spec)):
                        if not _ground(spec):
                            continue
                        own = _specific(s, spec, opi)
                        if own is not None and own.truth.c > 0.05 and own.truth.f < 0.5:
                            continue  # this instance is known not to work
                        if own is None:
                            missing = spec
                    pt = tf.projection(spike.truth, spike.occurrence_time, now)
                    desire = expectation(tf.goal_deduction(gd, pt))
                    ok = vetoes.get(op_g)
                    if ok is None:  # the same for every candidate of this operation
                        ok = vetoes[op_g] = _outcomes_acceptable(s, op_g, opi)
                    if not ok:
                        desire = 0.0
                    cx = spec.complexity
                    if (
                        best is None
                        or desire > best.desire
                        or (desire == best.desire and cx < best_cx)
                    ):
                        best = Decision(
                            desire, op_g, imp, spike, missing_specific=missing, before=first
                        )
                        best_cx = cx
    if best is None or best.desire < cfg.decision_threshold:
        return None
    imp, pre = best.implication, best.precondition
    if imp is not None and pre is not None:
        emit(
            s,
            f"decision expectation={best.desire:f} implication: {imp.term}. "
            f"Stamp={fmt(imp.stamp)} Truth: frequency={imp.truth.f:f} "
            f"confidence={imp.truth.c:f} dt={imp.dt:f} precondition: {pre.term}. :|: "
            f"Stamp={fmt(pre.stamp)} Truth: frequency={pre.truth.f:f} "
            f"confidence={pre.truth.c:f} occurrenceTime={pre.occurrence_time}",
        )
    return best


def _specific(s: Reasoner, term: Term, opi: int) -> Implication | None:
    """The stored implication ``term`` (ground) in its predicate's table ``opi``."""
    post = s.memory.find(term.args[1])
    if post is None or post.precondition_beliefs is None:
        return None
    for imp in post.precondition_beliefs[opi].items:
        if imp.term is term:
            return imp
    return None


def _outcomes_acceptable(s: Reasoner, op: Term, opi: int) -> bool:
    """ConsiderNegativeOutcomes: over every recent goal (wanted or to avoid) and each
    implication of the same operation whose precondition just happened, the desires
    for the operation are revised (or the stronger chosen); an expectation below 0.5
    vetoes the operation."""
    cfg = s.config
    now = s.time
    mem = s.memory
    # (the parameters read once, not for every goal and implication met)
    age_max = cfg.neg_goal_age_max
    distance = cfg.event_belief_distance
    size = cfg.stamp_size
    acc: Event | None = None
    # (declared for the compiled engine: concepts, links and events read as structs)
    gc: Concept
    gs: Event | None
    imp: Implication
    prec: Concept | None
    spike: Event | None
    for gc in s.recent_goal_concepts:
        gs = gc.goal_spike
        if gs is None or now - gs.occurrence_time >= age_max:
            continue
        tables = gc.precondition_beliefs
        if tables is None or opi >= len(tables):
            continue
        for imp in tables[opi].items:
            prec = mem.find(imp.source) if imp.source is not None else None
            spike = prec.belief_spike if prec is not None else None
            if spike is None or now - spike.occurrence_time >= distance:
                continue
            pre, op2 = split_precondition(imp.term.args[0])
            if op2 is not op:
                continue
            ctx = tf.goal_deduction(gs.truth, imp.truth)
            local = tf.goal_deduction(ctx, tf.projection(spike.truth, spike.occurrence_time, now))
            stamp = merge(spike.stamp, merge(gs.stamp, imp.stamp, size), size)
            ev = Event(pre, GOAL, local, stamp, now, now)
            acc, _ = revised_or_chosen(acc, ev, size)
    return acc is None or expectation(acc.truth) >= 0.5


def _subgoals(s: Reasoner, g: Event, c: Concept, priority: float, layer: int) -> None:
    """Pass the goal on: each concept it matches revises its goal event, and every
    implication into it derives its precondition (without the operation) as a
    subgoal one layer down, goal ⊗ implication, priority ``priority`` × E."""
    size = s.config.stamp_size  # (read once for every implication below)
    now = s.time
    # (declared for the compiled engine: concepts, links and events read as structs)
    post: Concept
    imp: Implication
    gs: Event
    for post, bind in _goal_concepts(s, g, c):
        if post is not c and not bind and not post.term.has_var:
            continue  # an instance of a general goal: ONA passes the goal upward only
        ge = g
        if bind:
            ge = Event(apply(g.term, bind), GOAL, g.truth, g.stamp, g.occurrence_time, now)
        gs, _ = revised_or_chosen(post.goal_spike, ge, size)
        post.goal_spike = gs
        tables = post.precondition_beliefs
        if tables is None:
            continue
        for opi in range(len(tables)):
            for imp in list(tables[opi].items):
                b2 = unify(imp.term.args[1], gs.term)
                if b2 is None:
                    continue
                subj = apply(imp.term.args[0], b2) if b2 else imp.term.args[0]
                pre, _op = split_precondition(subj)
                t = tf.goal_deduction(gs.truth, imp.truth)
                sub = Event(pre, GOAL, t, merge(gs.stamp, imp.stamp, size), now, now)
                _derive_goal(s, sub, priority * expectation(t), layer)


def _derive_goal(s: Reasoner, g: Event, priority: float, layer: int) -> None:
    """Memory_AddEvent for a derived goal: complexity penalty, confidence floor, no
    duplicates; printed when it is queued."""
    priority *= 1.0 / math.log2(1.0 + g.term.complexity)
    if g.truth.c < s.config.min_confidence or priority <= 0.0:
        return
    c = s.memory.find(g.term)
    if c is not None and c.goal_spike is not None and c.goal_spike.same(g):
        return
    if c is None and s.config.restricted_concept_creation:
        return  # ONA 0.9.3's *restrictedconceptcreation
    if add_goal(s, g, priority, layer + 1) and shows(s, priority):
        emit(s, "Derived: " + g.line(priority))


# -------------------------------------------------------------- execution
def _compound_runs(ops: tuple[Term, ...]) -> bool:
    """Each operation of a compound one is this system's, with no variable in its
    arguments but dependent ones (which an earlier operation's result may bind)."""
    for x in ops:
        if x.has_indep_var or x.has_query_var or not _self_operation(x):
            return False
    return True


def execute(s: Reasoner, d: Decision) -> Event | None:
    """Decision_Execute: forget the cycling goals (no residue actions), run the
    operation (the first of a compound one) and tell who listens; the event of the
    execution, which the caller feeds back as input, is returned (it takes the next
    stamp id). A compound operation's next is run by :func:`execute_next`."""
    for q in s.goal_layers:
        q.clear()
    return _run(s, d, d.before[0] if d.before else d.op)


def execute_next(s: Reasoner, d: Decision) -> Event | None:
    """The next operation of a compound decision, once the event of the last one was
    fed back (None when all ran, or when one's result did not fit its arguments)."""
    if d.done == 0 or d.done > len(d.before):
        return None
    return _run(s, d, d.before[d.done] if d.done < len(d.before) else d.op)


def _run(s: Reasoner, d: Decision, op: Term) -> Event | None:
    """Run ``op``; an operation that returns a term has that for its result, which
    the second component of its arguments ``({SELF} * X)``, when it has variables, is
    unified with: the bindings go into its event and into the operations after it
    (ONA's feedback substitution, which ``*setopstdin`` reads from the input). An
    operation of a compound one that returns False failed. None (no event, and the
    rest of a compound operation is not run) for a failure or a result that does not
    unify."""
    if op.op is None:
        name, arg, shown = op.name, None, ""
    else:
        name, arg = op.args[1].name, op.args[0]
        shown = str(arg)
    emit(s, f"{name} executed with args {shown}")
    fn = s.operations.get(name)
    result = None
    if fn is not None:
        result = fn(arg)
    for cb in s.execution_cbs:
        cb(name, arg)
    if d.before:
        d.done += 1
    if result is False and d.before:  # failed (ONA's feedback.failed): no event, no more
        d.done = len(d.before) + 1
        return None
    if (
        isinstance(result, Term)
        and arg is not None
        and arg.op == "*"
        and len(arg.args) == 2
        and arg.args[1].has_var
    ):
        bind = unify(arg.args[1], result)
        if bind is None:
            d.done = len(d.before) + 1  # the rest is not run
            return None
        op = apply(op, bind)
        d.before = tuple([apply(x, bind) for x in d.before])
        d.op = apply(d.op, bind)
    e = Event(
        op,
        BELIEF,
        Truth(1.0, 0.9),
        (s.stamp_base,),
        s.time,
        s.time,
        is_input=True,
    )
    s.stamp_base += 1
    return e


def assume_untried_failure(s: Reasoner, d: Decision) -> None:
    """After executing through a general implication whose specialization has no
    evidence of its own yet, assume that specialization fails until its outcome shows
    up (one piece of negative evidence, as anticipation counts)."""
    if d.missing_specific is not None and d.precondition is not None:
        cfg = s.config
        general = d.implication
        past = tf.projection(
            d.precondition.truth, 0, round(general.dt) if general is not None else 0
        )
        neg = tf.eternalize(tf.induction(Truth(0.0, cfg.anticipation_confidence), past))
        add_implication(
            s,
            d.missing_specific,
            neg,
            (),
            general.dt if general else 0.0,
            False,
            0.0,
            general.creation_time if general else None,  # a copy of the general link
        )


__all__ = [
    "Decision",
    "add_goal",
    "assume_untried_failure",
    "execute",
    "execute_next",
    "process_goals",
]
