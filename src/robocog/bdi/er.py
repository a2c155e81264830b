"""JasonER: sub-plans, goal conditions and the branches update events start.

Jason's JasonER extension (Jason 3.3, the ``contract-net-protocol-er`` example) lets a
plan carry plans of its own, written in braces after it::

    +!cnp(Id, Task) <- !call(LP); !bids(LP). {
        +!call(LP) <- .df_search("participant", LP); .send(LP, tell, cfp(Id, Task)).
        ...
    }

* A sub-plan is relevant only while its plan is intended, and it shares that plan's
  variables by name (``Id`` and ``Task`` above): a goal an intention posts is looked up
  first among the sub-plans of the plan on top of it (or, when that plan is a sub-plan
  itself, among its siblings), then a level up, the agent's plan library last; the
  sub-plan starts from the bindings its plan was chosen with.
* A belief change from outside (``+accept_proposal(Id)`` told by another agent) is also
  offered to each intention whose plans have a sub-plan applicable for it (with the
  bindings the plan has now): the sub-plan then runs in a *branch*, a copy of that
  intention's stack, which ends when the sub-plan does.
* ``<: Cond`` is a goal condition: the plan's goal is achieved as soon as ``Cond``
  holds, checked each cycle (Jason's ClrSatInt), whether the body still runs or has
  ended and waits for it (``<: false``: until ``.done`` ends the goal).
* ``.done`` (the nearest goal) and ``.done(G)`` achieve a goal wherever it is pursued,
  as ``.succeed_goal`` does; a branch pursuing it ends.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.circumstance import Intention, new_im
from robocog.bdi.formulas import unifies_under
from robocog.bdi.logic import holds
from robocog.bdi.terms import Literal, Var
from robocog.bdi.unifier import rename, unify, variables

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent
    from robocog.bdi.circumstance import Event


# ---------------------------------------------------------------- reading


def _map_chain(chain: P.Chain, fn: Any) -> P.Chain:
    """``chain`` with ``fn`` applied to every term of its formulas, blocks included."""
    steps = []
    while chain is not None:
        st = chain[0]
        term = st.term if st.term is None or isinstance(st.term, str) else fn(st.term)
        blocks, state = st.blocks, st.state
        if st.kind == P.IF:
            blocks = tuple((fn(c), _map_chain(b, fn)) for c, b in st.blocks)
            state = _map_chain(st.state, fn)
        elif st.kind in (P.WHILE, P.FOR, P.FORK):
            blocks = tuple(_map_chain(b, fn) for b in st.blocks)
        steps.append(P.Step(st.kind, term, blocks, st.line, state))
        chain = chain[1]
    return P.chain(steps)


def _plan_terms(plan: P.Plan) -> list:
    """The terms a plan is written with (trigger, context, goal condition, body)."""
    out: list = []
    if plan.trigger is not None:
        out.append(plan.trigger.literal)
    for t in (plan.context, plan.goal_cond):
        if t is not None:
            out.append(t)
    _map_chain(plan.body, lambda t: out.append(t) or t)
    return out


def _shared(plan: P.Plan, names: dict[str, Var]) -> P.Plan:
    """``plan`` with its variables named as one of ``names`` replaced by that one (a
    sub-plan shares its plan's variables by name), its own sub-plans likewise."""
    mapping: dict = {}
    for t in _plan_terms(plan):
        for v in variables(t):
            if v.name != "_" and not v.name.startswith("_"):
                mapping[v] = names.get(v.name, v)
    fn = lambda t: rename(t, mapping)  # noqa: E731 - one mapping for all its terms
    trig = plan.trigger
    trig = P.Trigger(trig.op, trig.kind, fn(trig.literal)) if trig is not None else None
    ctx = fn(plan.context) if plan.context is not None else None
    out = P.Plan(trig, ctx, _map_chain(plan.body, fn), plan.label, plan.source, plan.line)
    out.code_line = plan.code_line
    out.goal_cond = fn(plan.goal_cond) if plan.goal_cond is not None else None
    if plan.subplans is not None:
        mine = {v.name: v for v in mapping.values()}
        with_subplans(out, [_shared(p, {**names, **mine}) for p in plan.subplans])
    return out


def with_subplans(parent: P.Plan, subs: list[P.Plan]) -> P.Plan:
    """Give ``parent`` its sub-plans (sharing its variables by name); returns it."""
    names: dict[str, Var] = {}
    for t in _plan_terms(parent):
        for v in variables(t):
            if not v.name.startswith("_"):
                names.setdefault(v.name, v)
    lib = P.PlanLibrary()
    for sp in subs:
        sp = _shared(sp, names)
        sp.scope = parent
        lib.add(sp)
    parent.subplans = lib
    return parent


def with_goal_condition(plan: P.Plan, cond: Any) -> P.Plan:
    """``plan`` with the goal condition ``<: cond``: its body ends waiting until the
    condition holds (:func:`clear_satisfied`) or ``.done`` ends the goal."""
    wait = P.Step(P.INTERNAL, Literal(".wait", (Literal("false"),)), line=plan.line)
    out = P.Plan(
        plan.trigger,
        plan.context,
        P.chain([*P.chain_steps(plan.body), wait]),
        plan.label,
        plan.source,
        plan.line,
    )
    out.code_line = plan.code_line
    out.goal_cond = cond
    return out


# ---------------------------------------------------------------- running

_ARTIFICIAL: list[P.Plan] = []


def artificial_plan() -> P.Plan:
    """The plan under a branch's sub-plan: when the sub-plan returns to it, the branch
    ends (its first formula is stepped over by the return, as in Jason's)."""
    if not _ARTIFICIAL:
        body = [
            P.Step(P.INTERNAL, Literal(".print", (Literal("dropwhenreturntohere"),))),
            P.Step(P.INTERNAL, Literal(".drop_intention")),
        ]
        trig = P.Trigger("+", P.BELIEF, Literal("artificial_plan"))
        _ARTIFICIAL.append(P.Plan(trig, None, P.chain(body)))
    return _ARTIFICIAL[0]


def is_branch(i: Intention) -> bool:
    """Whether ``i`` is a branch an update event started for a sub-plan."""
    art = _ARTIFICIAL[0] if _ARTIFICIAL else None
    return art is not None and any(im.plan is art for im in i.stack)


def _option(ag: Agent, lib: P.PlanLibrary, trig: P.Trigger, base: dict | None) -> Any:
    for plan in lib.candidates(trig):
        s = dict(base) if base else {}
        trail: list = []
        if unify(plan.trigger.literal, trig.literal, s, trail) and (
            plan.test is None or ag._context(plan, s, trail)
        ):
            return plan, s
    return None


def _push(ag: Agent, i: Intention, plan: P.Plan, trig: P.Trigger, s: dict) -> None:
    im = new_im(plan, trig, s, plan.body)
    if plan.subplans is not None or plan.goal_cond is not None:
        im.base = dict(s)
    i.stack.append(im)
    ag._requeue(i)


def er_deliberate(ag: Agent, ev: Event) -> bool:
    """The sub-plans' part of handling ``ev``: True when a sub-plan took a goal the
    intention posted; an update event from outside starts the branches it may (and is
    then handled as usual, so False)."""
    i = ev.intention
    trig = ev.trigger
    if i is None:
        if trig.kind == P.BELIEF:
            _branches(ag, ev)
        return False
    if i.dropped or not i.stack:
        return False
    top = i.stack[-1].plan
    owner = top if top.subplans is not None else top.scope
    while owner is not None:
        base = next((im.base for im in reversed(i.stack) if im.plan is owner), None)
        got = _option(ag, owner.subplans, trig, base)
        if got is not None:
            _push(ag, i, got[0], trig, got[1])
            return True
        owner = owner.scope
    return False


def _branches(ag: Agent, ev: Event) -> None:
    trig = ev.trigger
    for i in ag.C.intentions():
        if i.dropped or not i.stack or is_branch(i):
            continue
        for im in reversed(i.stack):
            if im.plan.subplans is None:
                continue
            got = _option(ag, im.plan.subplans, trig, im.s)
            if got is None:
                continue
            branch = Intention()
            for x in i.stack:
                copy = new_im(x.plan, x.trigger, dict(x.s), x.cur)
                copy.ret, copy.base = x.ret, x.base
                branch.stack.append(copy)
            art = artificial_plan()
            branch.stack.append(new_im(art, art.trigger, {}, art.body))
            _push(ag, branch, got[0], trig, got[1])
            break


def done(ag: Agent, trig: P.Trigger | None, current: Intention | None) -> bool:
    """``.done``: achieve the goal ``trig`` (by default the nearest one of ``current``:
    the plan running it, or in a branch the plan whose sub-plan runs) wherever it is
    pursued; a branch pursuing it ends. True when ``current`` was changed."""
    if trig is None:
        if current is None or not current.stack:
            return False
        stack = current.stack
        pos = next((k for k, im in enumerate(stack) if im.plan is artificial_plan()), None)
        trig = stack[pos - 1].trigger if pos else stack[-1].trigger
    touched = False
    # the intention running .done first, then the others, as Jason goes through them
    others = [i for i in ag.C.intentions() if i is not current]
    for i in [*([current] if current is not None else []), *others]:
        if i.dropped or not i.stack:
            continue
        pos = next(
            (
                k
                for k in range(len(i.stack) - 1, -1, -1)
                if i.stack[k].trigger.op == trig.op
                and i.stack[k].trigger.kind == trig.kind
                and unifies_under(trig.literal, i.stack[k].trigger.literal, {})
            ),
            None,
        )
        if pos is None:
            continue
        touched = touched or i is current
        _achieved(ag, i, pos)
    return touched


def _achieved(ag: Agent, i: Intention, pos: int) -> None:
    """The goal of ``i.stack[pos]`` is achieved: that plan and those above it go, and
    the intention goes on after the goal (a branch ends)."""
    if is_branch(i):
        ag._drop(i)
        return
    ag.succeed_at(i, pos)


def has_goal_conditions(plan: P.Plan) -> bool:
    """Whether ``plan`` or one of its sub-plans has a goal condition other than false."""
    gc = plan.goal_cond
    if gc is not None and not (gc.__class__ is Literal and gc.functor == "false" and not gc.args):
        return True
    return plan.subplans is not None and any(has_goal_conditions(p) for p in plan.subplans)


def clear_satisfied(ag: Agent) -> None:
    """Jason's ClrSatInt: each intended plan whose goal condition now holds (with the
    bindings it was chosen with) has achieved its goal, whether its body still runs or
    has ended waiting for it."""
    for i in ag.C.intentions():
        if i.dropped:
            continue
        for pos, im in enumerate(i.stack):
            gc = im.plan.goal_cond
            if gc is not None and holds(ag, gc, dict(im.base or {}), []):
                _achieved(ag, i, pos)
                break
