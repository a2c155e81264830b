"""Every mind robocog ships, by name, made through one signature: ``make(config) -> Mind``.

The bridges, the experiments and the command line all build their minds here, so a
mind is added in one place (a factory decorated with :func:`register`) and is then
offered everywhere a ``--mind`` is. A :class:`MindConfig` says everything a factory may
use: the name, the seed, a source file (Narsese knowledge or an AgentSpeak program),
the robot's named places, and options of that mind's own.

A factory imports its mind's module, and so its engine, only when it is called:
importing the registry loads no engine. That is what lets the bridges, which know no
engine, name their mind through it (``tests/test_layering.py`` holds that rule).

A name ``module:factory`` outside the registry is a mind of the user's own: its
factory is called with the same :class:`MindConfig`.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from robocog.robot.protocols import Mind


class MindUnavailable(RuntimeError):
    """The mind asked for is unknown or cannot be built in this installation."""


@dataclass(frozen=True)
class MindConfig:
    """What a factory makes a mind from.

    ``source`` is the mind's knowledge (Narsese lines) or program (AgentSpeak) in place
    of the one robocog ships; ``places`` are the robot's named places in route order (a
    NARS mind's checkpoints); ``options`` are keyword settings of the mind itself (a
    NARS mind's :class:`~robocog.minds.nars_mind.NarsSettings` fields, a planner's
    ``mode``), each factory saying which it takes.
    """

    name: str
    seed: int = 0
    source: Path | None = None
    places: tuple[str, ...] = ()
    options: Mapping[str, Any] = field(default_factory=dict)

    def text(self) -> str | None:
        """The source file's text, or None without one."""
        return None if self.source is None else self.source.read_text(encoding="utf-8")

    def lines(self) -> list[str] | None:
        """The source file's non-blank lines (Narsese is read a line at a time)."""
        text = self.text()
        return None if text is None else [line for line in text.splitlines() if line.strip()]


Factory = Callable[[MindConfig], Mind]


@dataclass(frozen=True)
class Entry:
    """One registered mind: how to make it, and how to ask whether it can run here."""

    name: str
    make: Factory
    summary: str
    #: why the mind cannot run in this installation, or None (runs a small trial)
    probe: Callable[[], str | None]


#: name -> entry, in the order registered (the order ``--mind`` help lists them)
REGISTRY: dict[str, Entry] = {}


def register(
    name: str, summary: str, probe: Callable[[], str | None] | None = None
) -> Callable[[Factory], Factory]:
    """Register the decorated factory as the mind ``name``."""

    def add(factory: Factory) -> Factory:
        if name in REGISTRY:
            raise ValueError(f"a mind named {name!r} is registered already")
        REGISTRY[name] = Entry(name, factory, summary, probe or (lambda: None))
        return factory

    return add


def names() -> tuple[str, ...]:
    """The registered minds' names."""
    return tuple(REGISTRY)


def make(config: MindConfig) -> Mind:
    """The mind ``config.name`` (a registered name or ``module:factory``), made from ``config``.

    A mind whose engine is missing from this build, or a name that is neither, raises
    :class:`MindUnavailable`; what a factory itself raises (a program the engine
    refuses) passes through unchanged.
    """
    entry = REGISTRY.get(config.name)
    if entry is not None:
        try:
            return entry.make(config)
        except ImportError as exc:
            raise MindUnavailable(f"mind {config.name!r} is not available: {exc}") from exc
    return _user_factory(config.name)(config)


def probe(name: str) -> str | None:
    """Why the registered mind ``name`` cannot run here, or None when it can."""
    return REGISTRY[name].probe()


def _user_factory(name: str) -> Factory:
    module_name, colon, attr = name.partition(":")
    if not colon:
        known = ", ".join(REGISTRY)
        raise MindUnavailable(f"unknown mind {name!r}: use {known} or module:factory")
    try:
        module = importlib.import_module(module_name)
    except ImportError as exc:
        raise MindUnavailable(f"mind {name!r} is not available: {exc}") from exc
    factory = getattr(module, attr, None)
    if not callable(factory):
        raise MindUnavailable(f"mind {name!r} is not available: {module_name} has no {attr}")
    return factory


def _probe_import(engine: str, module: str, check: Callable[[Any], str | None]) -> str | None:
    try:
        loaded = importlib.import_module(module)
    except Exception as exc:  # an engine under construction may fail to import in any way
        return f"{engine} cannot be imported: {type(exc).__name__}: {exc}"
    return check(loaded)


# ---- the minds robocog ships ------------------------------------------------------------


@register(
    "nars",
    "NARS (Hammer et al.): robocog's reasoner on the garbage channels",
    lambda: _probe_import("the NARS engine", "robocog.minds.nars_mind", lambda m: m.probe()),
)
def make_nars(config: MindConfig) -> Mind:
    """NarsMind over the robot's places; ``options`` are NarsSettings fields."""
    from robocog.minds.nars_mind import NarsMind, NarsSettings

    settings = NarsSettings(seed=config.seed, **config.options)
    return NarsMind(list(config.places), settings, config.lines())


@register(
    "ona",
    "NarsMind with ONA 0.9.2 as its reasoner (the peer; needs ONA's NAR command)",
    lambda: _probe_import("the ONA adapter", "robocog.minds.ona_shell", lambda m: m.unavailable()),
)
def make_ona(config: MindConfig) -> Mind:
    """NarsMind driving ONA's ``NAR shell``, with the knowledge in the form ONA reads."""
    from robocog.minds.nars_mind import NarsMind, NarsSettings
    from robocog.minds.ona_shell import OnaShell, ona_knowledge

    settings = NarsSettings(seed=config.seed, **config.options)
    knowledge = config.lines()
    return NarsMind(
        list(config.places),
        settings,
        ona_knowledge() if knowledge is None else knowledge,
        nar=OnaShell(),  # type: ignore[arg-type]
    )


@register(
    "bdi",
    "AgentSpeak (Jason) agent: the paper's BDI baseline on the garbage channels",
    lambda: _probe_import("the AgentSpeak engine", "robocog.minds.bdi_mind", lambda m: m.probe()),
)
def make_bdi(config: MindConfig) -> Mind:
    """BdiMind running the source program, or the shipped one; ``options`` are its keywords."""
    from robocog.minds.bdi_mind import BdiMind

    return BdiMind(config.text(), **config.options)


@register("qbo", "the Q.bo leaving a room (Fujita et al.): Figs. 6-8 run by AgentSpeak")
def make_qbo(config: MindConfig) -> Mind:
    """QboBdiMind running the source program, or Figs. 6-8 with ``!reach_exit``."""
    from robocog.minds.qbo import QboBdiMind, reach_exit_program

    text = config.text()
    return QboBdiMind(reach_exit_program() if text is None else text)


@register("qbo-reference", "Figs. 6-8 transcribed into Python: the Q.bo's control run")
def make_qbo_reference(config: MindConfig) -> Mind:
    """ReachExitReference, which needs no engine."""
    from robocog.minds.qbo import ReachExitReference

    return ReachExitReference()


@register("planner", "AtomSpace task planner for the manipulator (Thiella 2021)")
def make_planner(config: MindConfig) -> Mind:
    """PlannerMind with the source's sentences as its facts; ``options`` are its keywords
    (``mode``, ``perceive_scene``, ``max_replans``)."""
    from robocog.minds.planner_mind import PlannerMind

    return PlannerMind(facts=config.text() or "", **config.options)
