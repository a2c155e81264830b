"""``--inspect`` on a run and ``robocog inspect FILE`` on its recording, as processes."""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import time
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


# ---- Ctrl-C and SIGTERM end it, whenever they come ---------------------------------------

#: how long a signalled inspector may take to end (it takes a fraction of a second; the
#: bound leaves room for a loaded machine)
ENDS_WITHIN = 8.0


def _address(proc: subprocess.Popen) -> str:
    """The page's address the command prints, once its port answers."""
    assert proc.stdout is not None
    url = ""
    for line in proc.stdout:
        if line.startswith("inspector: http"):
            url = line.split()[1]
            break
    assert url, "the command printed no address"
    assert url.startswith("http://127.0.0.1:")
    deadline = time.monotonic() + 30
    while True:
        try:
            with urllib.request.urlopen(url + "api/state", timeout=5) as r:
                assert r.status == 200
                return url
        except OSError:
            assert time.monotonic() < deadline, "the page never answered"
            time.sleep(0.05)


def _ends(proc: subprocess.Popen, sig: int) -> tuple[int, str, float]:
    """Send ``sig``; the exit code, what the process wrote, and how long it took."""
    started = time.monotonic()
    proc.send_signal(sig)
    try:
        out, _ = proc.communicate(timeout=ENDS_WITHIN)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, _ = proc.communicate()
        pytest.fail(f"still running {ENDS_WITHIN} s after {signal.Signals(sig).name}:\n{out}")
    return proc.returncode, out, time.monotonic() - started


def _stream(url: str) -> socket.socket:
    """A page's stream, open: the server has a response in progress."""
    port = int(url.rsplit(":", 1)[1].strip("/"))
    s = socket.create_connection(("127.0.0.1", port), timeout=10)
    s.sendall(b"GET /api/stream HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
    assert b"text/event-stream" in s.recv(4096)
    return s


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_ends_the_served_recording_at_once_and_quietly(recording: Path, sig: int) -> None:
    for streaming in (False, True, True):
        proc = robocog("inspect", str(recording), "--port", "0")
        url = _address(proc)
        page = _stream(url) if streaming else None
        try:
            code, out, _ = _ends(proc, sig)
        finally:
            if page is not None:
                page.close()
        assert code == 0, out
        assert "Traceback" not in out and "Exception ignored" not in out, out


def test_ctrl_c_while_starting_ends_it_without_a_traceback(recording: Path) -> None:
    # from the moment the command has read the log (its first line) to serving
    codes: set[int] = set()
    for delay in (0.0, 0.02, 0.05, 0.1, 0.2, 0.4):
        proc = robocog("inspect", str(recording), "--port", "0")
        assert proc.stdout is not None
        assert "snapshots" in proc.stdout.readline()
        time.sleep(delay)
        code, out, _ = _ends(proc, signal.SIGINT)
        # 0 once it serves (how it is meant to end), 130 if it did not serve yet
        assert code in (0, 130), out
        assert "Traceback" not in out and "Exception ignored" not in out, out
        codes.add(code)
    assert 130 in codes, "no signal came before it served: the test tried nothing"


@pytest.mark.slow
@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_ends_a_running_mind_and_closes_its_recording(tmp_path: Path, sig: int) -> None:
    from robocog.inspector.snapshot import read_log

    log = tmp_path / "run.jsonl"
    proc = robocog(
        "experiment", "garbage", "--runs", "5", "--minds", "nars", "--rounds", "12",
        "--no-report", "--inspect", "0", "--inspect-record", str(log), cwd=tmp_path,
    )  # fmt: skip
    url = _address(proc)
    page = _stream(url)
    try:
        deadline = time.monotonic() + 60
        while True:  # the mind has been running for a while
            with urllib.request.urlopen(url + "api/state", timeout=5) as r:
                if json.load(r)["state"]["last"] >= 20:
                    break
            assert time.monotonic() < deadline, "the run made no snapshots"
            time.sleep(0.1)
        code, out, _ = _ends(proc, sig)
    finally:
        page.close()
    # ended by the signal, as the shell counts it, with the recording closed
    assert code == 128 + sig, out
    assert "Traceback" not in out and "Exception ignored" not in out, out
    assert f"snapshots in {log}" in out
    _, history = read_log(log)
    assert len(history) >= 20


# ---- a console line of a hundred million cycles -----------------------------------------

#: how long a page file may take to come while the line runs (it takes a few hundredths
#: of a second; a second is already a page that hangs)
SERVED_WITHIN = 1.0
#: how long the process may take to end on a signal while the line runs (measured: 0.26
#: to 0.71 s in 20 trials on a loaded two-core machine; the goal is 2 s, and this bound
#: leaves room for a CI machine busier still)
LINE_ENDS_WITHIN = 5.0


def _get(url: str) -> dict:
    with urllib.request.urlopen(url, timeout=10) as r:
        return json.load(r)


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "SIGINT"])
def test_a_hundred_million_cycles_leave_the_page_served_and_a_signal_obeyed(
    tmp_path: Path, sig: int
) -> None:
    proc = robocog(
        "experiment", "garbage", "--runs", "5", "--minds", "nars", "--rounds", "12",
        "--no-report", "--inspect", "0", "--inspect-exit", cwd=tmp_path,
    )  # fmt: skip
    try:
        url = _address(proc)
        deadline = time.monotonic() + 60
        while _get(url + "api/state")["state"]["last"] < 3:  # the mind runs
            assert time.monotonic() < deadline, "the run made no snapshots"
            time.sleep(0.1)
        post = urllib.request.Request(
            url + "api/command",
            data=json.dumps({"kind": "tell", "text": "100000000"}).encode(),
            headers={"Content-Type": "application/json"},
            method="POST",
        )
        with urllib.request.urlopen(post, timeout=10) as r:
            assert r.status == 202
            entry = json.load(r)
        time.sleep(1.0)
        before = _get(url + "api/state")
        for path in ("app.css", "app.js", ""):
            started = time.monotonic()
            with urllib.request.urlopen(url + path, timeout=10) as r:
                assert r.status == 200 and r.read()
            took = time.monotonic() - started
            assert took < SERVED_WITHIN, f"/{path} took {took:.2f} s"
        after = _get(url + "api/state")
        # the line still runs: it has not finished, and the loop making snapshots is in it
        (line,) = [e for e in after["console"] if e["id"] == entry["id"]]
        assert line["status"] == "queued"
        assert after["state"]["last"] == before["state"]["last"]
    except BaseException:
        proc.kill()
        proc.communicate()
        raise
    code, out, took = _ends(proc, sig)
    assert took < LINE_ENDS_WITHIN, f"ended {took:.2f} s after {signal.Signals(sig).name}"
    assert code == 128 + sig, out
    assert "Traceback" not in out and "Exception ignored" not in out, out
