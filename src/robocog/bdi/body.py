"""Executing one formula of an intention's top intended means (Jason's ExecInt): goals,
actions, internal actions, belief changes, tests, control statements and fork-join.

These functions are the :class:`~robocog.bdi.agent.Agent`'s methods (bound there under
the names they had, a leading underscore for the internal ones), kept here by the step
of the cycle they belong to.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

from robocog.bdi import plans as P
from robocog.bdi.beliefs import StoredRule
from robocog.bdi.circumstance import (
    Event,
    Fork,
    IntendedMeans,
    Intention,
    new_event,
    new_im,
)
from robocog.bdi.formulas import (
    remember,
    sourced,
    with_source,
)
from robocog.bdi.logic import NOT_SUPPORTED, ActionError, holds, solve, unknown_action
from robocog.bdi.plans import (
    ACHIEVE,
    ACHIEVE_NF,
    ACHIEVE_STEP,
    ACTION,
    ADD_BEL,
    ADD_BEL_END,
    ADD_BEL_NF,
    BELIEF,
    CONSTRAINT,
    DEL_ADD_BEL,
    DEL_BEL,
    DEL_BEL_NF,
    FOR,
    FOR_NEXT,
    FORK,
    IF,
    INTERNAL,
    JOIN,
    TEST,
    TEST_STEP,
    WHILE,
    WHILE_AGAIN,
)
from robocog.bdi.signals import DONE, SUSPEND
from robocog.bdi.terms import (
    Body,
    Literal,
    RuleTerm,
    Var,
    term_str,
)
from robocog.bdi.unifier import (
    EvalError,
    deref,
    rename,
    resolve,
    unify,
    variables,
)

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent

_new = object.__new__


def execute(self: Agent, i: Intention) -> None:
    """Execute one formula of the top intended means of ``i`` (Jason's ExecInt)."""
    stack = i.stack
    im = stack[-1]
    cur = im.cur
    if cur is None:
        # an empty body (``<- true``): the plan is finished at once
        self._clear(i)
        if stack:
            if self._has_atomic:
                self._requeue(i)
            else:
                self.C.running.append(i)
        return
    step = cur[0]
    k = step.kind
    s = im.s
    try:
        if k == ACHIEVE_STEP:
            trig = step.cache
            if trig is None:
                goal = step.state
                if goal is None:
                    goal = step.term
                    if goal.__class__ is Literal:
                        goal = step.state = with_source(goal)
                if goal.__class__ is Literal and goal.ground:
                    # a goal without variables: the same trigger every time
                    trig = step.cache = P.Trigger("+", ACHIEVE, goal)
                else:
                    memo = step.memo  # reuse what remember() kept, if the value is the same
                    if memo:
                        x = s.get(memo[0])
                        while x.__class__ is Var:
                            x = s.get(x)
                        memo = memo[2] if x is memo[1] and x is not None else None
                    else:
                        memo = None
                    if memo is not None:
                        trig = memo
                    else:
                        lit = resolve(goal, s, {})
                        if lit.__class__ is not Literal:
                            raise ActionError(
                                f"{term_str(lit)} is not a goal", "body_var_without_value"
                            )
                        if lit is not goal and goal.__class__ is not Literal:
                            lit = with_source(lit)
                        trig = self._trigger(step, "+", ACHIEVE, lit)
                        remember(step, goal, s, trig)
            if self._event_waiters or self._has_atomic:
                self.post(Event(trig, i))
            else:
                self.C.events.append(new_event(trig, i))
        elif k == ACTION:
            lit = step.memo  # reuse what remember() kept, if the value is the same
            if lit:
                x = s.get(lit[0])
                while x.__class__ is Var:
                    x = s.get(x)
                lit = lit[2] if x is lit[1] and x is not None else None
            else:
                lit = None
            if lit is None:
                lit = resolve(step.term, s)
                remember(step, step.term, s, lit)
            if lit.__class__ is Var:
                raise ActionError(f"variable {lit.name} has no value", "body_var_without_value")
            if lit.__class__ is Body:
                # a body term in a variable (``H`` of ``{H; R}``): its formulas run here
                im.cur = (step, P.chain(lit.steps, im.cur[1]))
                self._advance(i)
                return
            if lit.__class__ is not Literal:
                raise ActionError(f"{term_str(lit)} is not an action")
            if lit.functor[0] == ".":
                fn = self._internal.get(lit.functor)
                if fn is None:
                    self._unknown_internal(i, lit)
                    return
                r = fn(self, lit.args, s, [], (i, im, step))
                if r is False:
                    self.fail_intention(i, "ia_failed", "")
                elif r is not SUSPEND and r is not DONE:
                    if r is True or r is None or any(True for _ in r):
                        self._advance(i)
                    else:
                        self.fail_intention(i, "ia_failed", "")
            else:
                self._act(i, lit)
        elif k == DEL_ADD_BEL:
            self._del_add_step(i, step, s)
        elif k == INTERNAL:
            lit = step.term
            fn = self._internal.get(lit.functor)
            if fn is None:
                self._unknown_internal(i, resolve(lit, s))
                return
            r = fn(self, lit.args, s, [], (i, im, step))
            if r is True or r is None:
                self._advance(i)
            elif r is False:
                self.fail_intention(i, "ia_failed", "")
            elif r is SUSPEND or r is DONE:
                pass
            else:
                ok = False
                for _ in r:
                    ok = True
                    break
                if ok:
                    self._advance(i)
                else:
                    self.fail_intention(i, "ia_failed", "")
        elif k == ADD_BEL or k == ADD_BEL_NF or k == ADD_BEL_END:
            self._add_belief_step(i, step, s)
        elif k == DEL_BEL or k == DEL_BEL_NF:
            self._del_belief_step(i, step, s)
        elif k == CONSTRAINT:
            if holds(self, step.term, s, []):
                self._advance(i)
            else:
                self.fail_intention(
                    i, "constraint_failed", f"Constraint {step!r} was not satisfied"
                )
        elif k == TEST_STEP:
            self._test_step(i, step, s)
        elif k == ACHIEVE_NF:
            lit = resolve(step.term, s, {})
            if lit.__class__ is not Literal:
                raise ActionError(f"{term_str(lit)} is not a goal", "body_var_without_value")
            self.post(Event(P.Trigger("+", ACHIEVE, with_source(lit)), None))
            self._advance(i)
        elif k == IF:
            self._if_step(i, im, step)
        elif k == WHILE or k == WHILE_AGAIN:
            self._while_step(i, im, step)
        elif k == FOR or k == FOR_NEXT:
            self._for_step(i, im, step)
        elif k == FORK:
            self._fork_step(i, im, step)
        elif k == JOIN:
            self._join_step(i, step)
        else:
            raise ActionError(f"cannot execute {step!r}")
    except ActionError as exc:
        self.fail_intention(i, exc.error, str(exc), getattr(exc, "annots", ()))
    except EvalError as exc:
        self.fail_intention(i, "ia_failed", str(exc))
    except RecursionError:
        self.fail_intention(i, "ia_failed", "term nesting too deep")
    except Exception as exc:  # noqa: BLE001 - a faulty extension must not stop the agent
        self.warn(f"error executing {step!r}: {exc.__class__.__name__}: {exc}")
        self.fail_intention(i, "ia_failed", str(exc))


def unknown_internal(self: Agent, i: Intention, lit: Literal) -> None:
    """An internal action nobody defined goes to the environment, as in Jason (and
    fails there with ``action_failed`` unless the environment knows it); one of
    Jason's own that robocog lacks fails, saying so."""
    if lit.functor in NOT_SUPPORTED:
        raise ActionError(unknown_action(lit))
    self.warn(f"{unknown_action(lit)}: handed to the environment, as Jason does")
    self._act(i, lit)


def fork_step(self: Agent, i: Intention, im: IntendedMeans, step: P.Step) -> None:
    """Jason's ``.fork``: each branch goes on as an intention of its own, a copy of
    ``i`` whose plan runs the branch, then a join, then what followed the fork; ``i``
    itself is done. The branches share the intended means below the forking one
    (only one branch ever returns into them) and each has its own bindings."""
    fork = Fork(step.term == "and")
    rest = im.cur[1]
    below = i.stack[:-1]
    for branch in step.blocks:
        join = P.Step(JOIN, None, line=step.line, state=fork)
        b = Intention()
        top = new_im(im.plan, im.trigger, dict(im.s), P.prepend(branch, (join, rest)))
        top.ret = im.ret
        b.stack = [*below, top]
        b.fork = (fork, len(i.stack))
        fork.branches.append(b)
        fork.to_finish += 1
    i.stack = []
    for b in fork.branches:
        self._requeue(b)


def join_step(self: Agent, i: Intention, step: P.Step) -> None:
    """Jason's ``.join``: with ``|&|`` the last branch to arrive goes on and the
    others end here; with ``|||`` the first goes on and the others are dropped."""
    fork = step.state
    assert isinstance(fork, Fork)
    fork.to_finish -= 1
    if fork.both:
        if fork.to_finish == 0:
            self._advance(i)
        return
    for b in fork.branches:
        if b is not i:
            self._drop(b)
    fork.branches = [i]
    self._advance(i)


def fork_failure(self: Agent, i: Intention) -> bool:
    """What a failure in a branch does to its fork; True when the failure ends there
    (a branch of ``|||`` failing below its own goals: the others go on). A failure
    handled in the branch's own subgoals is the branch's affair."""
    fork, point = i.fork or (None, 0)
    assert fork is not None
    for im in i.stack[point:]:
        t = im.trigger
        if t.kind != BELIEF and self.pl.has_candidate(P.Trigger("-", t.kind, t.literal)):
            return False
    if fork.both:
        for b in fork.branches:
            if b is not i:
                self._drop(b)
        fork.branches = [i]
        i.fork = None
        return False
    fork.branches = [b for b in fork.branches if b is not i]
    self.warn(f"no failure event was generated for {i.stack[-1].trigger!r} (a branch of |||)")
    self._drop(i)
    return True


_rule_vars = itertools.count(40)


def add_belief_step(self: Agent, i: Intention, step: P.Step, s: dict) -> None:
    got = resolve(step.term, s, {})
    if got.__class__ is RuleTerm:
        # ``+R`` with R a rule term: the rule joins the belief base (its variables
        # fresh ones, as a rule that came in a message has in Jason)
        mapping = {v: Var(f"_{next(_rule_vars)}") for v in variables(got.body, variables(got.head))}
        head, body = rename(got.head, mapping), rename(got.body, mapping)
        self.bb.add_rule(StoredRule(head, body), at_end=step.kind == ADD_BEL_END)
        self._advance(i)
        return
    lit = resolve(sourced(step), s, {})
    if lit.__class__ is not Literal:
        raise ActionError(f"{term_str(lit)} is not a belief", "body_var_without_value")
    lit = with_source(lit)
    added = self.bb.add(lit, at_end=step.kind == ADD_BEL_END)
    if added is None:
        self._advance(i)
        return
    trig = self._trigger(step, "+", BELIEF, lit)
    if step.kind == ADD_BEL_NF:
        self.post(Event(trig, None))
        self._advance(i)
    else:
        self.post(Event(trig, i))


def del_belief_step(self: Agent, i: Intention, step: P.Step, s: dict) -> None:
    lit = resolve(sourced(step), s)
    if lit.__class__ is not Literal:
        raise ActionError(f"{term_str(lit)} is not a belief", "body_var_without_value")
    lit = with_source(lit)
    gone = self._remove_matching(lit, s)
    if gone is None:
        self._advance(i)
        return
    trig = self._trigger(step, "-", BELIEF, gone)
    if step.kind == DEL_BEL_NF:
        self.post(Event(trig, None))
        self._advance(i)
    else:
        self.post(Event(trig, i))


def remove_matching(self: Agent, lit: Literal, s: dict) -> Literal | None:
    if lit.ground:
        return self.bb.remove(lit)
    for b in self.bb.candidates(lit.key):
        if b.__class__ is not Literal:
            continue
        mark: list = []
        if unify(lit, b, s, mark):
            exact = resolve(lit, s)
            if not exact.ground:
                exact = Literal(b.functor, b.args, exact.annots, b.neg)
            return self.bb.remove(exact)
        for v in mark:
            del s[v]
    return None


def del_add_step(self: Agent, i: Intention, step: P.Step, s: dict) -> None:
    term = sourced(step)
    lit = resolve(term, s, {})
    if lit.__class__ is not Literal:
        raise ActionError(f"{term_str(lit)} is not a belief", "body_var_without_value")
    if term is step.term:  # else the source is already there
        lit = with_source(lit)
    gone = self.bb.remove_first((lit.functor, len(lit.args), lit.neg), lit.annots)
    if gone is not None:
        cands = self._step_cands(step, "-", BELIEF, gone)
        if cands is None or cands[2] or self._event_waiters or self._custom_event:
            trig = P.Trigger("-", BELIEF, gone)
            trig.cands = cands
            self.post(Event(trig, None))
        # else: an external -b event that no plan handles, which post() would drop
    added = self.bb.add(lit)
    if added is None:
        self._advance(i)
        return
    ev = new_event(self._trigger(step, "+", BELIEF, lit), i)
    if self._has_atomic or self._event_waiters:
        self.post(ev)
    else:
        self.C.events.append(ev)  # what post() does for it


def trigger(self: Agent, step: P.Step, op: str, kind: str, lit: Literal) -> P.Trigger:
    """The trigger of an event posted by ``step``, with its candidate plans (which
    depend only on the step's functor and arity, so they are looked up once)."""
    trig = _new(P.Trigger)  # P.Trigger(op, kind, lit) without a call to __init__
    trig.op = op
    trig.kind = kind
    trig.literal = lit
    pl = self.pl
    rel = step.rel
    if rel is not None and rel[0] is pl and rel[1] == pl.version:
        got = rel[2].get(op)
        if got is not None:
            trig.cands = got
            return trig
        trig.cands = None
    else:
        trig.cands = None
        if step.term.__class__ is not Literal:
            return trig
        rel = step.rel = (pl, pl.version, {})
    pl.candidates(trig)
    rel[2][op] = trig.cands
    return trig


def step_cands(self: Agent, step: P.Step, op: str, kind: str, lit: Literal) -> tuple | None:
    """What :meth:`_trigger` would put in the trigger's ``cands``."""
    pl = self.pl
    rel = step.rel
    if rel is not None and rel[0] is pl and rel[1] == pl.version:
        got = rel[2].get(op)
        if got is not None:
            return got
    return self._trigger(step, op, kind, lit).cands


def test_step(self: Agent, i: Intention, step: P.Step, s: dict) -> None:
    f = step.term
    if holds(self, f, s, []):
        self._advance(i)
        return
    lit = deref(f, s)
    if lit.__class__ is Literal and not lit.functor.startswith("."):
        lit = with_source(resolve(lit, s, {}))
        trig = P.Trigger("+", TEST, lit)
        if self.pl.has_candidate(trig):
            self.post(Event(trig, i))
            return
    self.fail_intention(i, "test_goal_failed", f"Failed to test '{term_str(resolve(f, s))}'")


def if_step(self: Agent, i: Intention, im: IntendedMeans, step: P.Step) -> None:
    s = im.s
    block = None
    chosen = False
    for cond, body in step.blocks:
        if holds(self, cond, s, []):
            block = body
            chosen = True
            break
    if not chosen:
        block = step.state
    rest = im.cur[1]
    im.cur = (None, P.prepend(block, rest)) if block is not None else (None, rest)
    self._advance(i)


def while_step(self: Agent, i: Intention, im: IntendedMeans, step: P.Step) -> None:
    s = im.s
    if step.kind == WHILE:
        backup = dict(s)
        loop = P.Step(WHILE_AGAIN, step.term, step.blocks, step.line, backup)
    else:
        backup = step.state
        s.clear()
        s.update(backup)
        loop = step
    rest = im.cur[1]
    if holds(self, step.term, s, []):
        im.cur = (None, P.prepend(step.blocks[0], (loop, rest)))
    else:
        im.cur = (None, rest)
    self._advance(i)


def for_step(self: Agent, i: Intention, im: IntendedMeans, step: P.Step) -> None:
    s = im.s
    if step.kind == FOR:
        backup = dict(s)
        sols: list[dict] = []
        work = dict(s)
        for _ in solve(self, step.term, work, []):
            sols.append(dict(work))
        state = (iter(sols), backup)
        loop = P.Step(FOR_NEXT, step.term, step.blocks, step.line, state)
    else:
        state = step.state
        loop = step
    it, backup = state
    rest = im.cur[1]
    nxt = next(it, None)
    s.clear()
    if nxt is not None:
        s.update(nxt)
        im.cur = (None, P.prepend(step.blocks[0], (loop, rest)))
    else:
        s.update(backup)
        im.cur = (None, rest)
    self._advance(i)
