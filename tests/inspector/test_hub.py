"""The inspector's side of the loop: snapshots per cycle, commands applied between
cycles in the robot's thread, pause and step."""

from __future__ import annotations

import json
import threading
import time

import pytest

from robocog.experiments.garbage import default_minds, learn_accumulation, run_once
from robocog.inspector.hub import MAX_INPUT, MAX_QUEUED, Inspector
from robocog.inspector.snapshot import dumps
from robocog.minds.bdi_mind import BdiMind
from robocog.robot.loop import Loop
from robocog.worlds.garbage import GarbageConfig, GarbageField


def bdi_loop(inspector: Inspector, seed: int = 1) -> tuple[GarbageField, BdiMind, Loop]:
    world = GarbageField(GarbageConfig(), seed=seed)
    mind = BdiMind()
    loop = Loop(world, mind)
    return world, mind, loop


def test_every_cycle_is_snapshotted_and_serialisable() -> None:
    ins = Inspector(world_budget=None)
    world, mind, loop = bdi_loop(ins)
    hook = ins.watch(world, mind, loop)
    ran = loop.run(40, on_step=hook)
    first, last = ins.history.bounds()
    assert last - first + 1 == ran + 1  # the snapshot at watch time, then one per cycle
    snap = ins.history.latest()
    assert snap.world["kind"] == "garbage" and snap.mind["kind"] == "bdi"
    assert snap.world["robot"]["x"] == round(world.x, 2)
    assert "cycle_ms" in snap.stats
    shown = {d["instance"] for d in json.loads(dumps(snap.to_json()))["world"]["detections"]}
    # what the mind saw is what the snapshot shows
    assert shown == {p.instance for p in loop.body.last if hasattr(p, "instance")}


def test_commands_are_applied_in_the_robot_thread_between_cycles() -> None:
    ins = Inspector()
    world, mind, loop = bdi_loop(ins)
    hook = ins.watch(world, mind, loop)
    threads: list[int] = []
    real = mind.agent.add_belief

    def add_belief(b: str) -> None:
        threads.append(threading.get_ident())
        real(b)

    mind.agent.add_belief = add_belief  # type: ignore[method-assign]
    entry = ins.submit("belief", "visited(p9)")
    assert entry["status"] == "queued"
    assert mind.beliefs("visited") == [], "nothing happens before the loop takes it"
    runner = threading.Thread(target=loop.run, args=(3,), kwargs={"on_step": hook})
    runner.start()
    runner.join()
    assert threads == [runner.ident]
    assert mind.beliefs("visited") == ["visited(p9)[source(self)]"]
    done = ins.console_entries()[-1]
    assert done["status"] == "ok" and done["cycle"] == 1


def test_a_bad_line_gets_the_parser_error_and_the_mind_goes_on() -> None:
    ins = Inspector()
    world, mind, loop = bdi_loop(ins)
    hook = ins.watch(world, mind, loop)
    ins.submit("goal", "collect(")
    ins.submit("query", "trash(X)")
    loop.run(5, on_step=hook)
    bad, good = ins.console_entries()
    assert bad["status"] == "error" and "ParseError: 1:9" in bad["reply"]
    assert good["status"] == "ok" and good["reply"] == "X=bottle; X=cup"
    assert loop.cycles == 5


def test_console_input_is_bounded() -> None:
    ins = Inspector()
    with pytest.raises(ValueError, match="unknown command"):
        ins.submit("eval", "1")
    with pytest.raises(ValueError, match="at most"):
        ins.submit("tell", "x" * (MAX_INPUT + 1))
    for _ in range(MAX_QUEUED):
        ins.submit("tell", "<a --> b>.")
    with pytest.raises(ValueError, match="too many"):
        ins.submit("tell", "<a --> b>.")


