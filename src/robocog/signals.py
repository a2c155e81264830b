"""A signal's handler for the length of a block, the previous one back after it.

A command that stops cleanly on SIGTERM installs a handler for it; run in someone
else's process (a test, a notebook, a launcher calling ``robocog.cli.main``), it must not
leave that handler behind once it returns, where it would call into a robot or a
simulator that is gone.
"""

from __future__ import annotations

import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import FrameType

Handler = Callable[[int, FrameType | None], object]


@contextmanager
def handling(signum: int, handler: Handler) -> Iterator[None]:
    """Handle ``signum`` with ``handler`` inside the block (main thread only, as for
    ``signal.signal``), then put back whatever handled it before."""
    before = signal.signal(signum, handler)
    try:
        yield
    finally:
        signal.signal(signum, before)
