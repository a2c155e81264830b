"""What every reader does with text that is too long to repeat in an error message.

An error names the piece of input at fault; a 10 MB name would otherwise be echoed
whole, to a terminal or a log. :func:`clip` keeps the start of a piece and says how
long it was. (The bounds themselves live beside each reader and are listed in
docs/fuzzing.md.)
"""

from __future__ import annotations

#: how much of an input piece an error message repeats
QUOTE_CHARS = 80
#: the longest error message a reader gives
MESSAGE_CHARS = 500


def clip(text: str, most: int = QUOTE_CHARS) -> str:
    """``text`` if it is at most ``most`` characters, else its start and its length."""
    if len(text) <= most:
        return text
    return f"{text[:most]}... ({len(text)} characters)"
