"""Values: truth values and the other valuations an atom can carry under a key.

Values are immutable, like OpenCog's: to change one, store a new one. A truth value is
a SimpleTruthValue ``(stv strength confidence)``; the default of an atom that never got
one is ``(stv 1 0)``, as in OpenCog. Other Values (FloatValue, StringValue, LinkValue,
QueueValue) hold sequences and sit under a key atom in an atom's key-value table.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from robocog.atomspace.atoms import atom_text, quote


class Value:
    """Base of every Value."""

    __slots__ = ()

    def to_atomese(self) -> str:
        """The value as Atomese text."""
        raise NotImplementedError


@dataclass(frozen=True, slots=True, repr=False)
class TruthValue(Value):
    """A simple truth value: strength and confidence, both in [0, 1]."""

    strength: float = 1.0
    confidence: float = 0.0

    def __post_init__(self) -> None:
        for label, x in (("strength", self.strength), ("confidence", self.confidence)):
            if not isinstance(x, int | float) or not 0.0 <= float(x) <= 1.0:
                raise ValueError(f"truth value {label} must be in [0, 1], got {x!r}")

    @property
    def mean(self) -> float:
        """OpenCog's name for the strength."""
        return self.strength

    def is_true(self) -> bool:
        """Crisp reading used by the matcher: strength above one half."""
        return self.strength > 0.5

    def __repr__(self) -> str:
        return self.to_atomese()

    def to_atomese(self) -> str:
        """``(stv s c)``."""
        return f"(stv {_num(self.strength)} {_num(self.confidence)})"


def stv(strength: float, confidence: float) -> TruthValue:
    """Shorthand for ``TruthValue(strength, confidence)``."""
    return TruthValue(float(strength), float(confidence))


DEFAULT_TV = TruthValue(1.0, 0.0)
TRUE_TV = TruthValue(1.0, 1.0)
FALSE_TV = TruthValue(0.0, 1.0)


class _SeqValue(Value):
    """A Value holding an immutable sequence."""

    __slots__ = ("items",)
    _name = "Value"

    def __init__(self, items: Iterable[Any]) -> None:
        object.__setattr__(self, "items", tuple(items))

    def __setattr__(self, key: str, value: Any) -> None:
        raise AttributeError("Values are immutable")

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other.items == self.items  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash((self._name, self.items))

    def __len__(self) -> int:
        return len(self.items)

    def __iter__(self):  # noqa: ANN204 - iterator over the items
        return iter(self.items)

    def __repr__(self) -> str:
        return self.to_atomese()

    def to_atomese(self) -> str:
        """``(FloatValue 1 2 3)`` and the like."""
        inner = " ".join(self._item_text(x) for x in self.items)
        return f"({self._name}{' ' if inner else ''}{inner})"

    def _item_text(self, x: Any) -> str:
        return str(x)


class FloatValue(_SeqValue):
    """A vector of floats."""

    __slots__ = ()
    _name = "FloatValue"

    def __init__(self, items: Iterable[float]) -> None:
        super().__init__(float(x) for x in items)

    def _item_text(self, x: Any) -> str:
        return _num(x)


class StringValue(_SeqValue):
    """A vector of strings."""

    __slots__ = ()
    _name = "StringValue"

    def __init__(self, items: Iterable[str]) -> None:
        super().__init__(str(x) for x in items)

    def _item_text(self, x: Any) -> str:
        return quote(x)


class LinkValue(_SeqValue):
    """A vector of atoms or Values."""

    __slots__ = ()
    _name = "LinkValue"

    def _item_text(self, x: Any) -> str:
        return x.to_atomese() if isinstance(x, Value) else atom_text(x)


class QueueValue(LinkValue):
    """The results of a MeetLink, in the order they were found."""

    __slots__ = ()
    _name = "QueueValue"


def _num(x: float) -> str:
    """Shortest text for a float that reads back the same ("1", "0.5")."""
    f = float(x)
    if f.is_integer() and abs(f) < 1e15:
        return str(int(f))
    return repr(f)
