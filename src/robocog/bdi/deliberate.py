"""The second step of the cycle: for the selected event, the relevant plans (by trigger), the
applicable ones (by context), and the intended means pushed on its intention (with the
tail-recursion optimisation); an event no plan takes is a failure or is dropped.

These functions are the :class:`~robocog.bdi.agent.Agent`'s methods (bound there under
the names they had, a leading underscore for the internal ones), kept here by the step
of the cycle they belong to.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.circumstance import (
    Event,
    IntendedMeans,
    Intention,
    new_im,
)
from robocog.bdi.er import er_deliberate
from robocog.bdi.formulas import (
    propagate,
)
from robocog.bdi.plans import (
    ACHIEVE,
    BELIEF,
)
from robocog.bdi.terms import (
    Literal,
    Var,
    is_ground,
    term_str,
)
from robocog.bdi.unifier import (
    resolve,
    unify,
)

#: a (plan, substitution) pair, as Jason calls an applicable plan
Option = tuple

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


def relevant_plans(self: Agent, trigger: P.Trigger) -> list[P.Plan]:
    """Plans whose trigger unifies with ``trigger``, in program order."""
    out = []
    for plan in self.pl.candidates(trigger):
        if unify(plan.trigger.literal, trigger.literal, {}, []):
            out.append(plan)
    return out


def applicable_options(self: Agent, ev: Event) -> list[Option]:
    """Every (plan, substitution) whose trigger unifies and whose context holds."""
    out = []
    for plan in self.pl.candidates(ev.trigger):
        s: dict = {}
        trail: list = []
        if unify(plan.trigger.literal, ev.trigger.literal, s, trail):
            if plan.test is None or self._context(plan, s, trail):
                out.append((plan, s))
    return out


def context(self: Agent, plan: P.Plan, s: dict, trail: list) -> bool:
    try:
        return plan.test(self, s, trail)
    except Exception as exc:  # noqa: BLE001 - a bad context is just false
        self.warn(f"error in the context of {plan.trigger!r}: {exc}")
        return False


def deliberate(self: Agent, ev: Event) -> bool:
    """Handle one event; False when it was discarded without using the cycle."""
    if self.has_subplans and er_deliberate(self, ev):
        return True
    trig = ev.trigger
    pl = self.pl
    got = trig.cands
    if got is not None and got[0] is pl and got[1] == pl.version:
        cands = got[2]
    else:
        cands = pl.candidates(trig)
    if not cands:
        i = ev.intention
        if trig.kind == BELIEF:
            if i is None:
                return False
            # a belief change of this intention that no plan handles: carry on
            if not i.dropped:
                self._advance(i)
            return True
        self._no_plan(ev, "relevant")
        return True
    if self._custom_option or self.bb.has_rule("select__option", 4):
        if self._custom_option:
            option = self.select_option(self.applicable_options(ev))
        else:
            option = _option_by_rule(self, ev)
        if option is None:
            return self._no_option(ev)
        plan, s = option
    else:
        lit = trig.literal
        simple = lit.__class__ is Literal and not lit.neg
        trail: list = []  # emptied after each plan that is not applicable
        for plan in cands:
            bind = plan.bind
            if bind >= 0 and simple:
                # the candidates have the event's arity: the parameters take its args
                if bind == 1:
                    s: dict = {plan.params[0]: lit.args[0]}
                elif bind == 0:
                    s = {}
                else:
                    s = dict(zip(plan.params, lit.args))  # noqa: B905
            elif bind == -2 and simple and lit.ground:
                # a ground trigger without annotations against a ground event of
                # the same predicate: unification is equality of the arguments
                if plan.trigger.literal.args != lit.args:
                    continue
                s = {}
            else:
                s = {}
                if not unify(plan.trigger.literal, lit, s, trail):
                    trail.clear()
                    continue
            test = plan.test
            if test is None:
                break
            try:
                if test(self, s, trail):
                    break
            except Exception as exc:  # noqa: BLE001 - a bad context is just false
                self.warn(f"error in the context of {plan.trigger!r}: {exc}")
            trail.clear()
        else:
            return self._no_option(ev)
    im = new_im(plan, trig, s, plan.body)
    if plan.subplans is not None or plan.goal_cond is not None:
        im.base = dict(s)
    i = ev.intention
    if trig.kind == ACHIEVE and trig.literal.__class__ is Literal and trig.literal.annots:
        deadline = _hard_deadline(trig.literal)
        if deadline is not None:
            if i is None:
                i = ev.intention = Intention()
                i.stack.append(im)
                self._requeue(i)
                self._add_deadline(deadline, i, im)
                return True
            self._add_deadline(deadline, i, im)
    if i is None:
        i = Intention()
        i.stack.append(im)
        self._requeue(i)
        return True
    if i.dropped:
        return True
    stack = i.stack
    top = stack[-1] if stack else None
    cur = top.cur if top is not None else None
    if cur is not None and cur[1] is None and self.tail_recursion:
        if trig.op == "+" and trig.kind != BELIEF:
            t1 = top.trigger
            l1 = t1.literal
            l2 = trig.literal
            if (
                t1.op == "+"
                and t1.kind != BELIEF
                and l1.__class__ is Literal
                and l2.__class__ is Literal
                and l1.functor == l2.functor
                and len(l1.args) == len(l2.args)
            ):
                stack.pop()
                ret = top.ret
                im.ret = ret if ret is not None and ret[0] == "fixed" else self._tro_ret(top)
    stack.append(im)
    if self._has_atomic:
        self._requeue(i)
    else:
        self.C.running.append(i)
    return True


def no_option(self: Agent, ev: Event) -> bool:
    """No applicable plan for ``ev``: False when it is discarded without using the
    cycle (an external belief change), else the failure of its goal."""
    if ev.intention is None and ev.trigger.kind == BELIEF:
        return False
    self._no_plan(ev, "applicable")
    return True


def tro_ret(self: Agent, top: IntendedMeans) -> Any:
    """What the intended means replacing ``top`` must give back to ``top``'s caller."""
    ret = top.ret
    if ret is not None and ret[0] == "fixed":
        return ret
    val = top.trigger.literal
    if not val.ground:
        val = resolve(val, top.s)
    if is_ground(val):
        if ret is not None:
            val = propagate(val, ret[1])
        return ("fixed", val)
    entry = (top.cur[0].term, top.s, top.trigger.literal)
    return ("chain", (entry, ret[1] if ret is not None else None))


