"""Arithmetic functions a program defines by its rules: ``{ register_function(...) }``.

Jason lets a program name a predicate as a function: after
``{ register_function("search.h", 2, "h") }`` the expression ``search.h(S, G) + 1`` asks
the query ``h(S, G, R)`` and takes the first answer's ``R`` (a number) as the value,
the way its A* demo computes its heuristic. The directive holds from where it stands to
the end of its file (the reader turns later uses of the name into function calls, as
Jason's does); the agent then evaluates each call on its beliefs and rules
(:meth:`robocog.bdi.agent.Agent.function_value`).

Jason's one-argument form names a Java class; robocog runs no Java, so that form is an
error saying how a Python function is given instead.
"""

from __future__ import annotations

import re

_DIRECTIVE = re.compile(r"\s*register_function\s*\((.*)\)\s*\Z", re.S)
_JAVA_FORM = re.compile(r'\s*"([A-Za-z_][\w.]*)"\s*\Z')
_RULE_FORM = re.compile(r'\s*"([^"\\]*)"\s*,\s*(\d+)\s*,\s*"([a-z][A-Za-z0-9_]*)"\s*\Z')


def function_directive(text: str) -> tuple[str, int, str] | None:
    """``(name, arity, predicate)`` of a ``register_function`` directive's text, None for
    any other directive; a ``ValueError`` (the reader reports it at the directive) for a
    malformed one or for the Java form."""
    m = _DIRECTIVE.match(text)
    if m is None:
        return None
    form = _RULE_FORM.match(m.group(1))
    java = _JAVA_FORM.match(m.group(1))
    if java is not None:
        name = java.group(1)
        raise ValueError(
            f"register_function: the function {name} is the Java class {name}, and robocog "
            f'runs no Java: define it by a rule instead, {{ register_function("{name}", '
            f'ARITY, "predicate") }}, the predicate giving the value as its last argument'
        )
    if form is None:
        raise ValueError(
            'register_function takes a name, an arity and a predicate: { register_function("lib.f", 2, "p") }'
        )
    name, arity, pred = form.group(1), int(form.group(2)), form.group(3)
    if "." not in name or name.startswith("."):
        # Jason's rule for a function name: a library name with a dot, not at its start
        raise ValueError(f"function {name!r}: a function's name has a '.', not at its start")
    if arity > 64:
        raise ValueError(f"function {name!r}: arity {arity} is more than 64")
    return name, arity, pred
