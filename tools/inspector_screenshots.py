"""Make the screenshots of docs/inspector.md: the inspector on each world and mind.

Needs the inspect extra, Playwright's Python package and a chromium (Debian's:
``apt-get install chromium``):

    python tools/inspector_screenshots.py            # writes docs/img/inspector-*.png
"""

from __future__ import annotations

import argparse
import shutil
import threading
from pathlib import Path
from typing import Any

from robocog.experiments.assembly_thesis import experiment
from robocog.experiments.garbage import default_minds, learn_accumulation, run_once
from robocog.experiments.room_exit import run_once as room_run
from robocog.inspector.hub import Inspector
from robocog.inspector.server import InspectorServer
from robocog.minds.planner_mind import PlannerMind
from robocog.robot.loop import Loop
from robocog.worlds.garbage import GarbageConfig
from robocog.worlds.tabletop import TabletopWorld

OUT = Path(__file__).resolve().parents[1] / "docs" / "img"


def serve(run: Any, paused: bool = False) -> tuple[Inspector, InspectorServer, threading.Thread]:
    inspector = Inspector()
    server = InspectorServer(inspector, port=0)
    server.start()
    if paused:
        inspector.submit("pause")

    def body() -> None:
        run(inspector)
        inspector.linger()

    thread = threading.Thread(target=body, daemon=True)
    thread.start()
    return inspector, server, thread


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=args.chromium)
        page = browser.new_page(viewport={"width": 1360, "height": 940})

        def shot(name: str) -> None:
            page.screenshot(path=str(args.out / f"inspector-{name}.png"))
            print(args.out / f"inspector-{name}.png")

        # NARS learning where trash is seen, three rounds; a question asked at the end
        nars = default_minds(["nars"])[0]
        ins, server, thread = serve(
            lambda i: learn_accumulation(nars, GarbageConfig(), 2, 3, watch=i.watcher())
        )
        page.goto(server.url)
        page.wait_for_function(
            "() => /round:\\s*3/.test(document.querySelector('#world-facts').innerText)",
            timeout=300_000,
        )
        page.select_option("#console-kind", "ask")
        page.fill("#console-input", "<<({SELF} * {?1}) --> at> =/> <trash --> [see]>>?")
        page.click("#console-send")
        page.wait_for_selector("#console-log li.ok", timeout=60_000)
        page.wait_for_timeout(2500)
        shot("nars")
        ins.close()
        server.stop()

        # the BDI agent, paused a few cycles in
        bdi = default_minds(["bdi"])[0]
        ins, server, thread = serve(
            lambda i: run_once(bdi, GarbageConfig(), 4, watch=i.watcher()), paused=True
        )
        page.goto(server.url)
        for _ in range(12):
            page.click("#step")
            page.wait_for_timeout(120)
        page.select_option("#console-kind", "query")
        page.fill("#console-input", "trash(X)")
        page.click("#console-send")
        page.wait_for_timeout(1500)
        shot("bdi")
        ins.close()
        server.stop()

        # the planner given Table 5.2's request from the page
        exp = experiment("5.2")
        world, mind = TabletopWorld(), PlannerMind(facts=exp.facts)

        def tabletop(i: Inspector) -> None:
            loop = Loop(world, mind)
            i.watch(world, mind, loop)
            loop.step()
            i.on_step(None)

        ins, server, thread = serve(tabletop)
        page.goto(server.url)
        page.fill("#console-input", exp.request)
        page.click("#console-send")
        page.wait_for_function(
            "() => document.querySelector('#planner-status')?.innerText === 'reached'"
        )
        page.fill("#atom-name", "BettClamp")
        page.select_option("#atom-type", "ConceptNode")
        page.click("#atom-search")
        page.locator("#atom-results .atom-link").first.click()
        page.wait_for_timeout(4500)
        shot("planner")
        ins.close()
        server.stop()

        # the Q.bo leaving the room (Fujita et al.), its Jason plans as the mind
        ins, server, thread = serve(lambda i: room_run(3, "bdi", watch=i.watcher()))
        page.goto(server.url)
        page.wait_for_timeout(4000)
        shot("room")
        ins.close()
        server.stop()
        browser.close()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
