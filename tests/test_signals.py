"""``robocog.signals.handling``: a handler for a block, the previous one after it."""

from __future__ import annotations

import os
import signal

import pytest

from robocog.signals import handling


def test_the_handler_serves_inside_the_block_and_the_previous_one_after() -> None:
    got: list[int] = []
    before = signal.getsignal(signal.SIGUSR1)
    with handling(signal.SIGUSR1, lambda signum, _frame: got.append(signum)):
        os.kill(os.getpid(), signal.SIGUSR1)
    assert got == [signal.SIGUSR1]
    assert signal.getsignal(signal.SIGUSR1) is before


def test_the_previous_handler_is_back_when_the_block_raises() -> None:
    before = signal.getsignal(signal.SIGUSR2)
    with pytest.raises(RuntimeError), handling(signal.SIGUSR2, lambda *_: None):
        raise RuntimeError("the command failed")
    assert signal.getsignal(signal.SIGUSR2) is before
