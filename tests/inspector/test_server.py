"""The inspector's web server: its API, its guards, and a browser that stops reading."""

from __future__ import annotations

import socket
import threading
import time

import pytest

from robocog.inspector.hub import Inspector
from robocog.minds.bdi_mind import BdiMind
from robocog.robot.loop import Loop
from robocog.worlds.garbage import GarbageConfig, GarbageField
from tests.inspector.conftest import server_needed

pytestmark = [server_needed, pytest.mark.filterwarnings("ignore:Using `httpx`")]


def running(cycles: int = 20) -> tuple[Inspector, Loop]:
    ins = Inspector(world_budget=None)
    world = GarbageField(GarbageConfig(), seed=5)
    mind = BdiMind()
    loop = Loop(world, mind)
    loop.run(cycles, on_step=ins.watch(world, mind, loop))
    return ins, loop


def client(ins: Inspector, **kw):  # noqa: ANN201 - a TestClient
    from starlette.testclient import TestClient

    from robocog.inspector.server import make_app

    return TestClient(make_app(ins, **kw), base_url="http://127.0.0.1")


def test_the_page_and_its_assets_are_served_without_anything_from_outside() -> None:
    ins, _ = running(2)
    c = client(ins)
    page = c.get("/")
    assert page.status_code == 200 and "robocog inspector" in page.text
    assert "default-src 'self'" in page.headers["content-security-policy"]
    for asset in ("/app.js", "/app.css"):
        r = c.get(asset)
        assert r.status_code == 200 and len(r.text) > 500
        assert "http://" not in r.text.replace("http://www.w3.org/2000/svg", "")
        assert "https://" not in r.text


def test_snapshots_by_number_and_the_newest() -> None:
    ins, loop = running(20)
    c = client(ins)
    latest = c.get("/api/snapshot").json()
    assert latest["snapshot"]["seq"] == 20 and latest["state"]["last"] == 20
    assert latest["snapshot"]["world"]["kind"] == "garbage"
    old = c.get("/api/snapshot", params={"seq": 3}).json()["snapshot"]
    assert old["seq"] == 3 and old["cycle"] == 3
    assert c.get("/api/snapshot", params={"seq": "x' or 1"}).json()["snapshot"]["seq"] == 20
    assert "snapshot" not in c.get("/api/snapshot", params={"seq": 999}).json()
    series = c.get("/api/series").json()
    assert len(series["cycle_ms"]) == 20 and series["runs"][0][0] == 0


def test_commands_are_json_posts_bounded_in_size() -> None:
    ins, _ = running(1)
    c = client(ins)
    assert (
        c.post(
            "/api/command",
            content=b"kind=tell",
            headers={"content-type": "application/x-www-form-urlencoded"},
        ).status_code
        == 415
    )
    assert (
        c.post(
            "/api/command", content=b"{", headers={"content-type": "application/json"}
        ).status_code
        == 400
    )
    assert c.post("/api/command", json={"kind": 3}).status_code == 400
    assert c.post("/api/command", json={"kind": "eval", "text": "1"}).status_code == 409
    assert c.post("/api/command", json={"kind": "tell", "text": "x" * 100_000}).status_code == 413
    r = c.post("/api/command", json={"kind": "belief", "text": "seen(p1)"})
    assert r.status_code == 202 and r.json()["status"] == "queued"
    assert c.get("/api/state").json()["console"][-1]["text"] == "seen(p1)"


def test_a_loopback_server_answers_loopback_names_only() -> None:
    ins, _ = running(1)
    c = client(ins)
    assert c.get("/api/state", headers={"host": "localhost:8765"}).status_code == 200
    assert c.get("/api/state", headers={"host": "127.0.0.1:8765"}).status_code == 200
    assert c.get("/api/state", headers={"host": "attacker.example:8765"}).status_code == 421


def test_beyond_loopback_every_request_needs_the_token() -> None:
    from robocog.inspector.server import InspectorServer

    ins, _ = running(1)
    c = client(ins, token="s3cret", allow_any_host=True)
    assert c.get("/").status_code == 403
    assert c.get("/api/state", params={"token": "wrong"}).status_code == 403
    assert c.get("/", params={"token": "s3cret"}).status_code == 200
    assert c.get("/api/state", headers={"x-robocog-token": "s3cret"}).status_code == 200
    assert c.post("/api/command", json={"kind": "pause"}).status_code == 403
    served = InspectorServer(ins, host="0.0.0.0")
    assert served.token and len(served.token) >= 20
    assert served.url.endswith("?token=" + served.token)
    assert InspectorServer(ins).token is None


@pytest.mark.slow
def test_a_browser_that_stops_reading_never_holds_up_the_robot() -> None:
    from robocog.inspector.server import InspectorServer

    ins = Inspector()
    server = InspectorServer(ins, port=0, rate=200.0)  # a stream that fills its socket fast
    server.start()
    world = GarbageField(GarbageConfig(), seed=6)
    mind = BdiMind()
    loop = Loop(world, mind)
    hook = ins.watch(world, mind, loop)
    stalled = socket.socket()
    stalled.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    stalled.connect(("127.0.0.1", server.port))
    stalled.sendall(b"GET /api/stream HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
    try:
        time.sleep(0.3)
        runner = threading.Thread(target=loop.run, args=(1500,), kwargs={"on_step": hook})
        runner.start()
        runner.join(timeout=120)
        assert not runner.is_alive() and loop.cycles == 1500
        # the server still answers others while that one reads nothing
        import urllib.request

        with urllib.request.urlopen(f"http://127.0.0.1:{server.port}/api/state", timeout=10) as r:
            assert r.status == 200
    finally:
        stalled.close()
        server.stop()


def test_the_stream_sends_snapshots() -> None:
    from robocog.inspector.server import InspectorServer

    ins, _ = running(5)
    server = InspectorServer(ins, port=0)
    server.start()
    try:
        with socket.create_connection(("127.0.0.1", server.port), timeout=10) as s:
            s.sendall(b"GET /api/stream HTTP/1.1\r\nHost: localhost\r\n\r\n")
            got = b""
            deadline = time.time() + 10
            while (
                b"data: " not in got or not got.rstrip().endswith(b"}") and time.time() < deadline
            ):
                got += s.recv(65536)
        assert b"text/event-stream" in got and b'"seq":5' in got
    finally:
        server.stop()


@pytest.mark.parametrize("host", ["127.0.0.1", "localhost", "::1", "127.8.0.1"])
def test_loopback_names(host: str) -> None:
    from robocog.inspector.server import is_loopback

    assert is_loopback(host)
    assert (
        not is_loopback("0.0.0.0")
        and not is_loopback("192.168.1.2")
        and not is_loopback("example.org")
    )
