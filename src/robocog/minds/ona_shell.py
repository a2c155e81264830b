"""ONA 0.9.2 (``NAR shell``, PyPI ``ona``) as the reasoner behind NarsMind.

The peer system the seed's robot ran on, driven through its text protocol: NarsMind's
calls (``add_input``, ``add_sentence``, ``cycles``, ``register_operation``, ``answer``)
become lines on the child process's stdin, and its ``^op executed with args ...`` lines
call the registered operations with the arguments read as a term. Used to measure ONA on the same world, encodings and goals as
robocog's own reasoner (``robocog experiment garbage --minds nars,bdi,ona`` and
``benchmarks/robot_loop.py``).

ONA 0.9.2 cannot read the first rule of the background knowledge as the paper prints
it (``<<(gripper --> [open]) &/ <(...) --> ^goto> =/> ...>>`` comes out as another
term), so ONA is given that rule with the brackets its reader needs; the rest is the
same text.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from robocog.minds.nars_mind import BRACKETED_GOTO_RULE, PRINTED_GOTO_RULE, background
from robocog.nars import NarseseError, Term, parse_term
from robocog.nars.narsese import Sentence
from robocog.ona_process import OnaProcess, unavailable_reason

#: the first rule bracketed as ONA's reader needs it
ONA_GOTO_RULE = BRACKETED_GOTO_RULE


@dataclass(frozen=True)
class Truth:
    """Frequency and confidence of an answer."""

    f: float
    c: float


@dataclass(frozen=True)
class Answer:
    """An ONA answer, shaped like robocog's events (``term``, ``truth``): the term as
    ONA printed it, or read into robocog's term when :meth:`OnaShell.answer` asked."""

    term: str | Term
    truth: Truth


def _term(text: str | None) -> Term | None:
    """ONA's printed term read by robocog's reader, or None when there is none or it
    cannot be read."""
    if not text:
        return None
    try:
        return parse_term(text)
    except NarseseError:
        return None


def ona_knowledge() -> list[str]:
    """The background knowledge in the form ONA 0.9.2 reads as the paper means it."""
    return [ONA_GOTO_RULE if line == PRINTED_GOTO_RULE else line for line in background()]


def unavailable(command: str | None = None) -> str | None:
    """Why ONA cannot run here (``command``, or ONA's binary found as
    :func:`robocog.ona_process.ona_command` finds it), or None."""
    return unavailable_reason(None if command is None else [command])


class OnaShell:
    """A running ``NAR shell`` with the calls NarsMind makes on a reasoner.

    Input lines are written as they come; ``cycles`` and ``ask`` exchange them with ONA
    (:meth:`robocog.ona_process.OnaProcess.exchange`: a marker comment, ONA's output read
    up to its echo, each read waiting at most ``timeout`` seconds), calling the registered
    operation for every execution line on the way. A missing binary, a child that exits
    or one that stops answering raise :class:`~robocog.ona_process.OnaError` naming the
    command, with ONA's last output.
    """

    def __init__(self, command: str | None = None, timeout: float = 60.0) -> None:
        self.process = OnaProcess(None if command is None else [command], timeout=timeout)
        self.proc = self.process.proc
        self.ops: dict[str, Callable[[Term | None], object]] = {}
        self.output: Callable[[str], None] | None = None
        self.add_input("*volume=0")

    def register_operation(self, name: str, fn: Callable[[Term | None], object]) -> None:
        """Call ``fn(args)`` when ONA prints that ``name`` was executed: the printed
        arguments read as a term, as robocog's reasoner hands them."""
        self.ops[name] = fn

    def add_input(self, line: str) -> None:
        """Send one line (Narsese, a number of cycles, or a ``*`` command)."""
        self.process.send(line)

    def add_sentence(self, sentence: Sentence) -> None:
        """Send a sentence built by the mind, in ONA's notation."""
        self.add_input(str(sentence))

    def _on_line(self, line: str) -> None:
        if self.output is not None:
            self.output(line)
        if " executed with args" in line:
            op, _, args = line.partition(" executed with args")
            fn = self.ops.get(op.strip())
            if fn is not None:
                fn(_term(args.strip()))

    def _sync(self) -> list[str]:
        return self.process.exchange(on_line=self._on_line)

    def cycles(self, n: int) -> None:
        """Run ``n`` inference cycles and handle what they executed."""
        self.add_input(str(n))
        self._sync()

    def ask(self, question: str) -> Answer | None:
        """ONA's answer to a question, or None."""
        self.add_input(question)
        for line in self._sync():
            if line.startswith("Answer: ") and not line.startswith("Answer: None"):
                term = line[len("Answer: ") :].split(". ")[0]
                f = float(line.split("frequency=")[1].split(",")[0])
                c = float(line.split("confidence=")[1].split()[0])
                return Answer(term, Truth(f, c))
        return None

    def answer(self, question: Term) -> Answer | None:
        """ONA's answer to the question ``question?``, its term read by robocog's reader."""
        found = self.ask(f"{question}?")
        if found is None:
            return None
        term = _term(str(found.term))
        return None if term is None else Answer(term, found.truth)

    def close(self) -> None:
        """End the process (see :meth:`robocog.ona_process.OnaProcess.close`)."""
        self.process.close()
