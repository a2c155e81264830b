"""Mutations of seed inputs: what a careless file, a hostile peer or a noisy topic sends.

Every mutator takes the input, a second seed (for splicing), the target's tokens and
brackets, and a random generator, and returns new bytes. The hostile ones are the
shapes that broke readers before: deep nesting, long repetitions (lists of thousands of
annotations), huge and non-finite numbers, invalid UTF-8, very long lines.
"""

from __future__ import annotations

import random
from collections.abc import Callable, Sequence

#: the largest input a mutation may make (a few inputs per thousand reach it)
MAX_INPUT = 12 << 20

NUMBERS = (
    b"0",
    b"-0",
    b"1",
    b"-1",
    b"2.0",
    b"-5",
    b"1e308",
    b"-1e308",
    b"1e309",
    b"NaN",
    b"nan",
    b"inf",
    b"-inf",
    b"Infinity",
    b"9" * 25,
    b"9" * 400,
    b"0." + b"0" * 300 + b"1",
    b"1e-320",
    b"4294967296",
    b"18446744073709551616",
    b"1000000000000000",
    b"1000000000000001",
)
BAD_UTF8 = (b"\xff", b"\xc0\x80", b"\xed\xa0\x80", b"\xe2\x82", b"\x80", b"\xf4\x90\x80\x80")
ODD = (b"\x00", b"\t", b"\r", b"\r\n", b"\n", b"\\", b'"', b"'", b" ", "\u2028".encode())

Mutator = Callable[
    [bytes, bytes, Sequence[bytes], Sequence[tuple[bytes, bytes]], random.Random], bytes
]


def _pos(data: bytes, rng: random.Random) -> int:
    return rng.randint(0, len(data)) if data else 0


def flip(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """A few random bytes changed."""
    if not data:
        return bytes([rng.randrange(256)])
    b = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        i = rng.randrange(len(b))
        b[i] = rng.randrange(256) if rng.random() < 0.5 else b[i] ^ (1 << rng.randrange(8))
    return bytes(b)


def erase(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """A span removed."""
    if len(data) < 2:
        return data
    i = rng.randrange(len(data))
    j = min(len(data), i + rng.randint(1, max(1, len(data) // 4)))
    return data[:i] + data[j:]


def duplicate(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """A span repeated a few times where it stands."""
    if not data:
        return data
    i = rng.randrange(len(data))
    j = min(len(data), i + rng.randint(1, 64))
    return data[:j] + data[i:j] * rng.randint(1, 8) + data[j:]


def splice(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """The start of this input and the end of another."""
    i, j = _pos(data, rng), _pos(other, rng)
    return data[:i] + other[j:]


def token(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """A token of the language, or an odd character, put somewhere."""
    pool = list(tokens) + list(ODD)
    i = _pos(data, rng)
    return data[:i] + rng.choice(pool) + data[i:]


def number(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """A number replaced by a huge, tiny, negative or non-finite one."""
    digits = [i for i, c in enumerate(data) if 48 <= c <= 57]
    new = rng.choice(NUMBERS)
    if not digits:
        i = _pos(data, rng)
        return data[:i] + new + data[i:]
    i = rng.choice(digits)
    while i > 0 and (data[i - 1] in b"0123456789.-+eE"):
        i -= 1
    j = i
    while j < len(data) and data[j] in b"0123456789.-+eE":
        j += 1
    return data[:i] + new + data[j:]


def bad_utf8(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """Bytes that are not UTF-8."""
    i = _pos(data, rng)
    return data[:i] + rng.choice(BAD_UTF8) + data[i:]


def nest(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """A part wrapped in the language's brackets hundreds to tens of thousands deep."""
    if not brackets:
        return data
    opening, closing = rng.choice(brackets)
    depth = rng.choice((50, 200, 1_000, 1_500, 5_000, 30_000))
    i = _pos(data, rng)
    j = rng.randint(i, len(data)) if data else 0
    return data[:i] + opening * depth + data[i:j] + closing * depth + data[j:]


def repeat(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """A short span repeated thousands of times (long lists, long names)."""
    if not data:
        return data
    i = rng.randrange(len(data))
    j = min(len(data), i + rng.randint(1, 24))
    times = rng.choice((1_000, 5_000, 20_000, 100_000))
    return data[:j] + data[i:j] * times + data[j:]


def long_line(data: bytes, other: bytes, tokens, brackets, rng: random.Random) -> bytes:  # noqa: ANN001
    """One very long name or line (up to 10 MB)."""
    size = rng.choice((5_000, 70_000, 1 << 20, 10 << 20))
    i = _pos(data, rng)
    letter = bytes([rng.choice(b"abcxyzA0_")])
    return data[:i] + letter * size + data[i:]


#: the mutators and their weights: the cheap ones often, the ones making megabytes rarely
MUTATORS: list[tuple[Mutator, int]] = [
    (flip, 20),
    (erase, 10),
    (duplicate, 10),
    (splice, 10),
    (token, 20),
    (number, 10),
    (bad_utf8, 5),
    (nest, 6),
    (repeat, 5),
    (long_line, 1),
]


def mutate(
    data: bytes,
    other: bytes,
    tokens: Sequence[bytes],
    brackets: Sequence[tuple[bytes, bytes]],
    rng: random.Random,
) -> bytes:
    """One to three mutations of ``data``, at most ``MAX_INPUT`` bytes."""
    funcs = [m for m, _ in MUTATORS]
    weights = [w for _, w in MUTATORS]
    for _ in range(rng.choice((1, 1, 1, 2, 3))):
        data = rng.choices(funcs, weights)[0](data, other, tokens, brackets, rng)
        if len(data) > MAX_INPUT:
            data = data[:MAX_INPUT]
    return data
