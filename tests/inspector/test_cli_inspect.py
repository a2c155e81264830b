"""``--inspect`` on a run and ``robocog inspect FILE`` on its recording, as processes."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import urllib.error
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.inspector.conftest import browser, server_needed

SRC = Path(__file__).resolve().parents[2] / "src"

pytestmark = server_needed


def robocog(*args: str, **kw) -> subprocess.Popen:  # noqa: ANN003
    env = {**os.environ, "PYTHONPATH": str(SRC) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    return subprocess.Popen(
        [sys.executable, "-m", "robocog", *args],
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        env=env,
        **kw,
    )


@pytest.fixture(scope="module")
def recording(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("rec")
    log = out / "run.jsonl"
    proc = robocog(
        "experiment", "garbage", "--runs", "1", "--minds", "bdi", "--rounds", "0",
        "--no-report", "--inspect", "0", "--inspect-record", str(log), cwd=out,
    )  # fmt: skip
    text, _ = proc.communicate(timeout=300)
    assert proc.returncode == 0, text
    assert "inspector: http://127.0.0.1:" in text and f"snapshots in {log}" in text
    return log


@pytest.fixture
def served(recording: Path) -> Iterator[str]:
    proc = robocog("inspect", str(recording), "--port", "0")
    url = ""
    assert proc.stdout is not None
    for line in proc.stdout:
        if line.startswith("inspector: http"):
            url = line.split()[1]
            break
    try:
        assert url, "the command printed no address"
        yield url
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(timeout=30) == 0


def test_a_recorded_run_is_served_again_without_a_robot(served: str) -> None:
    with urllib.request.urlopen(served + "api/state", timeout=10) as r:
        state = json.load(r)["state"]
    assert state["live"] is False and state["first"] == 0 and state["last"] > 10
    with urllib.request.urlopen(served + "api/snapshot?seq=0", timeout=10) as r:
        first = json.load(r)["snapshot"]
    assert first["world"]["kind"] == "garbage" and first["mind"]["kind"] == "bdi"
    req = urllib.request.Request(
        served + "api/command",
        data=json.dumps({"kind": "belief", "text": "x"}).encode(),
        headers={"Content-Type": "application/json"},
    )
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(req, timeout=10)
    assert refused.value.code == 409 and b"recorded run" in refused.value.read()


@browser
def test_the_page_scrubs_through_a_recording(served: str, page, screenshot) -> None:  # noqa: ANN001
    from playwright.sync_api import expect

    page.goto(served)
    expect(page.locator("#loop-state")).to_have_text("recorded")
    expect(page.locator("#step")).to_be_disabled()
    page.evaluate(
        "() => { const t = document.querySelector('#timeline'); t.value = 0;"
        " t.dispatchEvent(new Event('input')); }"
    )
    expect(page.locator("#seq")).to_contain_text("0 (")
    assert page.locator("#robot").get_attribute("data-x") == "1.5"
    expect(page.locator("#intentions")).to_be_visible()
    screenshot(page)
