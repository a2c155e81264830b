"""The third step's machinery: environment actions and their feedback, and moving an
intention on once a formula is done (popping finished intended means, giving results back).

These functions are the :class:`~robocog.bdi.agent.Agent`'s methods (bound there under
the names they had, a leading underscore for the internal ones), kept here by the step
of the cycle they belong to.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi.actions import ActionHandle, to_python
from robocog.bdi.circumstance import (
    Intention,
)
from robocog.bdi.formulas import (
    NO_ENVIRONMENT,
    awaits,
    is_atomic,
    propagate,
    unifies_under,
)
from robocog.bdi.logic import ActionError
from robocog.bdi.plans import (
    BELIEF,
)
from robocog.bdi.terms import (
    Literal,
)
from robocog.bdi.unifier import (
    deref,
    resolve,
    unify,
)

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


def process_feedback(self: Agent) -> None:
    item = None
    if self._feedback:
        item = self._feedback.popleft()
    else:
        for k, (h, i) in enumerate(self._waiting_actions):
            if h.done:
                del self._waiting_actions[k]
                item = (i, bool(h.ok), h.reason, h.action)
                break
    if item is None:
        return
    i, ok, reason, _action = item
    if self.C.pending.pop(i.id, None) is None or i.dropped:
        return
    if ok:
        self._advance(i)  # the action succeeded: on to the next formula
    else:
        noenv = (Literal("noenv"),) if reason == NO_ENVIRONMENT else ()
        self.fail_intention(i, "action_failed", reason, noenv)


def execute_action(self: Agent, action: Literal) -> Any:
    """Run an environment action (through the agent's architecture, if it has one);
    override to plug in an environment object."""
    arch = self.arch
    if arch is not None:
        return arch.act(action, lambda a: _execute(self, a))
    return _execute(self, action)


def _execute(self: Agent, action: Literal) -> Any:
    entry = self._actions.get(action.functor)
    if entry is None:
        if self.mas is not None and self.mas.environment is not None:
            return self.mas.environment(self.name, action)
        if not self._actions:
            raise ActionError(NO_ENVIRONMENT)  # Jason's words, when there is none
        raise ActionError(f"no environment action {action.functor}/{len(action.args)}")
    fn, raw = entry
    if raw:
        return fn(*action.args)
    return fn(*map(to_python, action.args))


def act(self: Agent, i: Intention, lit: Literal) -> None:
    try:
        result = self.execute_action(lit)
    except Exception as exc:  # noqa: BLE001 - any failure of user code fails the action
        self.C.pending[i.id] = (i, "action")
        self._feedback.append((i, False, str(exc), lit))
        return
    self.C.pending[i.id] = (i, "action")
    if result is True or result is None:
        self._feedback.append((i, True, "", lit))
    elif isinstance(result, ActionHandle):
        result.action = lit
        self._waiting_actions.append((result, i))
    else:
        self._feedback.append((i, result is not False, "", lit))


def requeue(self: Agent, i: Intention) -> None:
    """Put ``i`` back among the running intentions (Jason's ``addRunningIntention``)."""
    if self._has_atomic and is_atomic(i):
        self.C.atomic_intention = i
    else:
        self.C.running.append(i)


def advance(self: Agent, i: Intention) -> None:
    """Jason's ``removeActionReQueue`` followed by ``ClrInt``."""
    stack = i.stack
    im = stack[-1]
    cur = im.cur
    if cur is not None:
        cur = im.cur = cur[1]
    if cur is None:
        self._clear(i)
        if not stack:
            return
    if self._has_atomic:
        self._requeue(i)
    else:
        self.C.running.append(i)


def clear(self: Agent, i: Intention) -> None:
    """Pop finished intended means, giving their result back to the caller."""
    stack = i.stack
    while stack:
        top = stack[-1]
        if top.cur is not None:
            return
        stack.pop()
        trig = top.trigger
        if trig.op == "-" and trig.kind != BELIEF and stack:
            # a failure plan finished: drop everything down to the failed goal
            goal = resolve(trig.literal, top.s)
            im = stack[-1]
            if not awaits(im, goal):
                im = stack.pop()
            while stack and not (
                (im.trigger.kind != BELIEF and unifies_under(im.trigger.literal, goal, im.s))
                or awaits(im, goal)
            ):
                im = stack.pop()
            if stack:
                caller = stack[-1]
                if caller.cur is not None:
                    unify(caller.cur[0].term, goal, caller.s, [])
                    caller.cur = caller.cur[1]
            continue
        if stack:
            caller = stack[-1]
            if caller.cur is not None:
                ret = top.ret
                lit = trig.literal
                if ret is None and lit.__class__ is Literal and lit.ground:
                    # the goal was sent without variables: nothing comes back
                    caller.cur = caller.cur[1]
                    continue
                if ret is None:
                    val = resolve(lit, top.s)
                elif ret[0] == "fixed":
                    val = ret[1]
                else:
                    val = propagate(resolve(lit, top.s), ret[1])
                # through a variable too (``?C`` with C bound to a literal)
                term = deref(caller.cur[0].term, caller.s)
                if term.__class__ is Literal and not term.ground:
                    unify(term, val, caller.s, [])
                caller.cur = caller.cur[1]
