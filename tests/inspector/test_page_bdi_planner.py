"""The inspector's page in a real browser: a BDI agent's intentions, and the planner
given an English goal from the page."""

from __future__ import annotations

from typing import Any

from robocog.experiments.assembly_thesis import experiment
from robocog.experiments.garbage import default_minds, run_once
from robocog.minds.planner_mind import PlannerMind
from robocog.robot.loop import Loop
from robocog.worlds.garbage import GarbageConfig
from robocog.worlds.tabletop import TabletopWorld
from tests.inspector.conftest import browser


@browser
def test_a_bdi_agent_shows_its_intention_stack_and_takes_beliefs(live, page, screenshot) -> None:
    from playwright.sync_api import expect

    def run(inspector: Any) -> None:
        run_once(default_minds(["bdi"])[0], GarbageConfig(), 4, watch=inspector.watcher())

    lv = live(run, paused=True)
    page.goto(lv.url)
    expect(page.locator("#mind-caption")).to_contain_text("BDI")
    expect(page.locator("#loop-state")).to_have_text("paused")
    for _ in range(3):
        before = page.locator("#seq").inner_text().split()[0]
        page.click("#step")
        page.wait_for_function(
            "(s) => document.querySelector('#seq').innerText.split(' ')[0] !== s", arg=before
        )
    frame = page.locator("#intentions .intention .frame").first
    expect(frame).to_contain_text("+!collect", timeout=20_000)
    assert page.locator("#beliefs li").count() > 0, "the belief base is listed"
    expect(page.locator("#beliefs")).to_contain_text("source(percept)")
    # the reply to a post comes late: the line typed meanwhile stays in the input
    page.evaluate(
        """() => {
          window.plainFetch = window.fetch;
          window.fetch = (url, opts) => (opts && opts.method === "POST")
            ? new Promise((ok) => setTimeout(ok, 800)).then(() => window.plainFetch(url, opts))
            : window.plainFetch(url, opts);
        }"""
    )
    page.select_option("#console-kind", "belief")
    page.fill("#console-input", "visited(p9)")
    page.click("#console-send")
    page.select_option("#console-kind", "query")
    page.fill("#console-input", "visited(X)")
    belief = page.locator("#console-log li.ok", has_text="belief visited(p9)")
    expect(belief).to_be_visible(timeout=20_000)
    page.wait_for_timeout(300)  # the post's own reply, after the stream's
    expect(page.locator("#console-input")).to_have_value("visited(X)")
    page.evaluate("() => { window.fetch = window.plainFetch; }")
    page.click("#console-send")
    reply = page.locator("#console-log li", has_text="query visited(X)").locator(".reply")
    expect(reply).to_contain_text("X=p9", timeout=20_000)
    page.select_option("#console-kind", "belief")
    page.fill("#console-input", "visited(p9")
    page.click("#console-send")
    expect(page.locator("#console-log li.error .reply").first).to_contain_text(
        "ParseError: 1:11", timeout=20_000
    )
    screenshot(page)
    page.click("#resume")


@browser
def test_the_planner_plans_and_executes_an_english_goal_typed_in_the_page(
    live, page, screenshot
) -> None:
    from playwright.sync_api import expect

    exp = experiment("5.2")
    world = TabletopWorld(seed=0)
    mind = PlannerMind(facts=exp.facts)

    def run(inspector: Any) -> None:
        loop = Loop(world, mind)
        inspector.watch(world, mind, loop)
        loop.step()  # the perception phase: the tags
        inspector.on_step(None)

    lv = live(run)
    page.goto(lv.url)
    expect(page.locator("#mind-caption")).to_contain_text("PLANNER")
    expect(page.locator("#console-kind")).to_have_value("english")
    # a sentence the reader cannot read: its error, and nothing planned
    page.fill("#console-input", "Put the clamp somewhere nice.")
    page.click("#console-send")
    expect(page.locator("#console-log li.error .reply").first).not_to_be_empty(timeout=20_000)
    page.fill("#console-input", exp.request)
    page.click("#console-send")
    expect(page.locator("#planner-status")).to_have_text("reached", timeout=60_000)
    steps = page.locator("#planner-plan li")
    assert steps.count() >= 2, "the plan is listed step by step"
    expect(page.locator(".cube[data-name='InductionHardenedRod']")).to_have_attribute(
        "data-on", "BettClamp"
    )
    expect(page.locator(".cube[data-name='BettClamp']")).to_have_attribute("data-on", "workbench")
    assert world.holds(("on", "InductionHardenedRod", "BettClamp"))
    # the AtomSpace: find the clamp's node and follow it to the links it is in
    page.fill("#atom-name", "BettClamp")
    page.select_option("#atom-type", "ConceptNode")
    page.click("#atom-search")
    page.locator("#atom-results .atom-link").first.click()
    expect(page.locator("#atom-shown")).to_have_text('(ConceptNode "BettClamp")')
    incoming = page.locator("#atom-results .atom-link")
    expect(incoming.first).to_be_visible()
    page.locator("#atom-results .atom-link", has_text="workbench").first.click()
    expect(page.locator("#atom-shown")).to_have_text(
        '(ListLink (ConceptNode "BettClamp") (ConceptNode "workbench"))'
    )
    page.locator("#atom-results .atom-link", has_text="EvaluationLink").first.click()
    expect(page.locator("#atom-shown")).to_contain_text('(PredicateNode "on")')
    screenshot(page)
