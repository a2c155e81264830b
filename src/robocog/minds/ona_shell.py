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

import shutil
import subprocess
from collections.abc import Callable
from dataclasses import dataclass

from robocog.minds.nars_mind import BRACKETED_GOTO_RULE, PRINTED_GOTO_RULE, background
from robocog.nars import NarseseError, Term, parse_term
from robocog.nars.narsese import Sentence

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


def unavailable(command: str = "NAR") -> str | None:
    """Why ONA cannot run here, or None."""
    if shutil.which(command) is None:
        return f"the {command} command of ONA is not installed (pip install ona==0.9.2)"
    return None


class OnaShell:
    """A running ``NAR shell`` with the calls NarsMind makes on a reasoner.

    Input lines are written as they come; ``cycles`` and ``ask`` write a marker comment
    and read ONA's output up to its echo, calling the registered operation for every
    execution line on the way.
    """

    def __init__(self, command: str = "NAR") -> None:
        self.proc = subprocess.Popen(
            [command, "shell"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
            bufsize=1,
        )
        self.ops: dict[str, Callable[[Term | None], object]] = {}
        self._marker = 0
        self.output: Callable[[str], None] | None = None
        self.add_input("*volume=0")

    def register_operation(self, name: str, fn: Callable[[Term | None], object]) -> None:
        """Call ``fn(args)`` when ONA prints that ``name`` was executed: the printed
        arguments read as a term, as robocog's reasoner hands them."""
        self.ops[name] = fn

    def add_input(self, line: str) -> None:
        """Send one line (Narsese, a number of cycles, or a ``*`` command)."""
        assert self.proc.stdin is not None
        self.proc.stdin.write(line.strip() + "\n")

    def add_sentence(self, sentence: Sentence) -> None:
        """Send a sentence built by the mind, in ONA's notation."""
        self.add_input(str(sentence))

    def _sync(self) -> list[str]:
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self._marker += 1
        marker = f"sync{self._marker}"
        self.proc.stdin.write(f"//{marker}\n")
        self.proc.stdin.flush()
        lines: list[str] = []
        for raw in self.proc.stdout:
            line = raw.rstrip("\n")
            if line == f"Comment: {marker}":
                return lines
            lines.append(line)
            if self.output is not None:
                self.output(line)
            if " executed with args" in line:
                op, _, args = line.partition(" executed with args")
                fn = self.ops.get(op.strip())
                if fn is not None:
                    fn(_term(args.strip()))
        raise RuntimeError("ONA's process ended")

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
        """End the process."""
        if self.proc.poll() is None:
            try:
                if self.proc.stdin:
                    self.proc.stdin.close()
                self.proc.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                self.proc.kill()
                self.proc.wait()

    def __del__(self) -> None:
        if getattr(self, "proc", None) is not None and self.proc.poll() is None:
            self.proc.kill()
