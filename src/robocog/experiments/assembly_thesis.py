"""The assembly experiments of the AtomSpace planner thesis (Tables 5.2-5.10), as data.

Each ``Experiment`` holds what the table lists: the objects seen, the sentences of the
learning phase, the sentences of the request phase, the plan the thesis printed, its
search time and its number of iterations. The footnote of the tables ("the additional
information about table, workbench and the bins is not rewritten") is expanded into
``FIXED_SENTENCES``. Two objects are named only in sentences (SnapRing2 in Table 5.2,
BlockC in Table 5.8); the learning phase adds such names as movable objects.

Table 5.5 prints its second request sentence in the Solution row; it is restored to the
request here. Table 5.9 prints one closing parenthesis too many; it is dropped.
``WHOLE_ASSEMBLIES`` are the BlockB and BlockC assemblies the thesis had to split into
several requests, stated as one request each.
"""

from __future__ import annotations

from dataclasses import dataclass

FIXED = ["table", "workbench", "PurpleBin", "GreenBin", "RedBin", "BlueBin", "YellowBin"]
FIXED_SENTENCES = " ".join(f"The {name} is a fixed object." for name in FIXED)


@dataclass(frozen=True)
class Experiment:
    """One table of Chapter 5."""

    table: str
    title: str
    objects: tuple[str, ...]
    facts: str
    request: str
    plan: tuple[str, ...]
    seconds: float
    iterations: int

    @property
    def length(self) -> int:
        """Number of actions in the thesis's plan."""
        return len(self.plan)


def _c(name: str) -> str:
    return f'(ConceptNode "{name}")'


def _pickup(x: str) -> str:
    return f"(pickup {_c(x)})"


def _unstack(x: str, y: str) -> str:
    return f"(unstack {_c(x)} {_c(y)})"


def _stack(x: str, y: str) -> str:
    return f"(stack {_c(x)} {_c(y)})"


_B_PARTS = ("SnapRing1", "SnapRing2", "RecirculatingBallSleeve", "BearingSleeve1", "BearingSleeve2")
_BLOCK_B_OBJECTS = ("BlockA", *_B_PARTS, *FIXED)
_C_PARTS = ("TCEIScrew", "UpperBearingBracket", "RotatingBalancerSupport", "Bearing")
_BLOCK_C_OBJECTS = ("BlockA", "BlockB", *_C_PARTS, *FIXED)
_SLEEVES = "The SnapRing1 is on the SnapRing2. The BearingSleeve1 is on the BearingSleeve2."

