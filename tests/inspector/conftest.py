"""Shared pieces of the inspector's tests: a live inspector on a loop in a thread, and
a browser (Debian's chromium under pytest-playwright, installed or unpacked privately by
.ci/apt_install.sh) to drive its page."""

from __future__ import annotations

import importlib.util
import os
import shutil
import threading
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

#: where each browser test leaves its screenshot
RESULTS = Path(
    os.environ.get(
        "ROBOCOG_TEST_RESULTS", Path(__file__).resolve().parents[2] / "tmp" / "test-results"
    )
)


def private_chromium() -> str | None:
    """Debian's chromium as .ci/apt_install.sh unpacks it where installing it through apt
    would upgrade installed packages: ROOT/bin/chromium, in the same root as the script's
    (``ROBOCOG_DEB_ROOT``, by default ~/.cache/robocog/deb-root)."""
    cache = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    root = os.environ.get("ROBOCOG_DEB_ROOT") or Path(cache) / "robocog" / "deb-root"
    path = Path(root) / "bin" / "chromium"
    return str(path) if os.access(path, os.X_OK) else None


CHROMIUM = (
    os.environ.get("ROBOCOG_CHROMIUM")
    or shutil.which("chromium")
    or shutil.which("chromium-browser")
    or private_chromium()
)
HAVE_PLAYWRIGHT = importlib.util.find_spec("pytest_playwright") is not None
HAVE_SERVER = (
    importlib.util.find_spec("starlette") is not None
    and importlib.util.find_spec("uvicorn") is not None
)

_needs_browser = pytest.mark.skipif(
    not (CHROMIUM and HAVE_PLAYWRIGHT and HAVE_SERVER),
    reason="needs chromium (bash .ci/install_system.sh), pytest-playwright and the inspect extra"
    + f" (chromium: {CHROMIUM or 'absent'}, pytest-playwright: {HAVE_PLAYWRIGHT}, server: {HAVE_SERVER})",
)


def browser(test: Callable[..., Any]) -> Callable[..., Any]:
    """The marks of every test that drives the page in a browser."""
    return pytest.mark.browser(_needs_browser(test))


server_needed = pytest.mark.skipif(
    not HAVE_SERVER, reason="needs the inspect extra (starlette, uvicorn)"
)


@pytest.fixture(scope="session")
def browser_type_launch_args(browser_type_launch_args: dict[str, Any]) -> dict[str, Any]:
    """Playwright launches Debian's chromium (its own browser download is not used)."""
    return {**browser_type_launch_args, "executable_path": CHROMIUM}


@pytest.fixture
def screenshot(request: pytest.FixtureRequest) -> Callable[[Any, str], Path]:
    """``screenshot(page, name)`` saves a full-page PNG under tmp/test-results."""

    def take(page: Any, name: str = "") -> Path:
        RESULTS.mkdir(parents=True, exist_ok=True)
        path = RESULTS / f"{request.node.name}{'-' + name if name else ''}.png"
        page.screenshot(path=str(path), full_page=True)
        return path

    return take


class Live:
    """An inspector served on loopback, its robot loop running in a thread."""

    def __init__(
        self, run: Callable[[Any], None], paused: bool = False, mind_interval: float | None = None
    ) -> None:
        from robocog.inspector.hub import Inspector
        from robocog.inspector.server import InspectorServer

        # A test that reads the mind's history at points of a run asks for a view every
        # ``mind_interval`` seconds. Its views may then take any share of the time: by
        # default they take at most 1%, so a view that costs more on a loaded machine
        # would leave a short run with one or two, and how busy the machine is would
        # decide what the test sees.
        if mind_interval is None:
            self.inspector = Inspector()
        else:
            self.inspector = Inspector(min_mind_interval=mind_interval, mind_budget=1.0)
        self.server = InspectorServer(self.inspector, port=0)
        self.url = self.server.start()
        if paused:
            self.inspector.submit("pause")
        self.error: BaseException | None = None

        def body() -> None:
            try:
                run(self.inspector)
                self.inspector.linger()
            except BaseException as exc:  # reported by the test
                self.error = exc

        self.thread = threading.Thread(target=body, daemon=True)
        self.thread.start()

    def close(self) -> None:
        self.inspector.close()
        self.thread.join(timeout=30)
        self.server.stop()


@pytest.fixture
def live() -> Iterator[Callable[..., Live]]:
    """``live(run, paused=False, mind_interval=None)`` starts one; all are closed after
    the test."""
    made: list[Live] = []

    def make(
        run: Callable[[Any], None], paused: bool = False, mind_interval: float | None = None
    ) -> Live:
        lv = Live(run, paused, mind_interval)
        made.append(lv)
        return lv

    yield make
    for lv in made:
        lv.close()
    for lv in made:
        assert lv.error is None, f"the robot loop failed: {lv.error!r}"
