"""The plan library at run time: ``.add_plan``, ``.remove_plan``, ``.relevant_plans``,
``.plan_label``."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi.logic import ActionError
from robocog.bdi.stdlib.base import internal, need_args
from robocog.bdi.terms import Literal, PlanTerm, is_list, iter_list, make_list, term_str
from robocog.bdi.unifier import map_plan, resolve, unify

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("add_plan")
def _add_plan(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "add_plan", 3)
    p = resolve(args[0], s)
    at_end = True
    if len(args) > 2:
        at_end = term_str(resolve(args[2], s)) != "begin"
    texts = list(iter_list(p)) if is_list(p) else [p]
    for t in texts:
        if t.__class__ is PlanTerm:
            # its variables' values in (as Jason's instance of the term), and read
            # again, so that each addition is a plan of its own
            t = repr(map_plan(t, lambda x: resolve(x, s)).plan)
        if t.__class__ is not str:
            raise ActionError(".add_plan expects a plan term or a string")
        from robocog.bdi.parser import ParseError

        try:
            ag.add_plan(t, at_end)
        except ParseError as exc:
            raise ActionError(f".add_plan: {exc}") from exc
    return True


@internal("remove_plan")
def _remove_plan(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "remove_plan", 2)
    label = resolve(args[0], s)
    names = list(iter_list(label)) if is_list(label) else [label]
    for n in names:
        ag.pl.remove(n.functor if n.__class__ is Literal else str(n))
    return True


@internal("relevant_plans")
def _relevant_plans(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.relevant_plans(Trigger, Plans[, Labels])``: the plans whose trigger unifies
    with ``Trigger`` (a plan term ``{+!g}`` or its text), as plan terms, and their labels."""
    from robocog.bdi.messages import plan_terms, trigger_of

    need_args(args, 2, "relevant_plans", 3)
    trigger = trigger_of(resolve(args[0], s))
    if trigger is None:
        raise ActionError('.relevant_plans expects a trigger like {+!g} or "+!g"')
    plans = plan_terms(ag, trigger)
    if not unify(args[1], make_list(plans), s, trail):
        return False
    if len(args) > 2:
        from robocog.bdi.messages import plan_label

        labels = [plan_label(ag, p.plan) for p in plans]
        return unify(args[2], make_list(labels), s, trail)
    return True


@internal("plan_label")
def _plan_label(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.plan_label(Plan, Label)``: the plan term of the plan labelled ``Label``."""

    need_args(args, 2, "plan_label", 2)
    label = resolve(args[1], s)
    name = label.functor if label.__class__ is Literal else str(label).lstrip("@")
    plan = ag.pl.get(name)
    if plan is None:
        return False
    from robocog.bdi.messages import plan_term

    return unify(args[0], plan_term(ag, plan), s, trail)


@internal("relevant_rules")
def _relevant_rules(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.relevant_rules(Head, Rules)``: the rules whose head unifies with ``Head``, as
    rule terms ``{ head :- body }``, in the order the belief base keeps them."""
    from robocog.bdi.terms import RuleTerm

    need_args(args, 2, "relevant_rules")
    pattern = resolve(args[0], s)
    out = []
    for rule in ag.bb.rules():
        if pattern.__class__ is not Literal or unify(pattern, rule.head, {}, []):
            out.append(RuleTerm(rule.head.without_annots(), rule.body))
    return unify(args[1], make_list(out), s, trail)


@internal("list_plans")
def _list_plans(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.list_plans`` (or ``.list_plans({+!g})``): print the plan library, as Jason does,
    in one message whose first line is empty: a ``// plans from`` line per source file,
    then each plan (or each one relevant for the trigger), labelled."""
    from robocog.bdi.messages import trigger_of

    need_args(args, 0, "list_plans", 1)
    plans = list(ag.pl)
    if args:
        from robocog.bdi.messages import plan_terms

        trigger = trigger_of(resolve(args[0], s))
        if trigger is None:
            raise ActionError('.list_plans expects a trigger like {+!g} or "+!g"')
        # the plans relevant for the trigger, each printed as Jason prints a plan term
        for t in plan_terms(ag, trigger):
            ag.print(t.text + ".")
        return True
    lines = [""]
    source = None
    for n, p in enumerate(plans, start=1):
        if p.label is not None and p.label.functor.startswith("kqmlReceived"):
            continue
        if p.source != source:
            source = p.source
            lines.append(f"// plans from {source or 'the program'}")
        text = str(p)
        lines.append(text if p.label is not None else f"@p__{n} {text}")
    ag.print("\n".join(lines))
    return True