EXPERIMENTS: tuple[Experiment, ...] = (
    Experiment(
        "5.2",
        "BlockA Assembly Process",
        (
            "InductionHardenedRod",
            "BettClamp",
            "SnapRing1",
            "RecirculatingBallSleeve",
            "BearingSleeve1",
            "BearingSleeve2",
            *FIXED,
        ),
        f"{FIXED_SENTENCES} {_SLEEVES}",
        "The BettClamp is on the workbench. The InductionHardenedRod is on the BettClamp.",
        (
            _pickup("BettClamp"),
            _stack("BettClamp", "workbench"),
            _pickup("InductionHardenedRod"),
            _stack("InductionHardenedRod", "BettClamp"),
        ),
        25.0,
        401,
    ),
    Experiment(
        "5.3",
        "BlockA Move Process",
        _BLOCK_B_OBJECTS,
        f"{FIXED_SENTENCES} {_SLEEVES}",
        "The BlockA is on the table.",
        (_pickup("BlockA"), _stack("BlockA", "table")),
        0.0,
        3,
    ),
    Experiment(
        "5.4",
        "BlockB Assembly Process 1",
        _BLOCK_B_OBJECTS,
        f"{FIXED_SENTENCES} {_SLEEVES}",
        "The SnapRing1 is on the workbench. The BearingSleeve1 is on the SnapRing1.",
        (
            _unstack("SnapRing1", "SnapRing2"),
            _stack("SnapRing1", "workbench"),
            _unstack("BearingSleeve1", "BearingSleeve2"),
            _stack("BearingSleeve1", "SnapRing1"),
        ),
        39.0,
        493,
    ),
    Experiment(
        "5.5",
        "BlockB Assembly Process 2",
        _BLOCK_B_OBJECTS,
        f"{FIXED_SENTENCES} The SnapRing1 is on the workbench. The BearingSleeve1 is on the SnapRing1.",
        "The RecirculatingBallSleeve is on the BearingSleeve1. "
        "The BearingSleeve2 is on the RecirculatingBallSleeve.",
        (
            _pickup("RecirculatingBallSleeve"),
            _stack("RecirculatingBallSleeve", "BearingSleeve1"),
            _pickup("BearingSleeve2"),
            _stack("BearingSleeve2", "RecirculatingBallSleeve"),
        ),
        2.1,
        343,
    ),
    Experiment(
        "5.6",
        "BlockB Assembly Process 3",
        _BLOCK_B_OBJECTS,
        f"{FIXED_SENTENCES} The SnapRing1 is on the workbench. The BearingSleeve1 is on the "
        "SnapRing1. The RecirculatingBallSleeve is on the BearingSleeve1. The BearingSleeve2 "
        "is on the RecirculatingBallSleeve.",
        "The SnapRing2 is on the BearingSleeve2.",
        (_pickup("SnapRing2"), _stack("SnapRing2", "BearingSleeve2")),
        0.0,
        3,
    ),
    Experiment(
        "5.7",
        "BlockB Move Process",
        ("BlockA", "BlockB", *FIXED),
        FIXED_SENTENCES,
        "The BlockB is on the BlockA.",
        (_pickup("BlockB"), _stack("BlockB", "BlockA")),
        0.0,
        2,
    ),
    Experiment(
        "5.8",
        "BlockC Assembly Process 1",
        _BLOCK_C_OBJECTS,
        f"{FIXED_SENTENCES} The BlockB is on the BlockA.",
        "The UpperBearingBracket is on the BlockC. The Bearing is on the UpperBearingBracket. "
        "The RotatingBalancerSupport is on the Bearing.",
        (
            _pickup("UpperBearingBracket"),
            _stack("UpperBearingBracket", "BlockC"),
            _pickup("Bearing"),
            _stack("Bearing", "UpperBearingBracket"),
            _pickup("RotatingBalancerSupport"),
            _stack("RotatingBalancerSupport", "Bearing"),
        ),
        699.0,
        5853,
    ),
    Experiment(
        "5.9",
        "BlockC Assembly Process 2",
        _BLOCK_C_OBJECTS,
        f"{FIXED_SENTENCES} The BlockB is on the BlockA. The UpperBearingBracket is on the "
        "BlockC. The Bearing is on the UpperBearingBracket. The RotatingBalancerSupport is on "
        "the Bearing.",
        "The TCEIScrew is on the RotatingBalancerSupport.",
        (_pickup("TCEIScrew"), _stack("TCEIScrew", "RotatingBalancerSupport")),
        0.0,
        2,
    ),
    Experiment(
        "5.10",
        "BlockC Move Process",
        ("BlockA", "BlockB", "BlockC", *FIXED),
        f"{FIXED_SENTENCES} The BlockB is on the BlockA.",
        "The BlockC is on the BlockB.",
        (_pickup("BlockC"), _stack("BlockC", "BlockB")),
        0.0,
        3,
    ),
)

#: BlockB and BlockC, each as one request from the state before its first split
WHOLE_ASSEMBLIES: tuple[Experiment, ...] = (
    Experiment(
        "BlockB",
        "BlockB assembly in one request (Tables 5.4-5.6)",
        _BLOCK_B_OBJECTS,
        f"{FIXED_SENTENCES} {_SLEEVES} The BlockA is on the table.",
        "The SnapRing1 is on the workbench. The BearingSleeve1 is on the SnapRing1. "
        "The RecirculatingBallSleeve is on the BearingSleeve1. The BearingSleeve2 is on the "
        "RecirculatingBallSleeve. The SnapRing2 is on the BearingSleeve2.",
        (),
        39.0 + 2.1 + 0.0,
        493 + 343 + 3,
    ),
    Experiment(
        "BlockC",
        "BlockC assembly in one request (Tables 5.8-5.9)",
        _BLOCK_C_OBJECTS,
        f"{FIXED_SENTENCES} The BlockB is on the BlockA.",
        "The UpperBearingBracket is on the BlockC. The Bearing is on the UpperBearingBracket. "
        "The RotatingBalancerSupport is on the Bearing. The TCEIScrew is on the "
        "RotatingBalancerSupport.",
        (),
        699.0 + 0.0,
        5853 + 2,
    ),
)


def experiment(table: str) -> Experiment:
    """The experiment of one table, by its number (``"5.2"``) or assembly name."""
    for exp in EXPERIMENTS + WHOLE_ASSEMBLIES:
        if exp.table == table:
            return exp
    raise KeyError(f"no experiment {table!r}")