def test_pause_holds_the_loop_and_step_lets_one_cycle_through() -> None:
    ins = Inspector()
    world, mind, loop = bdi_loop(ins)
    hook = ins.watch(world, mind, loop)
    ins.submit("pause")
    runner = threading.Thread(target=loop.run, args=(50,), kwargs={"on_step": hook})
    runner.start()
    time.sleep(0.3)
    assert loop.cycles == 1, "paused after the first cycle"
    ins.submit("step")
    ins.submit("step")
    deadline = time.time() + 10
    while loop.cycles < 3 and time.time() < deadline:
        time.sleep(0.01)
    time.sleep(0.2)
    assert loop.cycles == 3
    # while paused, questions are still answered (and a snapshot taken after them)
    before = ins.history.bounds()[1]
    ins.submit("query", "trash(cup)")
    deadline = time.time() + 10
    while ins.console_entries()[-1]["status"] == "queued" and time.time() < deadline:
        time.sleep(0.01)
    assert ins.console_entries()[-1]["reply"] == "yes"
    assert ins.history.bounds()[1] == before + 1
    assert loop.cycles == 3
    ins.submit("resume")
    runner.join(timeout=30)
    assert loop.cycles == 50


def test_a_fast_loop_is_sampled_within_the_budget() -> None:
    ins = Inspector(world_budget=0.01)  # snapshots may cost 1% of the time
    world, mind, loop = bdi_loop(ins)
    hook = ins.watch(world, mind, loop)
    loop.run(1000, on_step=hook)
    first, last = ins.history.bounds()
    assert 1 <= last - first < 1000, "some cycles were taken, not every one"
    cycles = [s.cycle for s in ins.history.all()]
    assert cycles == sorted(cycles) and cycles[-1] <= 1000
    ins.submit("query", "trash(cup)")
    loop.run(1, on_step=hook)
    assert ins.history.latest().cycle == 1001, "a cycle after a command is always taken"


def test_close_lets_a_paused_loop_go() -> None:
    ins = Inspector()
    world, mind, loop = bdi_loop(ins)
    hook = ins.watch(world, mind, loop)
    ins.submit("pause")
    runner = threading.Thread(target=loop.run, args=(10,), kwargs={"on_step": hook})
    runner.start()
    time.sleep(0.2)
    ins.close()
    runner.join(timeout=10)
    assert not runner.is_alive()


def test_the_experiments_hand_their_loops_to_the_inspector() -> None:
    ins = Inspector(capacity=10_000)
    run_once(default_minds(["bdi"])[0], GarbageConfig(), 3, watch=ins.watcher())
    assert ins.run_label == "run 1: BDI"
    assert ins.history.latest().world["done"]


@pytest.mark.slow
def test_nars_views_show_the_checkpoint_hypotheses_as_they_form() -> None:
    ins = Inspector(capacity=10_000, min_mind_interval=0.0, mind_budget=1.0)
    learn_accumulation(default_minds(["nars"])[0], GarbageConfig(), 2, 2, watch=ins.watcher())
    minds = [s.mind for s in ins.history.all() if s.mind_seq == s.seq]
    assert all(m["kind"] == "nars" for m in minds)
    last = minds[-1]
    assert last["concepts"] and last["concepts"][0]["priority"] >= last["concepts"][-1]["priority"]
    assert last["hypotheses"], "some checkpoint has a hypothesis after two rounds"
    place, row = next(iter(last["hypotheses"].items()))
    assert row["term"] == f"<<({{SELF}} * {{{place}}}) --> at> =/> <trash --> [see]>>"
    # the same evidence the mind's own question finds
    asked = {p: (f, c) for p, f, c, _e in ins.mind.trash_places()}
    assert (row["f"], row["c"]) == tuple(round(x, 3) for x in asked[place])
    assert 0 < row["c"] < 1
    confidences = {m["hypotheses"][place]["c"] for m in minds if place in m["hypotheses"]}
    assert len(confidences) > 1, "the hypothesis's confidence changed while the robot collected"
    assert any("desire" in d for d in last["decisions"]), "decisions come with their desire"
    assert last["threshold"] == pytest.approx(0.501)
