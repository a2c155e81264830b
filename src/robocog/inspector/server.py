"""The inspector's web server: the page, its JSON API and a stream of snapshots.

Starlette under uvicorn, in a thread of its own with its own event loop. It reads the
inspector's ring buffer and queues the page's commands; it never calls into the robot
loop. The stream (server-sent events) sends the newest snapshot at most ``rate`` times
a second and skips those the browser had no time for: a browser that stops reading
only stalls its own stream, whose sends wait in the server's event loop.

Safe by default: it binds 127.0.0.1 and answers only requests whose Host is a loopback
name (a page elsewhere cannot reach it by rebinding a name to 127.0.0.1). Bound to any
other address it requires the token it was given (printed by the command) on every
request, as ``?token=`` or the ``X-Robocog-Token`` header. Commands are JSON posts
(which a foreign page cannot send without the browser asking first), bounded in size.
"""

from __future__ import annotations

import asyncio
import hmac
import importlib.resources
import ipaddress
import json
import secrets
import threading
from collections import OrderedDict
from collections.abc import Callable
from typing import Any

from robocog.inspector.hub import MAX_INPUT, Inspector
from robocog.inspector.snapshot import Snapshot
from robocog.inspector.snapshot import dumps as snapshot_dumps
from robocog.limits import clip

#: the largest request body accepted (bytes)
MAX_BODY = MAX_INPUT * 4 + 256
#: the most points a chart series carries
SERIES_POINTS = 600
LOOPBACK_NAMES = {"localhost", "127.0.0.1", "::1", "[::1]"}


def is_loopback(host: str) -> bool:
    """True for 127.0.0.0/8, ::1 and ``localhost``."""
    if host in LOOPBACK_NAMES:
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def same_origin(origin: str, host: str) -> bool:
    """True when an ``Origin`` header names the address the request was sent to
    (``http://`` and the ``Host`` header's name and port)."""
    from urllib.parse import urlsplit

    try:
        parts = urlsplit(origin)
    except ValueError:
        return False
    return parts.scheme in ("http", "https") and bool(host) and parts.netloc.lower() == host.lower()


def new_token() -> str:
    """A random token for a server bound beyond loopback."""
    return secrets.token_urlsafe(18)


def _asset(name: str) -> bytes:
    return importlib.resources.files("robocog.inspector").joinpath("page", name).read_bytes()


def snapshot_json(snap: Snapshot | None, inspector: Inspector) -> dict[str, Any]:
    """A snapshot for the page, with the loop's state and the console's tail."""
    out: dict[str, Any] = {"state": inspector.state(), "console": inspector.console_entries()[-50:]}
    if snap is not None:
        out["snapshot"] = snap.to_json()
    return out


