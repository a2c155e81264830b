"""Cython's class decorators for the engine's value classes, as no-ops where Cython is
not installed.

The compiled engine reads ``@cython.freelist(n)`` on a class: its instances (a truth
value, an event, an implication: thousands made and dropped every cycle) are then
recycled from a list of ``n`` freed ones rather than allocated and freed each time; and
``@cython.no_gc`` on a class whose instances are never part of a reference cycle (a term,
an event), which keeps them out of the cycle collector's walks.
Cython knows the name ``cython`` at compile time; the pure engine imports Cython's own
pure-Python ``cython`` module if it is there, and else this one, which changes nothing.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

C = TypeVar("C", bound=type)


def freelist(size: int) -> Callable[[C], C]:
    """Keep up to ``size`` freed instances for reuse (compiled only)."""
    return lambda cls: cls


def no_gc(cls: C) -> C:
    """Leave the instances out of the cycle collector (compiled only): for a class whose
    instances can never be part of a reference cycle."""
    return cls


def cclass(cls: C) -> C:
    """Make the class an extension type (compiled only)."""
    return cls
