"""The agent whose reasoning cycle is running, for what term evaluation cannot be handed.

Jason's arithmetic function ``.count(Query)`` counts the solutions of a query over the
beliefs, deep inside the evaluation of an expression, where no agent is passed along.
The cycle names the agent it runs here before each step, and evaluation asks that agent
(through :meth:`robocog.bdi.agent.Agent.count_solutions`), so the unifier needs neither
the agent's module nor the solver's. A context variable keeps agents stepped in
different threads apart.
"""

from __future__ import annotations

from contextvars import ContextVar
from typing import Any

#: the agent whose step is running in this thread (None outside a step)
running: ContextVar[Any] = ContextVar("robocog_bdi_running_agent", default=None)

_get = running.get
_set = running.set


def enter(agent: Any) -> None:
    """Name ``agent`` as the one running. Setting a context variable builds a new
    context each time, several times the cost of reading it, and a cycle mostly follows
    a cycle of the same agent: so it is set only when another agent ran last."""
    if _get() is not agent:
        _set(agent)
