"""Jason's standard internal actions (``.print``, ``.member``, ``.findall``, ...).

Each internal action is ``fn(agent, args, s, trail, ctx)``: ``args`` are the literal's
arguments *before* substitution, ``s`` the substitution (bind outputs in it with
``unify``), and ``ctx`` is ``(intention, intended_means, step)`` when the action runs as
a body formula, ``None`` when it is used inside a context or a condition. It returns
``True``/``False``, a generator yielding once per solution (like ``.member``), or
:data:`~robocog.bdi.agent.SUSPEND` / :data:`~robocog.bdi.agent.DONE` when it has taken
care of its intention itself.
"""

from robocog.bdi.stdlib import (  # noqa: F401 - importing each family registers it
    beliefs,
    communication,
    containers,
    extras,
    goals,
    intentions,
    lists,
    modules,
    output,
    plans,
    strings,
    subplans,
    timing,
    typetests,
)
from robocog.bdi.stdlib.base import LIBRARY, internal

__all__ = ["LIBRARY", "internal"]
