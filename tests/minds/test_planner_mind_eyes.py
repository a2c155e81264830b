"""PlannerMind with perceive_scene: it plans from what a body reports resting on what,
and plans again when a look shows something the plan did not predict."""

from __future__ import annotations

from robocog.experiments.assembly_thesis import experiment
from robocog.minds.planner_mind import PlannerMind
from robocog.robot import Percept, PickUp, Resting
from robocog.robot.loop import Loop
from robocog.worlds.tabletop import TabletopWorld


class SeeingTabletop(TabletopWorld):
    """The symbolic tabletop reporting what each cube rests on, as a camera would."""

    def percepts(self) -> list[Percept]:
        return [*super().percepts(), *(Resting(top, below) for top, below in self.on.items())]


def test_a_cube_moved_by_hand_is_seen_and_the_mind_plans_around_it() -> None:
    world = SeeingTabletop()
    mind = PlannerMind(perceive_scene=True)
    loop = Loop(world, mind)
    record = mind.request(
        "The InductionHardenedRod is on the BettClamp.", facts=experiment("5.2").facts
    )
    loop.step()  # plans from the look, and picks the rod up
    assert world.held == "InductionHardenedRod"
    assert [str(s) for s in record.first_plan.steps][0].startswith("(pickup")
    # someone sets the SnapRing1 on the clamp while the rod is in the hand
    world.on["SnapRing1"] = "BettClamp"
    loop.run(20, until=lambda: not mind.busy)
    assert record.status == "reached"
    assert record.replans == 1
    assert record.failures == ["seen: the SnapRing1 is on the BettClamp, not on the SnapRing2"]
    assert world.holds(("on", "InductionHardenedRod", "BettClamp"))
    assert any(e.command == PickUp("InductionHardenedRod") for e in world.log[1:])


def test_the_last_step_is_confirmed_by_a_look_and_parts_in_bins_rest_where_found() -> None:
    world = SeeingTabletop()
    mind = PlannerMind(perceive_scene=True)
    loop = Loop(world, mind)
    exp = experiment("5.2")
    record = mind.request(exp.request, facts=exp.facts)
    loop.run(20, until=lambda: not mind.busy)
    assert record.status == "reached" and record.replans == 0
    # the same plan as the thesis: parts in their bins are picked up, not unstacked
    assert tuple(record.first_plan.lines()) == exp.plan
    assert len(world.log) == 4 and loop.cycles == 5  # the fifth look confirms the goal


def test_without_eyes_the_mind_does_not_see_what_blocks_it() -> None:
    """The default mind plans from its own bookkeeping: it retries the same stack."""
    world = SeeingTabletop()
    mind = PlannerMind()
    loop = Loop(world, mind)
    record = mind.request(
        "The InductionHardenedRod is on the BettClamp.", facts=experiment("5.2").facts
    )
    loop.step()
    world.on["SnapRing1"] = "BettClamp"
    loop.run(20, until=lambda: not mind.busy)
    assert record.status != "reached" and record.replans >= 10
    assert all(f.endswith("the BettClamp is not clear") for f in record.failures)
