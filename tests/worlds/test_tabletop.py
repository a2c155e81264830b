"""The tabletop: tags, the four arm actions, failed grasps, and merged blocks."""

from __future__ import annotations

import pytest

from robocog.robot import Body, Forward, Gripper, PickUp, PutDown, Stack, Tag, Unstack
from robocog.worlds.tabletop import FIXED_OBJECTS, INITIAL_BINS, TabletopWorld


def names(world: TabletopWorld) -> set[str]:
    return {p.name for p in world.percepts() if isinstance(p, Tag)}


def test_every_object_has_a_tag_and_the_gripper_is_reported() -> None:
    world = TabletopWorld()
    assert isinstance(world, Body)
    assert names(world) == set(FIXED_OBJECTS) | set(INITIAL_BINS)
    ids = [p.id for p in world.percepts() if isinstance(p, Tag)]
    assert len(ids) == len(set(ids))
    assert Gripper(None) in world.percepts()


def test_pickup_and_stack_build_a_stack_on_the_workbench() -> None:
    world = TabletopWorld()
    assert world.execute(PickUp("BettClamp")).ok
    assert world.holds(("in-hand", "BettClamp"))
    assert Gripper("BettClamp") in world.percepts()
    assert world.execute(Stack("BettClamp", "workbench")).ok
    assert world.execute(PickUp("InductionHardenedRod")).ok
    assert world.execute(Stack("InductionHardenedRod", "BettClamp")).ok
    assert world.holds(("on", "InductionHardenedRod", "BettClamp"))
    assert world.below("InductionHardenedRod") == ["BettClamp", "workbench"]
    assert world.time() == pytest.approx(22.0)


def test_preconditions_are_checked_and_a_refused_command_changes_nothing() -> None:
    world = TabletopWorld()
    before = dict(world.on)
    assert "not clear" in world.execute(PickUp("SnapRing2")).reason
    assert "unstack it" in world.execute(PickUp("SnapRing1")).reason
    assert "not on" in world.execute(Unstack("SnapRing1", "GreenBin")).reason
    assert "fixed" in world.execute(PickUp("table")).reason
    assert "no Widget" in world.execute(PickUp("Widget")).reason
    assert "not in the hand" in world.execute(Stack("BettClamp", "table")).reason
    assert "cannot" in world.execute(Forward(1.0)).reason
    assert world.on == before and world.held is None
    assert world.execute(Unstack("SnapRing1", "SnapRing2")).ok
    assert "already holds" in world.execute(PickUp("BettClamp")).reason
    assert "not a fixed object" in world.execute(PutDown("SnapRing1", "BettClamp")).reason
    assert "not clear" in world.execute(Stack("SnapRing1", "BearingSleeve2")).reason
    assert world.execute(PutDown("SnapRing1", "table")).ok


def test_a_chosen_grasp_fails_and_leaves_the_cube_in_place() -> None:
    world = TabletopWorld(fail_grasps={1})
    outcome = world.execute(Unstack("SnapRing1", "SnapRing2"))
    assert not outcome.ok and "slipped" in outcome.reason
    assert world.holds(("on", "SnapRing1", "SnapRing2")) and world.held is None
    assert world.execute(Unstack("SnapRing1", "SnapRing2")).ok
    assert world.failed_grasps == 1


def test_random_grasp_failures_follow_the_rate_and_the_seed() -> None:
    def failures(seed: int) -> list[bool]:
        world = TabletopWorld(seed=seed, grasp_failure=0.3)
        out = []
        for _ in range(200):
            ok = world.execute(PickUp("BettClamp")).ok
            out.append(not ok)
            if ok:
                world.execute(PutDown("BettClamp", "BlueBin"))
        return out

    first = failures(4)
    assert first == failures(4)
    assert 0.2 < sum(first) / len(first) < 0.4
    with pytest.raises(ValueError):
        TabletopWorld(grasp_failure=1.0)


def test_a_finished_stack_becomes_one_block_where_it_stood() -> None:
    world = TabletopWorld()
    for command in (
        PickUp("BettClamp"),
        Stack("BettClamp", "workbench"),
        PickUp("InductionHardenedRod"),
        Stack("InductionHardenedRod", "BettClamp"),
    ):
        assert world.execute(command).ok
    world.replace_with_block(["InductionHardenedRod", "BettClamp"], "BlockA")
    assert world.holds(("on", "BlockA", "workbench"))
    assert "BettClamp" not in names(world) and "BlockA" in names(world)
    assert names(world) >= {"SnapRing1", "SnapRing2", "BearingSleeve1", "BearingSleeve2"}
    ids = [p.id for p in world.percepts() if isinstance(p, Tag)]
    assert len(ids) == len(set(ids))
    with pytest.raises(ValueError):
        world.replace_with_block(["SnapRing2"], "BlockX")  # SnapRing1 stands on it


def test_parts_can_be_brought_in_and_unknown_supports_are_refused() -> None:
    world = TabletopWorld(parts={})
    world.add_parts({"B": "A", "A": "table"})
    assert world.below("B") == ["A", "table"]
    with pytest.raises(ValueError):
        world.add_parts({"C": "nowhere"})
    with pytest.raises(ValueError):
        world.add_parts({"A": "table"})
