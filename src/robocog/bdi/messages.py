"""Agents talking: Jason's performatives as message handling, and ``.send``/``.broadcast``.

This is the ProcMsg step of Jason's reasoning cycle and the internal actions that send:
how a message taken from the mailbox changes the receiver (``tell``, ``untell``,
``achieve``, ``unachieve``, ``askOne``, ``askAll``, ``tellHow``), and how a sent message
reaches its receiver, through the agent's system when it has one. It knows agents only
through the attributes the cycle gives them (name, mailbox, mas), so it sits below both
the agent and the system of agents.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.circumstance import Event
from robocog.bdi.logic import ActionError, solve
from robocog.bdi.signals import SUSPEND
from robocog.bdi.terms import (
    FALSE,
    SOURCE_SELF,
    AnnotTail,
    Literal,
    PlanTerm,
    Term,
    Var,
    is_list,
    iter_list,
    make_list,
    sort_annots,
    source,
    term_str,
)
from robocog.bdi.unifier import resolve, unify

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent

_msg_ids = itertools.count(1)


@dataclass(slots=True)
class Message:
    """A KQML-like message between agents."""

    sender: str
    receiver: str
    performative: str
    content: Term
    msg_id: str
    in_reply_to: str | None = None


def _receivers(ag: Agent, to: Term) -> list[str]:
    if to.__class__ is Literal:
        # one receiver, the usual case; ``self`` is the sender itself, as in Jason
        return [ag.name if to.functor == "self" else to.functor]
    names = list(iter_list(to)) if is_list(to) else [to]
    out = []
    for n in names:
        if n.__class__ is Literal:
            out.append(ag.name if n.functor == "self" else n.functor)
        elif n.__class__ is str:
            out.append(n)
        else:
            raise ActionError(f".send: bad receiver {term_str(n)}")
    return out


def _deliver(ag: Agent, msg: Message) -> None:
    arch = ag.arch
    if arch is not None:
        arch.send(msg, lambda m: _deliver_now(ag, m))
        return
    _deliver_now(ag, msg)


def _deliver_now(ag: Agent, msg: Message) -> None:
    if ag.mas is not None:
        ag.mas.deliver(msg)
    elif msg.receiver == ag.name:
        ag.mailbox.append(msg)
    else:
        raise ActionError(f"no agent named {msg.receiver}")


def send(ag: Agent, args: tuple, s: dict, ctx: Any) -> Any:
    """``.send(To, Performative, Content[, Answer[, Timeout]])``."""
    to = resolve(args[0], s)
    perf = resolve(args[1], s)
    if perf.__class__ is not Literal:
        raise ActionError(".send: the performative must be an atom")
    perf_name = perf.functor
    content = resolve(args[2], s, {})
    msg_id = f"mid{next(_msg_ids)}"
    if len(args) >= 4 and perf_name in ("askOne", "askAll", "askHow"):
        if ctx is None:
            raise ActionError(".send with an answer can only be used in a plan body")
        names = _receivers(ag, to)
        if len(names) != 1:
            raise ActionError(".send: an ask with an answer needs one receiver")
        i = ctx[0]
        ag._asks[msg_id] = (i, args[3])
        ag.C.pending[i.id] = (i, "ask")
        _deliver(ag, Message(ag.name, names[0], perf_name, content, msg_id))
        return SUSPEND
    if len(args) >= 4 and perf_name in ("tell", "untell"):
        reply_to = resolve(args[3], s)
        reply_to = reply_to if reply_to.__class__ is str else term_str(reply_to)
        for name in _receivers(ag, to):
            _deliver(ag, Message(ag.name, name, perf_name, content, msg_id, reply_to))
        return True
    for name in _receivers(ag, to):
        _deliver(ag, Message(ag.name, name, perf_name, content, msg_id))
    return True


def broadcast(ag: Agent, perf: Term, content: Term) -> None:
    """Send to every other agent of the system."""
    if perf.__class__ is not Literal:
        raise ActionError(".broadcast: the performative must be an atom")
    if ag.mas is None:
        return
    for name in ag.mas.agents:
        if name != ag.name:
            ag.mas.deliver(Message(ag.name, name, perf.functor, content, f"mid{next(_msg_ids)}"))


def _with_sender(t: Term, sender: str) -> Term:
    """``t`` as received from ``sender`` (Jason's ``.add_nested_source``): its sources
    become annotations of ``source(sender)``, so ``p[source(a)]`` told by b is
    ``p[source(b)[source(a)]]``."""
    if t.__class__ is Literal:
        if not t.annots:  # the usual case: one annotation, nothing to sort or merge
            return Literal.make(t.functor, t.args, (source(sender),), t.neg, t.ground)
        olds = [a for a in t.annots if a.__class__ is Literal and a.functor == "source"]
        if not olds:
            return t.add_annots((source(sender),))
        others = [a for a in t.annots if not (a.__class__ is Literal and a.functor == "source")]
        nested = Literal("source", (Literal(sender),), sort_annots(olds))
        return t.with_annots([*others, nested])
    if t.__class__ is PlanTerm and t.text.startswith("@") and "[source(self)" in t.text:
        # a plan sent by another agent: its label says it comes from the sender
        head, sep, rest = t.text.partition("[source(self)")
        if " " not in head:
            return PlanTerm(t.plan, f"{head}[source({sender}){rest}")
    return t


#: Jason's default plan for an askOne whose answer the belief base lacks: the test goal
#: may be achieved by the receiver's ``+?`` plans; when it fails the asker is told no
ASK_BY_TEST_GOAL = (
    "@kqmlReceivedAskOne1 +!kqml_received(S, askOne, C, M) <- ?C; .send(S, tell, C, M).",
    "@kqmlReceivedAskOne1f -!kqml_received(S, askOne, C, M) <- .send(S, untell, C, M).",
)


def _kqml_literal(msg: Message) -> Literal:
    return Literal(
        "kqml_received",
        (Literal(msg.sender), Literal(msg.performative), msg.content, Literal(msg.msg_id)),
    )


#: any ``+!kqml_received/4`` event, to ask a plan library whether it has such plans
_KQML_ANY = P.Trigger(
    "+", P.ACHIEVE, Literal("kqml_received", (Var("S"), Var("P"), Var("C"), Var("M")))
)


def _handled_by_a_plan(ag: Agent, msg: Message) -> bool:
    """Post ``+!kqml_received(Sender, Performative, Content, MsgId)`` when a plan of the
    agent's own takes that message (it overrides Jason's default handling, as the
    program's plans come before the default ones); True if posted."""
    if not ag.pl.has_candidate(_KQML_ANY):
        return False  # the program has no such plan (the usual case): nothing to build
    trigger = P.Trigger("+", P.ACHIEVE, _kqml_literal(msg))
    plans = ag.pl.candidates(trigger)
    if not plans:
        return False
    for plan in plans:
        if plan.label is not None and plan.label.functor.startswith("kqmlReceived"):
            continue
        if unify(plan.trigger.literal, trigger.literal, {}, []):
            ag.post(Event(trigger, None))
            return True
    return False


def _ask_by_test_goal(ag: Agent, msg: Message) -> bool:
    """An askOne the belief base cannot answer goes to the receiver's ``+?`` plans (as
    Jason's default plan does it, by a test goal); True if it went."""
    if msg.content.__class__ is not Literal:
        return False
    if not ag.pl.has_candidate(P.Trigger("+", P.TEST, msg.content)):
        return False
    if ag.pl.get("kqmlReceivedAskOne1") is None:
        for text in ASK_BY_TEST_GOAL:
            ag.add_plan(text)
    ag.post(Event(P.Trigger("+", P.ACHIEVE, _kqml_literal(msg)), None))
    return True


def trigger_of(content: Term) -> P.Trigger | None:
    """The trigger an askHow or ``.relevant_plans`` asks about: a plan term ``{+!g}``
    or its text ``"+!g"``."""
    if content.__class__ is PlanTerm:
        return content.plan.trigger
    if content.__class__ is str:
        from robocog.bdi.parser import ParseError, parse_plan

        try:
            return parse_plan(content).trigger
        except (ParseError, ValueError):
            return None
    return None


def plan_terms(ag: Agent, trigger: P.Trigger) -> list[PlanTerm]:
    """The agent's plans relevant for ``trigger`` as plan terms (not the default
    message-handling plans). A trigger without a source gets ``source(_)``, as in
    Jason, so that ``{+!g(_)}`` finds ``+!g(X)[source(A)]``."""
    lit = trigger.literal
    if lit.__class__ is Literal and not any(
        a.__class__ is Literal and a.functor == "source" for a in lit.annots
    ):
        lit = lit.add_annots((Literal("source", (Var("_"),)),))
        trigger = P.Trigger(trigger.op, trigger.kind, lit)
    return [
        plan_term(ag, p)
        for p in ag.relevant_plans(trigger)
        if p.label is None or not p.label.functor.startswith("kqmlReceived")
    ]


_fresh_names = itertools.count(100)
_VAR_OR_STRING = re.compile(r'"(?:\\.|[^"\\])*"|(?<![\w.])[A-Z_][A-Za-z0-9_]*')


def plan_label(ag: Agent, plan: P.Plan) -> Literal:
    """A plan's label as Jason gives it: ``p__N`` when the program gave none, annotated
    with where the plan comes from (``source(self)``, ``url("file:a.asl")``)."""
    label = plan.label
    if label is None:
        n = 1 + sum(1 for p in ag.pl if p.label is None and p.order < plan.order)
        label = Literal(f"p__{n}")
    if not any(a.__class__ is Literal and a.functor == "source" for a in label.annots):
        url = ag.url if not plan.source or plan.source == ag.file else f"file:{plan.source}"
        extra = [SOURCE_SELF] + ([Literal("url", (url,))] if url else [])
        label = Literal(label.functor, label.args, (*label.annots, *extra), label.neg)
    return label


def plan_term(ag: Agent, plan: P.Plan) -> PlanTerm:
    """A plan of the library as a term, as Jason gives it: labelled (``@p__N`` when
    the program gave no label), the label annotated with where the plan comes from
    (``source(self)``, ``url("file:a.asl")``), and its variables fresh ones (``_N``)."""
    label = plan_label(ag, plan)
    body = str(plan).rstrip(".")
    if plan.label is not None:
        body = body.split(" ", 1)[1]  # the label, printed again below
    names: dict[str, str] = {}

    def fresh(m: re.Match) -> str:
        tok = m.group(0)
        if tok.startswith('"'):
            return tok
        if tok == "_":
            return f"_{next(_fresh_names)}"  # each ``_`` a variable of its own
        if tok not in names:
            names[tok] = f"_{next(_fresh_names)}"
        return names[tok]

    return PlanTerm(plan, f"@{term_str(label)} " + _VAR_OR_STRING.sub(fresh, body), label=label)


def handle_message(ag: Agent, msg: Message) -> None:
    """What a received message does (Jason's default ``kqmlPlans``)."""
    sender = "self" if msg.sender == ag.name else msg.sender
    if msg.in_reply_to is None and _handled_by_a_plan(ag, msg):
        return
    if msg.in_reply_to is not None and msg.in_reply_to in ag._asks:
        i, answer = ag._asks.pop(msg.in_reply_to)
        if ag.C.pending.pop(i.id, None) is None or i.dropped:
            return
        content = msg.content
        if msg.performative == "untell":
            content = FALSE
        elif is_list(content):
            content = make_list([_with_sender(x, msg.sender) for x in iter_list(content)])
        else:
            content = _with_sender(content, msg.sender)
        if unify(answer, content, i.top().s, []):
            ag._advance(i)
        else:
            ag.fail_intention(i, "ask_failed", f"reply '{term_str(content)}' does not unify")
        return
    perf = msg.performative
    content = msg.content
    if perf == "tell":
        items = list(iter_list(content)) if is_list(content) else [content]
        if len(items) > 1:
            # Jason adds a told list one belief per reasoning cycle (its default plans
            # recurse over the list), so each belief's event sees only those before it
            rest = Message(msg.sender, msg.receiver, perf, make_list(items[1:]), msg.msg_id)
            ag.mailbox.append(rest)
        for c in items[:1]:
            if c.__class__ is Literal:
                lit = _with_sender(c, sender)
                if ag.bb.add(lit) is not None:
                    ag.post(Event(P.Trigger("+", P.BELIEF, lit), None))
    elif perf == "untell":
        for c in list(iter_list(content)) if is_list(content) else [content]:
            if c.__class__ is Literal:
                gone = ag.bb.remove(c.add_annots((source(sender),)))
                if gone is not None:
                    ag.post(Event(P.Trigger("-", P.BELIEF, gone), None))
    elif perf == "achieve":
        if content.__class__ is Literal:
            ag.post(Event(P.Trigger("+", P.ACHIEVE, _with_sender(content, sender)), None))
    elif perf == "signal":
        # an event +content[source(sender)], no belief added (Jason's signal)
        if content.__class__ is Literal:
            ag.post(Event(P.Trigger("+", P.BELIEF, _with_sender(content, sender)), None))
    elif perf == "unachieve":
        if content.__class__ is Literal:
            ag.drop_goal(content, "drop")
    elif perf in ("askOne", "askAll"):
        answers = []
        s: dict = {}
        # askAll answers with each belief's annotations but source(self), as Jason's
        # askAll plan does; askOne with the content as asked
        pattern = content
        tail = None
        if perf == "askAll" and content.__class__ is Literal:
            tail = Var("_LA")
            pattern = Literal(
                content.functor, content.args, (*content.annots, AnnotTail(tail)), content.neg
            )
        try:
            for _ in solve(ag, pattern, s, []):
                got = resolve(content, s, {})
                if tail is not None and got.__class__ is Literal:
                    extra = [a for a in iter_list(resolve(tail, s)) if a != SOURCE_SELF]
                    got = got.add_annots(extra) if extra else got
                answers.append(got)
                if perf == "askOne":
                    break
        except ActionError:
            answers = []
        if perf == "askOne":
            if answers:
                reply = Message(ag.name, msg.sender, "tell", answers[0], f"mid{next(_msg_ids)}")
            elif _ask_by_test_goal(ag, msg):
                return
            else:
                reply = Message(ag.name, msg.sender, "untell", content, f"mid{next(_msg_ids)}")
        else:
            reply = Message(ag.name, msg.sender, "tell", make_list(answers), f"mid{next(_msg_ids)}")
        reply.in_reply_to = msg.msg_id
        _reply(ag, reply)
    elif perf == "askHow":
        trigger = trigger_of(content)
        if trigger is None:
            ag.warn(f"askHow from {msg.sender}: not a trigger: {term_str(content)}")
            return
        plans = plan_terms(ag, trigger)
        reply = Message(ag.name, msg.sender, "tellHow", make_list(plans), f"mid{next(_msg_ids)}")
        reply.in_reply_to = msg.msg_id
        _reply(ag, reply)
    elif perf == "untellHow":
        for label in list(iter_list(content)) if is_list(content) else [content]:
            name = label.functor if label.__class__ is Literal else str(label).lstrip("@")
            plan = ag.pl.get(name)
            # only a plan the sender told (its label says source(sender)), as in Jason
            if plan is not None and source(msg.sender) in plan.label.annots:
                ag.pl.remove(name)
    elif perf == "tellHow":
        texts = list(iter_list(content)) if is_list(content) else [content]
        for t in texts:
            if t.__class__ is PlanTerm:
                t = _with_sender(t, msg.sender).text
            if t.__class__ is str:
                try:
                    ag.add_plan(t)
                except ValueError as exc:
                    ag.warn(f"tellHow from {msg.sender}: {exc}")
    else:
        ag.warn(f"unknown performative {perf} from {msg.sender}")


def _reply(ag: Agent, reply: Message) -> None:
    try:
        _deliver(ag, reply)
    except ActionError as exc:
        ag.warn(str(exc))
