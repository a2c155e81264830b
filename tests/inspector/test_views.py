"""What the inspector shows of worlds and minds, read without the page."""

from __future__ import annotations

import json

from robocog.experiments.assembly_thesis import experiment
from robocog.inspector.snapshot import dumps
from robocog.inspector.views import (
    BdiView,
    NarsView,
    PlannerView,
    garbage_view,
    mind_viewer,
    stacks,
    tabletop_view,
    thin,
)
from robocog.minds.bdi_mind import BdiMind
from robocog.minds.nars_mind import NarsMind
from robocog.minds.planner_mind import PlannerMind
from robocog.robot.loop import Loop
from robocog.robot.percepts import Detection
from robocog.worlds.garbage import GarbageConfig, GarbageField
from robocog.worlds.tabletop import TabletopWorld


def test_a_long_path_is_thinned_but_keeps_its_newest_points() -> None:
    path = [(float(i), 0.0) for i in range(1000)]
    out = thin(path, 300)
    assert len(out) <= 300
    assert out[0] == [0.0, 0.0] and out[-100:] == [[float(i), 0.0] for i in range(900, 1000)]
    assert thin(path[:5]) == [[float(i), 0.0] for i in range(5)]


def test_the_garbage_view_is_the_field_now() -> None:
    world = GarbageField(GarbageConfig(), seed=1)
    seen = Detection("bottle", 0.1, 1.5, 0.8, "bottle3")
    view = json.loads(dumps(garbage_view(world, [seen])))
    assert view["size"] == 22.0 and len(view["checkpoints"]) == 8
    hot = {c["name"]: c["hot"] for c in view["checkpoints"]}
    assert hot["p2"] == 4.0 and hot["p0"] == 1.0
    assert len(view["objects"]) == len(world.objects(1))
    assert view["detections"] == [
        {
            "label": "bottle",
            "instance": "bottle3",
            "bearing": 0.1,
            "distance": 1.5,
            "confidence": 0.8,
        }
    ]
    assert view["robot"] == {"x": 1.5, "y": 20.5, "theta": round(world.theta, 3)}


def test_stacks_are_read_bottom_to_top_on_each_fixed_object() -> None:
    on = {"a": "table", "b": "a", "c": "b", "d": "table", "e": "bin"}
    assert stacks(on, ["table", "bin", "shelf"]) == {
        "table": [["a", "b", "c"], ["d"]],
        "bin": [["e"]],
        "shelf": [],
    }


def test_the_tabletop_view_shows_the_bins_and_what_stands_on_them() -> None:
    world = TabletopWorld()
    view = tabletop_view(world)
    assert view["stacks"]["PurpleBin"] == [["SnapRing2", "SnapRing1"]]
    assert view["held"] is None and "table" in view["fixed"]


def test_each_mind_gets_its_view() -> None:
    assert isinstance(mind_viewer(NarsMind(["p0"])), NarsView)
    assert isinstance(mind_viewer(BdiMind()), BdiView)
    assert isinstance(mind_viewer(PlannerMind()), PlannerView)
    assert mind_viewer(object()) is None


def test_the_nars_view_taps_the_output_and_gives_it_back() -> None:
    mind = NarsMind(["p0"])
    lines: list[str] = []
    mind.nar.output = lines.append
    view = NarsView(mind.nar, mind)
    mind.nar.add_input("<a --> b>.")
    assert lines and lines[-1].startswith("Input: <a --> b>.")
    view.detach()
    assert mind.nar.output == lines.append
    assert view.command("ask", "<a --> b>?").startswith("Answer: <a --> b>. Truth: frequency=1.0")
    assert view.command("tell", "<c --> d>?") == "Answer: None."


def test_the_bdi_view_shows_intentions_as_stacks() -> None:
    world = GarbageField(GarbageConfig(), seed=1)
    mind = BdiMind()
    Loop(world, mind).run(3)
    view = BdiView(mind.agent, mind).view()
    json.dumps(view)
    assert any(b.startswith("trash(bottle)") for b in view["beliefs"])
    tops = [i["stack"][0]["trigger"] for i in view["intentions"]]
    assert any("collect" in t for t in tops)


def test_the_planner_view_follows_the_plan_step_by_step() -> None:
    exp = experiment("5.2")
    world = TabletopWorld()
    mind = PlannerMind(facts=exp.facts)
    view = PlannerView(mind)
    loop = Loop(world, mind)
    loop.step()
    assert view.command("english", exp.request).startswith("goal: on BettClamp workbench")
    loop.step()
    v = view.view()
    assert v["request"]["status"] == "executing" and v["step"] == 1 and len(v["plan"]) == 4
    loop.run(10, until=lambda: not mind.busy)
    v = view.view()
    assert v["request"]["status"] == "reached" and v["step"] == 4
    assert v["scene"]["on"]["InductionHardenedRod"] == "BettClamp"


def test_the_room_exit_run_is_shown_with_its_walls_and_path() -> None:
    from robocog.experiments.room_exit import run_once
    from robocog.inspector.hub import Inspector

    ins = Inspector()
    run_once(3, "bdi", watch=ins.watcher())
    ins.finish()
    last = ins.history.latest()
    dumps(last.to_json())
    world = last.world
    assert world["kind"] == "room" and len(world["walls"]) >= 7
    assert {t["id"] for t in world["targets"]} == {"door", "opposite_door", "doorway"}
    assert len(world["trajectory"]) > 5
    assert last.mind["kind"] == "bdi" and last.mind_seq == last.seq
    assert any(b.startswith("found_target(") for b in last.mind["beliefs"])
