"""``.include(File)`` and ``.include(File, Ns)``: a program file added to a running agent.

Jason's modules are files included at run time into a namespace: the contract-net
example's initiator starts one protocol per product with
``.include("initiator.asl", T)``, each into its own namespace. The file is read as the
directive ``{ include(File, Ns) }`` reads it (beside the agent's own file first, then
in its source path), and its plans, beliefs (each with its ``+b`` event) and initial
goals are added to the agent, as Jason's ``importComponents`` does. A free variable
``Ns`` is bound to a new namespace, ``ns1``, ``ns2``, ...
"""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robocog.bdi.logic import ActionError
from robocog.bdi.parser import ParseError, parse_program, read_source
from robocog.bdi.stdlib.base import arg_text, bind, internal, need_args
from robocog.bdi.terms import Literal, Var, term_str
from robocog.bdi.unifier import resolve

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent

#: Jason's unique namespace ids for ``.include(F, Var)``
_UNIQUE = itertools.count(1)


@internal("include")
def _include(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "include", 2)
    file = arg_text(args[0], s)
    ns = None
    if len(args) == 2:
        v = resolve(args[1], s)
        if v.__class__ is Var:
            ns = f"ns{next(_UNIQUE)}"
            bind(Literal(ns), v, s, trail)
        elif v.__class__ is Literal and not v.args and not v.annots and not v.neg:
            ns = v.functor
        else:
            raise ActionError(f".include: the namespace {term_str(v)} is not an atom")
    here = Path(ag.file).parent if ag.file else Path(".")
    found = next(
        (p for p in [here / file, *(Path(d) / file for d in ag.asl_path)] if p.is_file()), None
    )
    if found is None:
        raise ActionError(f".include: no file {file!r}")
    try:
        prog = parse_program(read_source(found), str(found), ag.asl_path, 0, ns)
    except ParseError as exc:
        raise ActionError(f".include: {exc}") from exc
    ag.load_program(prog)
    return True
