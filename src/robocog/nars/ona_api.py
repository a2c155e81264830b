"""ONA's Python interface (``misc/Python/NAR.py``) over this reasoner.

A script written for ONA's wrapper runs on robocog by changing its import::

    import NAR                                   # ONA's wrapper, which drives ONA's binary
    from robocog.nars import ona_api as NAR      # the same calls, in this process

``AddInput(narsese, Print=True)`` returns what ONA's wrapper returns: a dict with the
parsed ``input`` lines, ``derivations`` (``Derived:`` and ``Revised:`` lines),
``answers``, ``executions`` (``{"operator": "^op", "arguments": ...}``), ``reason``
(the last decision's desire, hypothesis and precondition, or None), ``selections``,
``raw`` (the output lines, joined) and ``requestOutputArgs``; ``AddInput("*stats")``
returns the statistics as a dict of numbers. Each parsed line is a dict with
``term``, ``punctuation``, ``occurrenceTime`` (``"eternal"``, or the time as a string),
and where the line has them ``truth`` (``{"frequency": "...", "confidence": "..."}``,
strings as printed), ``Stamp`` (a list of ints) and ``Priority`` (a string). The fields
are ONA's, read from the same output lines ONA prints, so code that picks them apart
sees what it saw with ONA.

Where ONA's wrapper talks to a process, this module holds a :class:`robocog.nars.NAR`;
``spawnNAR()`` makes another, ``setNAR``/``getNAR`` choose which one is used, and
``Exit()`` ends one. Unlike ONA's binary a bad line does not stop anything: its
``Error:`` line is part of ``raw``.
"""

from __future__ import annotations

import re
import sys
from typing import Any

from .nar import NAR
from .narsese import NarseseError


class Instance:
    """One reasoner as ONA's wrapper sees a ``NAR shell`` process: lines in, lines out."""

    def __init__(self) -> None:
        self.nar: NAR | None = NAR()
        self.lines: list[str] = []
        self.nar.output = self.lines.append
        self.nar.config.print_derivations = True
        self.line_number = 0

    def send(self, narsese: str) -> list[str]:
        """The output lines of one input line, as ``NAR shell`` prints them."""
        if self.nar is None:
            raise RuntimeError("this reasoner was ended by Exit()")
        self.lines.clear()
        self.line_number += 1
        try:
            self.nar.add_input(narsese)
        except NarseseError as exc:
            self.lines.append(f"Error: line {self.line_number}, column {exc.column}: {exc.message}")
        out = [line.strip() for line in self.lines]
        self.lines.clear()
        return out


def spawnNAR() -> Instance:  # noqa: N802 - ONA's name
    """A new reasoner, as ONA's wrapper starts a new process."""
    return Instance()


NARproc = spawnNAR()  # noqa: N816 - ONA's name


def getNAR() -> Instance:  # noqa: N802 - ONA's name
    """The reasoner calls use when given none."""
    return NARproc


def setNAR(proc: Instance) -> None:  # noqa: N802 - ONA's name
    """Make ``proc`` the reasoner :func:`getNAR` returns."""
    global NARproc
    NARproc = proc


def terminateNAR(usedNAR: Instance | None = None) -> None:  # noqa: N802, N803 - ONA's names
    """End a reasoner (ONA kills its process)."""
    (usedNAR or NARproc).nar = None


# ----------------------------------------------------------------- reading lines
_STAMP = re.compile(r"Stamp=\[([0-9,\s]*)\]")
_OCCURRENCE = re.compile(r"occurrenceTime=(\S*)")
_PRIORITY = re.compile(r"Priority=(\S*)")
_FREQUENCY = re.compile(r"frequency=([^\s,]*)")
_CONFIDENCE = re.compile(r"confidence=([^\s,]*)")
_CUTS = (" occurrenceTime=", " Stamp=", " Priority=", " creationTime=", " Truth")


def parseTruth(text: str) -> dict[str, str]:  # noqa: N802 - ONA's name
    """``{"frequency": "1.000000", "confidence": "0.900000"}`` from a printed truth."""
    f = _FREQUENCY.search(text)
    c = _CONFIDENCE.search(text)
    return {"frequency": f.group(1) if f else "", "confidence": c.group(1) if c else ""}


def parseTask(text: str) -> dict[str, Any]:  # noqa: N802 - ONA's name
    """The fields of a printed event, e.g. ``x. :|: occurrenceTime=3 Priority=1.000000
    Stamp=[3] Truth: frequency=1.000000, confidence=0.900000``."""
    task: dict[str, Any] = {"occurrenceTime": "eternal"}
    tensed = " :|:" in text
    if tensed:
        text = text.replace(" :|:", "")
        occ = _OCCURRENCE.search(text)
        task["occurrenceTime"] = occ.group(1) if occ else "now"
    stamp = _STAMP.search(text)
    if stamp:
        inner = stamp.group(1).strip()
        task["Stamp"] = [int(x) for x in inner.split(",") if x.strip()] if inner else []
    head = text
    for cut in _CUTS:
        head = head.split(cut)[0]
    task["punctuation"] = head[-1:] if head else ""
    task["term"] = head[:-1]
    if "Truth" in text:
        task["truth"] = parseTruth(text.split("Truth: ", 1)[1] if "Truth: " in text else "")
    prio = _PRIORITY.search(text)
    if prio:
        task["Priority"] = prio.group(1)
    return task


