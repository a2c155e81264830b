"""``.intention``: an intention seen from inside the program, as Jason 3.3 shows it.

``.intention(Id, State)``, ``.intention(Id, State, Stack)`` and
``.intention(Id, State, Stack, current)``. ``Stack`` lists the intended means from the
top down, each ``im(Label, {Trigger}, {Body}, Unifier)``: the plan's label annotated with
where the plan comes from (``code_line``, ``code_src``, ``source``, ``url``), the trigger
as a plan term, what is left of the body (the step that runs, or the subgoal being
pursued, first) and the substitution as ``[map(V, Value), ...]``. Variables come out as
fresh ones (``_N``), as Jason's do, so a program can take the stack apart without binding
anything inside the intention. A program uses it to explain what it is doing (Jason's
``failure`` and ``current-intention`` demos) or to find the other intentions' goals.

``State`` is ``running`` (selected, or ready to run), ``waiting[reason(R)]`` (on a
``.wait``, an answer, an action) or ``suspended`` (``.suspend``), Jason's states.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.stdlib.base import internal, need_args
from robocog.bdi.terms import Body, Literal, PlanTerm, Var, make_list
from robocog.bdi.unifier import rename, resolve, undo, unify, variables

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent
    from robocog.bdi.circumstance import IntendedMeans, Intention

_fresh = itertools.count(40)
RUNNING = Literal("running")


def _anon(t: Any, mapping: dict) -> Any:
    """``t`` with each of its variables replaced by a fresh ``_N`` (one per variable)."""
    found = variables(t)
    for v in found:
        if v not in mapping:
            mapping[v] = Var(f"_{next(_fresh)}")
    return rename(t, mapping) if found else t


def _java_order(names: list[str]) -> list[int]:
    """The order in which Java's ``HashMap`` lists keys with these names (inserted in
    this order): Jason keeps a substitution in one, and prints it in that order."""
    cap = 16
    while len(names) > cap * 3 // 4:
        cap *= 2

    def bucket(name: str) -> int:
        h = 0
        for ch in name:
            h = (31 * h + ord(ch)) & 0xFFFFFFFF
        return (h ^ (h >> 16)) & (cap - 1)

    # the interpreter's own variables (``_N``, named differently in Jason) come last
    def own(name: str) -> bool:
        return name[:1] == "_" and name[1:2].isdigit()

    return sorted(range(len(names)), key=lambda k: (own(names[k]), bucket(names[k]), k))


def _label(ag: Agent, im: IntendedMeans) -> Literal:
    from robocog.bdi.messages import plan_label

    label = plan_label(ag, im.plan)
    src = ag.url if not im.plan.source or im.plan.source == ag.file else im.plan.source
    line = im.plan.code_line
    extra = [Literal("code_line", (line,))] if line else []
    if src:
        extra.append(Literal("code_src", (src if ":" in src else f"file:{src}",)))
    return label.add_annots(extra)


def im_term(ag: Agent, im: IntendedMeans, handler: dict | None = None) -> Literal:
    """One intended means as Jason's ``im(Label, {Trigger}, {Body}, Unifier)``;
    ``handler``: the substitution of the failure plan handling this goal, whose
    bindings of the goal's variables Jason shows here already."""
    s = im.s
    trig = im.trigger
    lit = _anon(resolve(trig.literal, s), {})
    only = P.Plan(P.Trigger(trig.op, trig.kind, lit), None, None)
    trigger = PlanTerm(only, repr(only.trigger), bare=True)
    mapping: dict = {}
    steps = []
    for st in P.chain_steps(im.cur):
        if st.term is None or st.term.__class__ is str or st.blocks:
            steps.append(st)
            continue
        term = _anon(st.term, mapping)  # Jason shows the body as written
        steps.append(P.Step(st.kind, term, st.blocks, st.line, st.state))
    pairs = [(k, v) for k, v in s.items() if k.__class__ is Var]
    names = [k.name for k, _v in pairs]
    unifier = []
    for k in _java_order(names):
        value = resolve(pairs[k][1], s)
        if handler is not None:
            value = resolve(value, handler)
        unifier.append(Literal("map", (Var(f"_{next(_fresh)}"), _anon(value, {}))))
    return Literal("im", (_label(ag, im), trigger, Body(tuple(steps)), make_list(unifier)))


def stack_term(ag: Agent, i: Intention) -> Any:
    """The intended means of ``i``, top first."""
    out = []
    failing = None  # (goal, substitution) of a failure plan (``-!g``) above
    for im in reversed(i.stack):
        trig = im.trigger
        handler = None
        if failing is not None and trig.op == "+" and trig.kind == failing[0].kind:
            goal = resolve(failing[0].literal, failing[1])
            if unify(resolve(trig.literal, im.s), goal, {}, []):
                handler, failing = failing[1], None
        out.append(im_term(ag, im, handler))
        if trig.op == "-" and trig.kind != P.BELIEF:
            failing = (trig, im.s)
    return make_list(out)


def state_term(ag: Agent, i: Intention) -> Literal:
    """``running``, ``suspended`` or ``waiting[reason(R)]`` (Jason's ``computeState``)."""
    entry = ag.C.pending.get(i.id)
    if entry is None:
        return RUNNING
    why = entry[1]
    if why in ("suspend_ia", "suspended"):
        return Literal("suspended")
    reason = ag.wait_reasons.get(i.id) if why.startswith("wait") else None
    if reason is None:
        reason = Literal(why)
    name = "action" if why == "action" else "reason"
    return Literal("waiting", (), (Literal(name, (reason,)),))


@internal("intention")
def _intention(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    need_args(args, 2, "intention", 4)
    current = ctx[0] if ctx else None
    if len(args) == 4 and str(resolve(args[3], s)) == "current":
        if current is None:
            return False
        stack = stack_term(ag, current)  # as it is before this action binds anything
        mark = len(trail)
        if (
            unify(args[0], current.id, s, trail)
            and unify(args[1], RUNNING, s, trail)
            and unify(args[2], stack, s, trail)
        ):
            return True
        undo(s, trail, mark)
        return False
    return _each(ag, args, s, trail, current)


def _each(ag: Agent, args: tuple, s: dict, trail: list, current: Any) -> Iterator[None]:
    """One solution per live intention (the one running this action first)."""
    live = [current] if current is not None else []
    live += [i for i in ag.C.intentions() if i is not current]
    found = [
        (i, RUNNING if i is current else state_term(ag, i), len(args) > 2 and stack_term(ag, i))
        for i in live
    ]
    mark = len(trail)
    for i, state, stack in found:
        if unify(args[0], i.id, s, trail) and unify(args[1], state, s, trail):
            if len(args) == 2 or unify(args[2], stack, s, trail):
                yield None
        undo(s, trail, mark)