def no_plan(self: Agent, ev: Event, what: str) -> None:
    trig = ev.trigger
    if trig.op == "+" and trig.kind != BELIEF:
        msg = f"Found a goal for which there is no {what} plan: {trig!r}"
        fail_ev = self._failure_event(ev.intention, trig, in_stack=False)
        if fail_ev is not None:
            self._annotate_failure(fail_ev, f"no_{what}", msg, trig.literal, 0)
            self.post(fail_ev)
        else:
            self.warn(msg)
            if ev.intention is not None:
                self._drop(ev.intention)
    elif ev.intention is not None:
        # a belief change of this intention that no plan handles: carry on
        if not ev.intention.dropped:
            self._advance(ev.intention)
    elif trig.kind != BELIEF:
        self.warn(f"no {what} plan for {trig!r}")


def _hard_deadline(lit: Literal) -> float | None:
    """The milliseconds of a goal's ``hard_deadline(MS)`` annotation, if it has one."""
    for a in lit.annots:
        if (
            a.__class__ is Literal
            and a.functor == "hard_deadline"
            and len(a.args) == 1
            and isinstance(a.args[0], (int, float))
        ):
            return float(a.args[0])
    return None


def _option_by_rule(self: Agent, ev: Event) -> Option | None:
    """Jason's option selection by a rule: the first applicable option (each solution
    of each relevant plan's context, in order) for which ``select__option(E, I, P, U)``
    holds, where E is the event, I the intention (-1 for none), P the plan with the
    option's bindings and U the bindings."""
    from robocog.bdi.logic import solve
    from robocog.bdi.messages import plan_label
    from robocog.bdi.terms import PlanTerm, make_list

    trig = ev.trigger
    event = PlanTerm(P.Plan(trig, None, None), repr(trig), bare=True)
    intention = -1 if ev.intention is None else ev.intention.id
    for plan in self.pl.candidates(trig):
        s0: dict = {}
        trail: list = []
        if not unify(plan.trigger.literal, trig.literal, s0, trail):
            continue
        solutions = [dict(s0)] if plan.context is None else []
        if plan.context is not None:
            for _ in solve(self, plan.cond, s0, trail):
                solutions.append(dict(s0))
        for s in solutions:
            ctx = f" : {term_str(resolve(plan.context, s))}" if plan.context is not None else ""
            steps = "; ".join(
                repr(P.Step(st.kind, resolve(st.term, s), st.blocks, st.line, st.state))
                if not st.blocks and st.term is not None and not isinstance(st.term, str)
                else repr(st)
                for st in P.chain_steps(plan.body)
            )
            label = plan_label(self, plan)
            head = f"@{term_str(label)} {trig.op}{trig.kind}"
            lit = term_str(resolve(plan.trigger.literal, s))
            text = f"{head}{lit}{ctx}" + (f" <- {steps}." if steps else ".")
            bindings = make_list(
                [Literal("map", (v, resolve(v, s))) for v in s if v.__class__ is Var]
            )
            query = Literal(
                "select__option", (event, intention, PlanTerm(plan, text, True, label), bindings)
            )
            for _ in solve(self, query, {}, []):
                return plan, s
    return None
