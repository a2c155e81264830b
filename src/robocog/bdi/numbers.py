"""Numbers as Jason prints them: integral values without a decimal part, the others as
Java's ``Double.toString`` writes them (plain in [1e-3, 1e7), scientific otherwise), so
that a program's output reads as it does on Jason."""

from __future__ import annotations

import math


def number_str(x: int | float) -> str:
    """Jason prints integral numbers without a decimal part, others as Java doubles."""
    if x.__class__ is int:
        return str(x)
    if x != x:
        return "NaN"
    if math.isinf(x):
        return "Infinity" if x > 0 else "-Infinity"
    if math.isfinite(x) and x == int(x) and abs(x) < 9.2e18:
        return str(int(x))
    return java_double_str(x)


def java_double_str(x: float) -> str:
    """``Double.toString``: plain notation in [1e-3, 1e7), scientific otherwise."""
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "Infinity" if x > 0 else "-Infinity"
    ax = abs(x)
    if ax == 0 or 1e-3 <= ax < 1e7:
        s = repr(x)
        if "e" in s or "E" in s:
            s = f"{x:f}".rstrip("0")
        if "." not in s:
            s += ".0"
        if s.endswith("."):
            s += "0"
        return s
    # shortest round-trip digits of x, re-expressed as d.dddE<exp>
    sign = "-" if x < 0 else ""
    digits = repr(ax)
    if "e" in digits:
        mant, _, e2 = digits.partition("e")
        if "." not in mant:
            mant += ".0"
        return f"{sign}{mant}E{int(e2)}"
    whole, _, frac = digits.partition(".")
    if whole != "0":
        exp_i = len(whole) - 1
    else:
        exp_i = -(len(frac) - len(frac.lstrip("0")) + 1)
    sig = (whole + frac).lstrip("0").rstrip("0") or "0"
    return f"{sign}{sig[0]}.{sig[1:] or '0'}E{exp_i}"
