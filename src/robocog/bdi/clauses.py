"""The clauses a program is made of, as the reader hands them over: rules and programs."""

from __future__ import annotations

from dataclasses import dataclass, field

from robocog.bdi import plans as P
from robocog.bdi.terms import Literal, Term


@dataclass
class Rule:
    """``head :- body``: a belief that holds when its body does."""

    head: Literal
    body: Term


@dataclass
class Program:
    """What a source file declares, in program order."""

    beliefs: list = field(default_factory=list)  # Literal or Rule, in order
    goals: list[Literal] = field(default_factory=list)
    plans: list[P.Plan] = field(default_factory=list)
    functions: dict = field(default_factory=dict)  # name -> (name, arity, predicate)