def parseReason(raw: str) -> dict[str, Any] | None:  # noqa: N802 - ONA's name
    """The last decision in ``raw``: its desire, hypothesis and precondition."""
    if "implication: " not in raw:
        return None
    last = raw[raw.rindex("decision expectation=") :] if "decision expectation=" in raw else raw
    last = last.split("\n")[0]
    implication_text = last.split("implication: ")[-1].split("precondition: ")[0]
    precondition_text = last.split("precondition: ")[-1]
    hypothesis = parseTask(implication_text.strip())
    precondition = parseTask(precondition_text.strip())
    hypothesis["occurrenceTime"] = "eternal"
    hypothesis["punctuation"] = precondition["punctuation"] = "."
    desire = last.split("decision expectation=")[-1].split(" ")[0]
    return {"desire": desire, "hypothesis": hypothesis, "precondition": precondition}


def parseExecution(line: str) -> dict[str, Any]:  # noqa: N802 - ONA's name
    """``^go executed with args ({SELF} * y)`` -> ``{"operator": "^go", "arguments": "y"}``;
    without arguments, ``"arguments"`` is an empty list (as in ONA's wrapper)."""
    operator = line.split(" ")[0]
    if "args " not in line:
        return {"operator": operator, "arguments": []}
    args = line.split("args ", 1)[1]
    if "{SELF} * " in args:
        args = args.split("{SELF} * ", 1)[1][:-1]
    return {"operator": operator, "arguments": args}


def _after(line: str, prefix: str) -> str:
    return line[len(prefix) :].strip()


def GetOutput(lines: list[str]) -> dict[str, Any]:  # noqa: N802 - ONA's name
    """The dict :func:`AddInput` returns, from one input's output lines."""
    derived = [x for x in lines if x.startswith(("Derived:", "Revised:"))]
    raw = "\n".join(lines)
    return {
        "input": [parseTask(_after(x, "Input:")) for x in lines if x.startswith("Input:")],
        "derivations": [parseTask(x.split(": ", 1)[1]) for x in derived],
        "answers": [parseTask(_after(x, "Answer:")) for x in lines if x.startswith("Answer:")],
        "executions": [parseExecution(x) for x in lines if x.startswith("^")],
        "reason": parseReason(raw),
        "selections": [
            parseTask(_after(x, "Selected:")) for x in lines if x.startswith("Selected:")
        ],
        "raw": raw,
        "requestOutputArgs": False,
    }


def _stats(lines: list[str]) -> dict[str, float]:
    out: dict[str, float] = {}
    for line in lines:
        if ":" not in line or line.startswith("//"):
            continue
        key, _, value = line.partition(":")
        try:
            out[key.replace(" ", "_").strip()] = float(value.strip())
        except ValueError:
            continue
    return out


# ------------------------------------------------------------------- the calls
def AddInput(  # noqa: N802 - ONA's name
    narsese: str,
    Print: bool = True,
    usedNAR: Instance | None = None,  # noqa: N803
) -> dict[str, Any]:
    """Give the reasoner one line; the dict of what it printed (see the module's doc).
    ``"*stats"`` returns the statistics instead. ``Print`` echoes the raw output."""
    proc = usedNAR or NARproc
    lines = proc.send(narsese)
    if narsese == "*stats":
        if Print:
            print("\n".join(lines))
        return _stats(lines)
    result = GetOutput(lines)
    if Print:
        print(result["raw"])
        sys.stdout.flush()
    return result


def GetStats(usedNAR: Instance | None = None) -> dict[str, float]:  # noqa: N802, N803
    """The statistics as numbers by name (spaces in names become ``_``)."""
    return AddInput("*stats", Print=False, usedNAR=usedNAR)  # type: ignore[return-value]


def Reset(usedNAR: Instance | None = None) -> None:  # noqa: N802, N803 - ONA's names
    """Forget everything (``*reset``)."""
    AddInput("*reset", Print=False, usedNAR=usedNAR)


def Exit(usedNAR: Instance | None = None) -> None:  # noqa: N802, N803 - ONA's names
    """End the reasoner (ONA's wrapper sends ``quit``)."""
    terminateNAR(usedNAR)


def PrintedTask(task: dict[str, Any]) -> str:  # noqa: N802 - ONA's name
    """A parsed task printed back in ONA's short form."""
    text = task["term"] + task["punctuation"]
    if str(task["occurrenceTime"]).isdigit():
        text += " :|: occurrenceTime=" + task["occurrenceTime"]
    if "Priority" in task:
        text += " Priority=" + str(task["Priority"])
    if "truth" in task:
        t = task["truth"]
        text += f" Truth: frequency={t['frequency']} confidence={t['confidence']}"
    return text


def Shell() -> None:  # noqa: N802 - ONA's name
    """Read lines from stdin and print what each gives, until EOF."""
    for line in sys.stdin:
        AddInput(line.rstrip("\n"))


AddInput("*volume=100", Print=False)

__all__ = [
    "AddInput",
    "Exit",
    "GetOutput",
    "GetStats",
    "NARproc",
    "PrintedTask",
    "Reset",
    "Shell",
    "getNAR",
    "parseExecution",
    "parseReason",
    "parseTask",
    "parseTruth",
    "setNAR",
    "spawnNAR",
    "terminateNAR",
]
