"""A typed hypergraph store in the manner of OpenCog's AtomSpace: atoms, truth
values and Values, Atomese s-expressions, a pattern matcher and SQLite persistence.

Start with :class:`AtomSpace`, :func:`parse` / ``space.load_atomese`` and
``space.execute``; docs/atomspace.md has the tour.
"""

from robocog.atomspace.atomese import (
    AtomeseError,
    dump,
    load,
    parse,
    read_atom,
    write,
    write_pretty,
)
from robocog.atomspace.atoms import Atom, Link, Node, bulk, constructor, has_variables, variables_of
from robocog.atomspace.execute import GroundedError, evaluate, execute, instantiate
from robocog.atomspace.flow import evaluate_any, execute_any
from robocog.atomspace.matcher import Pattern, PatternError, compile_pattern, query, substitute
from robocog.atomspace.space import TV_KEY, AtomSpace, register_function
from robocog.atomspace.types import declare_type, is_a, subtypes
from robocog.atomspace.values import (
    DEFAULT_TV,
    FALSE_TV,
    TRUE_TV,
    FloatValue,
    LinkValue,
    QueueValue,
    StringValue,
    TruthValue,
    Value,
    stv,
)

__all__ = [
    "DEFAULT_TV",
    "FALSE_TV",
    "TRUE_TV",
    "TV_KEY",
    "Atom",
    "AtomSpace",
    "AtomeseError",
    "FloatValue",
    "GroundedError",
    "Link",
    "LinkValue",
    "Node",
    "Pattern",
    "PatternError",
    "QueueValue",
    "StringValue",
    "TruthValue",
    "Value",
    "bulk",
    "compile_pattern",
    "constructor",
    "declare_type",
    "dump",
    "evaluate",
    "evaluate_any",
    "execute",
    "execute_any",
    "has_variables",
    "instantiate",
    "is_a",
    "load",
    "parse",
    "query",
    "read_atom",
    "register_function",
    "stv",
    "subtypes",
    "substitute",
    "variables_of",
    "write",
    "write_pretty",
]
