"""The inspector's page in a real browser, on the garbage field with NARS."""

from __future__ import annotations

import re
from typing import Any

import pytest

from robocog.experiments.garbage import MindSpec, default_minds, learn_accumulation
from robocog.worlds.garbage import GarbageConfig
from tests.inspector.conftest import browser


def nars_spec() -> MindSpec:
    return default_minds(["nars"])[0]


def rounds(n: int, seed: int = 2) -> Any:
    """A run of ``n`` learning rounds of NARS on one field, hooked by the inspector."""

    def run(inspector: Any) -> None:
        learn_accumulation(nars_spec(), GarbageConfig(), seed, n, watch=inspector.watcher())

    return run


def seq_of(page: Any) -> int:
    return int(page.locator("#seq").inner_text().split()[0])


@browser
def test_the_robot_moves_on_the_map_and_pause_and_step_work(live, page, screenshot) -> None:
    lv = live(rounds(1), paused=True)
    page.goto(lv.url)
    page.wait_for_selector("#robot")
    from playwright.sync_api import expect

    expect(page.locator("#loop-state")).to_have_text("paused")
    start = (
        page.locator("#robot").get_attribute("data-x"),
        page.locator("#robot").get_attribute("data-y"),
    )
    first = seq_of(page)
    page.click("#step")
    expect(page.locator("#seq")).to_contain_text(f"{first + 1} (")
    page.click("#step")
    expect(page.locator("#seq")).to_contain_text(f"{first + 2} (")
    page.wait_for_timeout(600)
    assert seq_of(page) == first + 2, "a step runs one cycle and pauses again"
    expect(page.locator("#loop-state")).to_have_text("paused")
    page.click("#resume")
    expect(page.locator("#loop-state")).to_have_text(re.compile("running|paused"))
    page.wait_for_function(
        "([x, y]) => { const r = document.querySelector('#robot');"
        " return r && (r.dataset.x !== x || r.dataset.y !== y); }",
        arg=list(start),
        timeout=60_000,
    )
    points = page.locator("#trajectory").get_attribute("points")
    assert points is not None and len(points.split()) > 2, "the path the robot took is drawn"
    screenshot(page)


@pytest.mark.slow
@browser
def test_a_checkpoint_hypothesis_gains_confidence_over_rounds(live, page, screenshot) -> None:
    lv = live(rounds(3), mind_interval=0.02)  # a view of the mind every few cycles
    page.goto(lv.url)
    lv.thread.join(timeout=0)  # the loop goes on while the page follows it
    page.wait_for_function(
        "() => document.querySelectorAll('#hypotheses tr[data-place]').length > 0", timeout=120_000
    )
    # let the three rounds end (the loop then waits for the page's commands)
    page.wait_for_function(
        "() => /round:\\s*3/.test(document.querySelector('#world-facts').innerText)",
        timeout=180_000,
    )
    page.wait_for_timeout(2500)
    assert page.locator("#hypotheses tr[data-place]").count() > 0
    # each checkpoint's confidence, read at points of the timeline: which checkpoints
    # a round's visits reach first depends on the field, so any of them may be the one
    # whose hypothesis the page shows changing
    lo = int(page.locator("#timeline").get_attribute("min"))
    hi = int(page.locator("#timeline").get_attribute("max"))
    seen: dict[str, set[str]] = {}
    for k in range(0, 17):
        seq = lo + (hi - lo) * k // 16
        page.evaluate(
            "(v) => { const t = document.querySelector('#timeline'); t.value = v;"
            " t.dispatchEvent(new Event('input')); }",
            seq,
        )
        page.wait_for_function(
            "(v) => document.querySelector('#seq').innerText.startsWith(v + ' ')", arg=seq
        )
        rows = page.locator("#hypotheses tr[data-place]")
        for i in range(rows.count()):
            row = rows.nth(i)
            cell = row.locator("td.c")
            if cell.count():
                seen.setdefault(row.get_attribute("data-place"), set()).add(cell.inner_text())
    changed = sorted(p for p, values in seen.items() if len(values) > 1)
    assert changed, f"no checkpoint's confidence changed over the rounds: {seen}"
    # the chart of confidences has a line for such a checkpoint
    page.click("#follow")
    page.wait_for_selector(f"#chart-hyp polyline[data-name='{changed[0]}']", timeout=10_000)
    screenshot(page)


@pytest.mark.slow
@browser
def test_a_question_typed_in_the_console_gets_its_answer(live, page, screenshot) -> None:
    lv = live(rounds(1))
    page.goto(lv.url)
    from playwright.sync_api import expect

    def tell(line: str) -> None:
        page.select_option("#console-kind", "tell")
        page.fill("#console-input", line)
        page.click("#console-send")
        reply = page.locator("#console-log li.ok", has_text=f"tell {line}").first
        expect(reply).to_be_visible(timeout=60_000)

    tell("<{bottle9} --> bottle>.")
    tell("20")  # cycles to derive in, whether the robot's loop still runs or not
    page.select_option("#console-kind", "ask")
    page.fill("#console-input", "<{bottle9} --> trash>?")
    page.click("#console-send")
    answer = page.locator("#console-log li", has_text="<{bottle9} --> trash>?").locator(".reply")
    expect(answer).to_contain_text("Answer: <{bottle9} --> trash>.", timeout=60_000)
    expect(answer).to_contain_text("confidence=")
    # a line the reader cannot read gets the reader's error, and the mind goes on
    page.select_option("#console-kind", "tell")
    page.fill("#console-input", "<bottle --> >.")
    page.click("#console-send")
    bad = page.locator("#console-log li.error .reply").first
    expect(bad).to_contain_text("NarseseError", timeout=60_000)
    expect(bad).to_contain_text("column")
    before = page.locator("#seq").inner_text()
    page.select_option("#console-kind", "ask")
    page.fill("#console-input", "<bottle --> trash>?")
    page.click("#console-send")
    expect(
        page.locator("#console-log li", has_text="<bottle --> trash>?").locator(".reply")
    ).to_contain_text("Answer: <bottle --> trash>.", timeout=60_000)
    assert page.locator("#concepts tr").count() > 1, "the concepts are listed"
    assert before
    screenshot(page)
