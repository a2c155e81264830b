"""The minds' registry: every shipped mind is made from a MindConfig, by name."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocog.minds import registry
from robocog.minds.registry import MindConfig, MindUnavailable
from robocog.robot.protocols import Mind

KINDS = {
    "nars": "NarsMind",
    "bdi": "BdiMind",
    "qbo": "QboBdiMind",
    "qbo-reference": "ReachExitReference",
    "planner": "PlannerMind",
}


def test_every_shipped_mind_is_registered() -> None:
    assert set(KINDS) | {"ona"} == set(registry.names())


@pytest.mark.parametrize("name", sorted(KINDS))
def test_each_mind_is_made_from_its_config(name: str) -> None:
    mind = registry.make(MindConfig(name, seed=3, places=("p0", "p1")))
    assert type(mind).__name__ == KINDS[name]
    assert isinstance(mind, Mind)


def test_a_nars_mind_takes_the_seed_places_options_and_knowledge(tmp_path: Path) -> None:
    knowledge = tmp_path / "k.nal"
    knowledge.write_text("<bottle --> trash>.\n\n<can --> trash>.\n")
    config = MindConfig("nars", 7, knowledge, ("p0", "p1"), {"cycles_per_frame": 4})
    mind = registry.make(config)
    assert mind.places == ["p0", "p1"]  # type: ignore[attr-defined]
    assert mind.settings.seed == 7 and mind.settings.cycles_per_frame == 4  # type: ignore[attr-defined]
    # the operations' slots, the babbling switch, then the file's two lines
    assert mind.inputs == 6 + 1 + 2  # type: ignore[attr-defined]


def test_a_bdi_mind_runs_the_program_it_is_given(tmp_path: Path) -> None:
    program = tmp_path / "p.asl"
    program.write_text("ready.\n")
    mind = registry.make(MindConfig("bdi", source=program))
    assert mind.beliefs("ready") == ["ready[source(self)]"]  # type: ignore[attr-defined]


def test_a_planner_takes_its_options() -> None:
    mind = registry.make(MindConfig("planner", options={"mode": "first", "max_replans": 2}))
    assert (mind.mode, mind.max_replans) == ("first", 2)  # type: ignore[attr-defined]


def test_a_mind_of_ones_own_gets_the_config() -> None:
    mind = registry.make(MindConfig("tests.minds.test_registry:echo", seed=11))
    assert mind.config.seed == 11  # type: ignore[attr-defined]


class _Echo:
    def __init__(self, config: MindConfig) -> None:
        self.config = config

    def perceive(self, percepts: object) -> None: ...

    def decide(self) -> list[object]:
        return []

    def on_outcome(self, command: object, outcome: object) -> None: ...


def echo(config: MindConfig) -> _Echo:
    """A factory of one's own: the registry calls it with the MindConfig."""
    return _Echo(config)


@pytest.mark.parametrize(
    ("name", "message"),
    [
        ("marvin", "unknown mind 'marvin': use nars, "),
        ("tests.minds.test_registry:nothing", "has no nothing"),
        ("no_such_module_anywhere:make", "not available"),
    ],
)
def test_an_unknown_mind_is_a_clear_error(name: str, message: str) -> None:
    with pytest.raises(MindUnavailable, match=message):
        registry.make(MindConfig(name))


def test_a_name_is_registered_once() -> None:
    with pytest.raises(ValueError, match="registered already"):
        registry.register("nars", "again")(registry.make_nars)


def test_the_probes_say_why_or_nothing() -> None:
    assert registry.probe("qbo-reference") is None
    why = registry.probe("ona")
    assert why is None or "ONA" in why or "NAR" in why
