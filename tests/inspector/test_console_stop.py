"""A console line of a hundred million cycles neither holds the page nor the process:
it runs in slices that end on the page's stop or when the inspector closes."""

from __future__ import annotations

import threading
import time

from robocog.inspector.hub import Inspector
from robocog.inspector.views import NarsView
from robocog.nars.nar import NAR


def _running(end: str) -> None:
    nar = NAR(seed=1)
    nar.output = lambda line: None  # type: ignore[method-assign]
    ins = Inspector()
    ins._mind_view = NarsView(nar)  # (what ``watch`` sets for a NARS mind)
    entry = ins.submit("tell", "100000000")
    worker = threading.Thread(target=ins.apply_commands)
    worker.start()
    deadline = time.monotonic() + 60
    while nar.time < 200 and time.monotonic() < deadline:
        time.sleep(0.01)
    assert worker.is_alive()  # the line is running
    if end == "stop":
        ins.submit("stop")
    else:
        ins.close()
    worker.join(30)
    assert not worker.is_alive()
    done = next(e for e in ins.console_entries() if e["id"] == entry["id"])
    assert done["status"] == "ok"
    assert nar.time < 100_000_000
    assert nar.stop_requested is None  # the view left the reasoner as it was


def test_the_page_s_stop_ends_a_long_cycles_line() -> None:
    _running("stop")


def test_closing_the_inspector_ends_a_long_cycles_line() -> None:
    _running("close")


def test_the_page_is_served_while_a_long_line_runs() -> None:
    from starlette.testclient import TestClient

    from robocog.inspector.server import make_app

    nar = NAR(seed=1)
    nar.output = lambda line: None  # type: ignore[method-assign]
    ins = Inspector()
    ins._mind_view = NarsView(nar)
    ins.submit("tell", "100000000")
    worker = threading.Thread(target=ins.apply_commands)
    worker.start()
    try:
        client = TestClient(make_app(ins), base_url="http://127.0.0.1")
        for path in ("/app.css", "/app.js", "/"):
            assert client.get(path).status_code == 200
    finally:
        ins.submit("stop")
        worker.join(30)
    assert not worker.is_alive()