def series(inspector: Inspector) -> dict[str, Any]:
    """The charts' data over the history: collected objects, cycle time, and each
    checkpoint hypothesis's confidence (from the mind views), thinned to at most
    ``SERIES_POINTS`` points each."""
    snaps = inspector.history.all()
    step = max(1, len(snaps) // SERIES_POINTS)
    collected, cycle_ms, runs, rounds = [], [], [], []
    last_run = last_round = None
    for i, s in enumerate(snaps):
        if s.run != last_run:
            runs.append([s.seq, s.run])
            last_run = s.run
        if s.world.get("round") != last_round:
            if last_round is not None:
                rounds.append([s.seq, s.world.get("round")])
            last_round = s.world.get("round")
        if i % step and i != len(snaps) - 1:
            continue
        w = s.world
        if "collected" in w:
            collected.append([s.seq, w["collected"]])
        if "cycle_ms" in s.stats:
            cycle_ms.append([s.seq, s.stats["cycle_ms"]])
    hyp: dict[str, list[list[float]]] = {}
    seen_minds: set[int] = set()
    for s in snaps:
        if s.mind_seq != s.seq or s.mind_seq in seen_minds or not s.mind:
            continue
        seen_minds.add(s.mind_seq)
        for place, row in (s.mind.get("hypotheses") or {}).items():
            hyp.setdefault(place, []).append([s.seq, row["c"], row["f"], s.world.get("round", 0)])
    for place, pts in hyp.items():
        if len(pts) > SERIES_POINTS:
            k = len(pts) // SERIES_POINTS + 1
            hyp[place] = pts[::k] + ([pts[-1]] if (len(pts) - 1) % k else [])
    return {
        "collected": collected,
        "cycle_ms": cycle_ms,
        "runs": runs,
        "rounds": rounds,
        "hypotheses": hyp,
    }


class AtomBrowser:
    """The planner's state as an AtomSpace, for finding atoms and following links.

    Built in the server's thread from a snapshot's plain scene (never from the live
    mind), and kept for the last few snapshots asked about.
    """

    def __init__(self) -> None:
        self._spaces: OrderedDict[int, tuple[Any, dict[str, Any]]] = OrderedDict()

    def space(self, snap: Snapshot) -> tuple[Any, dict[str, Any]] | None:
        mind = snap.mind or {}
        scene = mind.get("scene")
        if mind.get("kind") != "planner" or not scene:
            return None
        key = snap.mind_seq
        if key in self._spaces:
            self._spaces.move_to_end(key)
            return self._spaces[key]
        from robocog.atomspace import AtomSpace
        from robocog.planning.atomspace_rules import fact_atom, scene_space
        from robocog.planning.world import Scene

        space = scene_space(
            Scene(list(scene["objects"]), list(scene["fixed"]), dict(scene["on"]), scene["held"])
        )
        request = mind.get("request") or {}
        goal = AtomSpace(name="goal")
        for fact in request.get("goal", []):
            goal.add(fact_atom(tuple(fact)))
        atoms = {str(a): a for a in space.atoms()}
        for a in goal.atoms():
            atoms.setdefault(str(a), a)
        entry = ({"state": space, "goal": goal}, atoms)
        self._spaces[key] = entry
        while len(self._spaces) > 4:
            self._spaces.popitem(last=False)
        return entry

    @staticmethod
    def describe(spaces: dict[str, Any], atom: Any) -> dict[str, Any]:
        state, goal = spaces["state"], spaces["goal"]
        out = list(getattr(atom, "out", ()) or ())
        incoming = set(state.incoming(atom)) if state.contains(atom) else set()
        if goal.contains(atom):
            incoming |= set(goal.incoming(atom))
        return {
            "key": str(atom),
            "type": atom.type,
            "name": getattr(atom, "name", None),
            "outgoing": [str(a) for a in out],
            "incoming": sorted(str(a) for a in incoming)[:100],
            "in_state": state.contains(atom),
            "in_goal": goal.contains(atom),
        }

    def find(self, snap: Snapshot, type_: str, name: str, limit: int = 100) -> list[dict[str, Any]]:
        got = self.space(snap)
        if got is None:
            return []
        spaces, atoms = got
        hits = []
        for key, atom in atoms.items():
            if type_ and atom.type != type_:
                continue
            if name and name.lower() not in key.lower():
                continue
            hits.append(self.describe(spaces, atom))
            if len(hits) >= limit:
                break
        return hits

    def get(self, snap: Snapshot, key: str) -> dict[str, Any] | None:
        got = self.space(snap)
        if got is None:
            return None
        spaces, atoms = got
        atom = atoms.get(key)
        return None if atom is None else self.describe(spaces, atom)


def make_app(
    inspector: Inspector,
    token: str | None = None,
    allow_any_host: bool = False,
    rate: float = 5.0,
    stopping: threading.Event | None = None,
):  # noqa: ANN201 - an ASGI app
    """The ASGI application serving ``inspector``; streams end once ``stopping`` is set."""
    stopping = stopping or threading.Event()
    #: how many stream messages were handed to the network (each counted once its send
    #: returned: a client that stops reading stops this count)
    stats = {"streams": 0, "sent": 0}
    from starlette.applications import Starlette
    from starlette.requests import Request
    from starlette.responses import Response, StreamingResponse
    from starlette.routing import Route

    atoms = AtomBrowser()
    pages = {
        "/": ("index.html", "text/html; charset=utf-8"),
        "/app.js": ("app.js", "text/javascript; charset=utf-8"),
        "/app.css": ("app.css", "text/css; charset=utf-8"),
    }
    headers = {
        "Cache-Control": "no-store",
        "X-Content-Type-Options": "nosniff",
        "Content-Security-Policy": "default-src 'self'; img-src 'self' data:; style-src 'self' 'unsafe-inline'",
        "X-Frame-Options": "DENY",
        "Referrer-Policy": "no-referrer",
    }

    def dumps(obj: Any) -> bytes:
        return snapshot_dumps(obj).encode("utf-8")

    def reply(obj: Any, status: int = 200) -> Response:
        return Response(dumps(obj), status, headers=headers, media_type="application/json")

    async def page(request: Request) -> Response:
        name, media = pages[request.url.path]
        return Response(_asset(name), headers=headers, media_type=media)

    def _snap(request: Request) -> Snapshot | None:
        raw = request.query_params.get("seq", "")
        if raw and raw.lstrip("-").isdigit() and len(raw) < 19:
            return inspector.history.get(int(raw))
        return inspector.history.latest()

    async def snapshot(request: Request) -> Response:
        return reply(snapshot_json(_snap(request), inspector))

    async def state(request: Request) -> Response:
        return reply({"state": inspector.state(), "console": inspector.console_entries()[-50:]})

    async def charts(request: Request) -> Response:
        return reply(series(inspector))

    async def command(request: Request) -> Response:
        if request.headers.get("content-type", "").split(";")[0].strip() != "application/json":
            return reply({"error": "send JSON"}, 415)
        body = b""
        async for chunk in request.stream():
            body += chunk
            if len(body) > MAX_BODY:
                return reply({"error": f"a command is at most {MAX_BODY} bytes"}, 413)
        try:
            data = json.loads(body)
            kind = data["kind"]
            text = data.get("text", "")
            if not isinstance(kind, str) or not isinstance(text, str):
                raise TypeError("kind and text are strings")
        except (ValueError, KeyError, TypeError) as exc:
            return reply({"error": f"bad command: {clip(str(exc), 200)}"}, 400)
        except RecursionError:
            return reply({"error": "bad command: JSON nested too deeply"}, 400)
        try:
            entry = inspector.submit(kind, text)
        except ValueError as exc:
            return reply({"error": str(exc)}, 409)
        return reply(entry, 202)

    async def atoms_find(request: Request) -> Response:
        snap = _snap(request)
        if snap is None:
            return reply({"atoms": []})
        q = request.query_params
        type_, name = q.get("type", "")[:100], q.get("name", "")[:200]
        key = q.get("key", "")[:2000]
        if key:
            return reply({"atom": atoms.get(snap, key)})
        return reply({"atoms": atoms.find(snap, type_, name)})

    async def stream(request: Request) -> Response:
        async def events():  # noqa: ANN202 - an async generator of bytes
            sent = -2
            console = -1
            wait = 1.0 / rate
            stats["streams"] += 1
            yield b"retry: 1000\n\n"
            while not stopping.is_set() and not await request.is_disconnected():
                snap = inspector.history.latest()
                entries = inspector.console_entries()
                ver = max((e["id"] * 10 + (e["status"] != "queued") for e in entries), default=0)
                seq = snap.seq if snap is not None else -1
                if seq != sent or ver != console:
                    sent, console = seq, ver
                    yield b"data: " + dumps(snapshot_json(snap, inspector)) + b"\n\n"
                    stats["sent"] += 1
                await asyncio.sleep(wait)

        return StreamingResponse(
            events(), media_type="text/event-stream", headers={**headers, "X-Accel-Buffering": "no"}
        )

    routes = [Route(p, page) for p in pages] + [
        Route("/api/snapshot", snapshot),
        Route("/api/state", state),
        Route("/api/series", charts),
        Route("/api/command", command, methods=["POST"]),
        Route("/api/atoms", atoms_find),
        Route("/api/stream", stream),
    ]
    app = Starlette(routes=routes)

    async def guarded(scope: dict, receive: Any, send: Any) -> None:
        if scope["type"] == "http":
            hdrs = {k.decode("latin-1"): v.decode("latin-1") for k, v in scope["headers"]}
            host = (
                hdrs.get("host", "").rsplit(":", 1)[0]
                if "]" not in hdrs.get("host", "")
                else hdrs["host"].split("]")[0] + "]"
            )
            refused = None
            if not allow_any_host and not is_loopback(host):
                refused = (421, "this inspector answers loopback names only")
            origin = hdrs.get("origin")
            if refused is None and origin is not None and scope.get("method") != "GET":
                # a command from a page of another site (or any client naming one):
                # only the inspector's own page may send commands
                if not same_origin(origin, hdrs.get("host", "")):
                    refused = (403, "commands are taken from the inspector's own page only")
            if token is not None:
                given = hdrs.get("x-robocog-token", "")
                if not given:
                    from urllib.parse import parse_qs

                    given = parse_qs(scope.get("query_string", b"").decode("latin-1")).get(
                        "token", [""]
                    )[0]
                if not hmac.compare_digest(given.encode(), token.encode()):
                    refused = (403, "a token is required: open the address the command printed")
            if refused is not None:
                body = refused[1].encode()
                await send(
                    {
                        "type": "http.response.start",
                        "status": refused[0],
                        "headers": [
                            (b"content-type", b"text/plain"),
                            (b"content-length", str(len(body)).encode()),
                        ],
                    }
                )
                await send({"type": "http.response.body", "body": body})
                return
        try:
            await app(scope, receive, send)
        except asyncio.CancelledError:
            if not stopping.is_set():
                raise  # a stream cut while stopping (a client that never read) is no error

    guarded.stats = stats  # type: ignore[attr-defined]
    return guarded


class InspectorServer:
    """Serves an Inspector from a thread: ``start()`` returns the page's address."""

    def __init__(
        self,
        inspector: Inspector,
        host: str = "127.0.0.1",
        port: int = 0,
        token: str | None = None,
        rate: float = 5.0,
    ) -> None:
        self.inspector = inspector
        self.host = host
        self.port = port
        loopback = is_loopback(host)
        self.token = token if token is not None else (None if loopback else new_token())
        self.stopping = threading.Event()
        self.app = make_app(
            inspector, self.token, allow_any_host=not loopback, rate=rate, stopping=self.stopping
        )
        self._server: Any = None
        self._thread: threading.Thread | None = None

    @property
    def url(self) -> str:
        """The page's address (with the token when one is needed)."""
        host = self.host if ":" not in self.host else f"[{self.host}]"
        shown = "127.0.0.1" if host in ("0.0.0.0", "[::]") else host
        base = f"http://{shown}:{self.port}/"
        return base + (f"?token={self.token}" if self.token else "")

    def start(self, timeout: float = 10.0, check: Callable[[], None] | None = None) -> str:
        """Start serving; returns the address once the socket listens.

        ``check`` is called while waiting for that and may raise to give up (a stop
        asked for meanwhile); the server is then stopped before the exception goes on."""
        import uvicorn

        config = uvicorn.Config(
            self.app,
            host=self.host,
            port=self.port,
            log_level="warning",
            lifespan="off",
            access_log=False,
            timeout_graceful_shutdown=1,
        )
        self._server = uvicorn.Server(config)
        self._thread = threading.Thread(target=self._server.run, name="inspector-web", daemon=True)
        self._thread.start()
        waited = 0.0
        try:
            while not self._server.started:
                if not self._thread.is_alive():
                    raise OSError(f"the inspector could not listen on {self.host}:{self.port}")
                threading.Event().wait(0.02)
                if check is not None:
                    check()
                waited += 0.02
                if waited > timeout:
                    raise TimeoutError("the inspector's server did not start")
        except BaseException:
            # (Ctrl-C while it starts included: the thread would go on to listen)
            self.stop()
            raise
        sockets = [s for srv in self._server.servers for s in srv.sockets]
        if sockets:
            self.port = sockets[0].getsockname()[1]
        return self.url

    def stop(self) -> None:
        """Stop serving (open streams are cut), in at most about three seconds.

        The server's thread is a daemon: should it still not have ended by then, it
        does not keep the process alive."""
        self.stopping.set()
        if self._server is not None:
            self._server.should_exit = True
        if self._thread is not None:
            self._thread.join(timeout=1.5)
            if self._thread.is_alive() and self._server is not None:
                self._server.force_exit = True  # a stream whose client never reads
                self._thread.join(timeout=1.5)
