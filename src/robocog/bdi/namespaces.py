"""Jason's namespaces: what ``{ begin namespace(ns) }`` and ``include(f, ns)`` do to a
program's clauses.

A namespace is kept in a literal's functor (``ns::b``; :data:`~robocog.bdi.terms.NS_SEP`),
so that beliefs, goals and triggers of different namespaces never meet in the belief
base or the plan library. Inside a block or an included file, a clause's beliefs, goals
and triggers move to the namespace; internal actions, environment actions and the
arguments of literals stay where they are, as in Jason.
"""

from __future__ import annotations

import re
from typing import Any

from robocog.bdi import plans as P
from robocog.bdi.clauses import Rule
from robocog.bdi.terms import NS_SEP, And, Literal, Not, Or, Term

#: Jason's default namespace, and what joins a namespace to a functor
DEFAULT_NS = "default"
BEGIN_NS = re.compile(r"\s*begin\s+namespace\s*\(\s*(\w+)\s*(?:,\s*(local|global)\s*)?\)\s*\Z")
END_NS = re.compile(r"\s*end\s*\Z")
#: ``{ namespace(ns, local) }``: a namespace declared (local to the file) before its use
DECLARE_NS = re.compile(r"\s*namespace\s*\(\s*(\w+)\s*,\s*(local|global)\s*\)\s*\Z")


def in_namespace(item: Any, ns: str) -> Any:
    """``item`` (a belief, rule, goal, or a plan's (trigger, context, body)) as written
    inside ``{ begin namespace(ns) }``: its beliefs, goals and triggers, and the
    literals its contexts, rule bodies and belief and goal formulas consult, in ``ns``;
    internal actions, environment actions and arguments are left as they are; a
    literal with an explicit namespace keeps it (``default::b`` is plain ``b``)."""
    if isinstance(item, tuple):
        trigger, context, body = item
        if trigger is not None and trigger.literal.__class__ is Literal:
            trigger = P.Trigger(trigger.op, trigger.kind, _ns_lit(trigger.literal, ns))
        return trigger, _ns_formula(context, ns), _ns_chain(body, ns)
    if isinstance(item, Rule):
        return Rule(_ns_lit(item.head, ns), _ns_formula(item.body, ns))
    return _ns_lit(item, ns)


def _ns_lit(t: Term, ns: str) -> Term:
    if t.__class__ is not Literal or t.functor.startswith("."):
        return t
    f = t.functor
    if NS_SEP in f:
        if not f.startswith(DEFAULT_NS + NS_SEP):
            return t
        f = f[len(DEFAULT_NS) + len(NS_SEP) :]
    else:
        f = f"{ns}{NS_SEP}{f}"
    return Literal(f, t.args, t.annots, t.neg)


def _ns_formula(t: Term, ns: str) -> Term:
    c = t.__class__
    if c is Literal:
        if t.functor in ("true", "false") and not t.args:
            return t
        return _ns_lit(t, ns)
    if c is And or c is Or:
        return c(_ns_formula(t.left, ns), _ns_formula(t.right, ns))
    if c is Not:
        return Not(_ns_formula(t.arg, ns))
    return t


#: the body formulas whose literal is a belief or a goal (namespaced in a block)
_NS_STEPS = frozenset(
    {
        P.ACHIEVE_STEP,
        P.ACHIEVE_NF,
        P.ADD_BEL,
        P.ADD_BEL_NF,
        P.ADD_BEL_END,
        P.DEL_BEL,
        P.DEL_BEL_NF,
        P.DEL_ADD_BEL,
    }
)


def _ns_chain(chain: P.Chain, ns: str) -> P.Chain:
    steps = []
    while chain is not None:
        st = chain[0]
        if st.kind in _NS_STEPS:
            st = P.Step(st.kind, _ns_lit(st.term, ns), st.blocks, st.line, st.state)
        elif st.kind == P.TEST_STEP:
            st = P.Step(st.kind, _ns_formula(st.term, ns), st.blocks, st.line, st.state)
        elif st.kind == P.IF:
            # blocks: (condition, chain) per branch; state: the else chain
            blocks = tuple((_ns_formula(c, ns), _ns_chain(b, ns)) for c, b in st.blocks)
            st = P.Step(st.kind, _ns_formula(st.term, ns), blocks, st.line, _ns_chain(st.state, ns))
        elif st.kind in (P.WHILE, P.FOR):
            blocks = tuple(_ns_chain(b, ns) for b in st.blocks)  # the body
            st = P.Step(st.kind, _ns_formula(st.term, ns), blocks, st.line, st.state)
        elif st.kind == P.FORK:
            st = P.Step(st.kind, st.term, tuple(_ns_chain(b, ns) for b in st.blocks), st.line)
        steps.append(st)
        chain = chain[1]
    return P.chain(steps)


def plan_in(plan: P.Plan, ns: str) -> P.Plan:
    """``plan`` as written inside a block of ``ns``."""
    trigger, context, body = in_namespace((plan.trigger, plan.context, plan.body), ns)
    out = P.Plan(trigger, context, body, plan.label, plan.source, plan.line)
    out.code_line = plan.code_line
    return out
