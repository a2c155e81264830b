"""The robot loop's cycle time with and without the inspector watching it.

The same learning runs of a mind on the garbage field (``learn_accumulation``: NARS
over several rounds, or the BDI agent) are timed four ways, interleaved run by run so
the shared machine's drift falls on all of them alike:

* ``none``: no inspector (only the timing hook);
* ``hooked``: the inspector's snapshots, no server;
* ``open``: the server too, with a client that reads the stream as a page does (and
  fetches the charts every 2 s);
* ``stalled``: the server with a client that sends its request and never reads (its
  socket's buffers fill up; the stream waits in the server's thread).

The figure is the whole iteration of ``Loop.run`` (the cycle, the collection between
cycles and the ``on_step`` hook), from one hook call to the next, in wall time; the
goal is at most 10% more than ``none`` at p50 with the page open.

    python benchmarks/inspector.py                      # NARS, 3 runs of 4 rounds
    python benchmarks/inspector.py --mind bdi --runs 3
"""

from __future__ import annotations

import argparse
import http.client
import json
import socket
import sys
import threading
import time
from typing import Any

from robocog.experiments.garbage import default_minds, learn_accumulation
from robocog.inspector.hub import Inspector
from robocog.inspector.server import InspectorServer
from robocog.nars import ENGINE
from robocog.robot.loop import percentile
from robocog.worlds.garbage import GarbageConfig

MODES = ("none", "hooked", "open", "stalled")


class Reader(threading.Thread):
    """A page: reads the stream as fast as it comes and fetches the charts every 2 s."""

    def __init__(self, port: int) -> None:
        super().__init__(daemon=True)
        self.port = port
        self.stop = threading.Event()
        self.events = 0
        self.bytes = 0

    def run(self) -> None:
        try:
            self.read()
        except (OSError, http.client.HTTPException):
            pass  # the server stopped under it

    def read(self) -> None:
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=30)
        conn.request("GET", "/api/stream")
        resp = conn.getresponse()
        charts = http.client.HTTPConnection("127.0.0.1", self.port, timeout=30)
        last = 0.0
        while not self.stop.is_set():
            line = resp.fp.readline()
            if not line:
                break
            self.bytes += len(line)
            if line.startswith(b"data: "):
                self.events += 1
            if time.monotonic() - last > 2.0:
                last = time.monotonic()
                charts.request("GET", "/api/series")
                self.bytes += len(charts.getresponse().read())
        conn.close()
        charts.close()


def stalled_client(port: int) -> socket.socket:
    """A client that asks for the stream and never reads it."""
    s = socket.socket()
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    s.connect(("127.0.0.1", port))
    s.sendall(b"GET /api/stream HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
    return s


def unread(s: socket.socket) -> int:
    """Bytes waiting in the socket (read now, without blocking)."""
    s.setblocking(False)
    total = 0
    try:
        while chunk := s.recv(1 << 20):
            total += len(chunk)
    except BlockingIOError:
        pass
    return total


def one_run(
    mind: str, mode: str, seed: int, rounds: int, world_budget: float | None = None
) -> dict[str, Any]:
    """One learning run in one mode: the iteration times and what the clients saw."""
    intervals: list[float] = []
    cpu: list[float] = []
    last = [0.0]
    last_cpu = [0.0]
    inspector = Inspector(world_budget=world_budget) if mode != "none" else None
    server = reader = stalled = None
    if mode in ("open", "stalled"):
        assert inspector is not None
        # the stalled client's stream runs at 50 a second, so that its socket's buffers
        # (several MB on loopback) fill within a run
        server = InspectorServer(inspector, port=0, rate=5.0 if mode == "open" else 50.0)
        server.start()
        if mode == "open":
            reader = Reader(server.port)
            reader.start()
        else:
            stalled = stalled_client(server.port)
        time.sleep(0.3)

    def watch(world: Any, m: Any, loop: Any) -> Any:
        hook = inspector.watch(world, m, loop) if inspector is not None else None

        def on_step(step: Any) -> None:
            now, now_cpu = time.perf_counter(), time.process_time()
            if last[0]:
                intervals.append(now - last[0])
                cpu.append(now_cpu - last_cpu[0])
            if hook is not None:
                hook(step)
            last[0], last_cpu[0] = now, now_cpu

        return on_step

    spec = default_minds([mind])[0]
    start = time.perf_counter()
    if mind == "nars":
        learn_accumulation(spec, GarbageConfig(), seed, rounds, watch=watch)
    else:
        from robocog.experiments.garbage import run_once

        for r in range(rounds):
            last[0] = 0.0
            run_once(spec, GarbageConfig(), seed * 100 + r, watch=watch)
    wall = time.perf_counter() - start
    out: dict[str, Any] = {"intervals": intervals, "cpu": cpu, "wall": wall}
    if reader is not None:
        reader.stop.set()
        out["events"] = reader.events
        out["bytes"] = reader.bytes
    if server is not None:
        out["stream_sent"] = server.app.stats["sent"]
    if stalled is not None:
        out["unread"] = unread(stalled)
        stalled.close()
    if server is not None:
        server.stop()
    if inspector is not None:
        out["snapshots"] = inspector.history.next_seq
        inspector.close()
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mind", choices=("nars", "bdi"), default="nars")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument(
        "--world-budget",
        type=float,
        help="the inspector's world_budget (default: every cycle is snapshotted)",
    )
    parser.add_argument("--json", help="write the figures here")
    args = parser.parse_args(argv)
    print(
        f"engine: {ENGINE}; mind {args.mind}; {args.runs} runs of {args.rounds} rounds; "
        f"world budget {args.world_budget or 'none (every cycle)'}"
    )
    times: dict[str, list[float]] = {m: [] for m in MODES}
    cpus: dict[str, list[float]] = {m: [] for m in MODES}
    extra: dict[str, dict[str, float]] = {m: {} for m in MODES}
    for i in range(args.runs):
        order = MODES if i % 2 == 0 else tuple(reversed(MODES))
        for mode in order:
            got = one_run(args.mind, mode, args.seed + i, args.rounds, args.world_budget)
            times[mode] += got["intervals"]
            cpus[mode] += got["cpu"]
            for k in ("events", "bytes", "stream_sent", "unread", "snapshots", "wall"):
                if k in got:
                    extra[mode][k] = extra[mode].get(k, 0) + got[k]
    base = percentile(times["none"], 50)
    base_cpu = percentile(cpus["none"], 50)
    rows = {}
    print(
        f"{'mode':8} {'iterations':>10} {'p50 ms':>8} {'p99 ms':>8} {'p50 vs none':>12}"
        f" {'CPU p50 ms':>10} {'vs none':>8}  notes"
    )
    for mode in MODES:
        t = times[mode]
        p50, p99 = percentile(t, 50), percentile(t, 99)
        c50 = percentile(cpus[mode], 50)
        notes = ", ".join(
            f"{k} {v:,.0f}" if k != "wall" else f"wall {v:.1f} s" for k, v in extra[mode].items()
        )
        print(
            f"{mode:8} {len(t):>10} {p50 * 1e3:8.2f} {p99 * 1e3:8.2f} {p50 / base - 1:+11.1%}"
            f" {c50 * 1e3:10.2f} {c50 / base_cpu - 1:+8.1%}  {notes}"
        )
        rows[mode] = {
            "iterations": len(t),
            "p50_ms": p50 * 1e3,
            "p99_ms": p99 * 1e3,
            "cpu_p50_ms": c50 * 1e3,
            **extra[mode],
        }
    if args.json:
        with open(args.json, "w") as f:
            json.dump(
                {"engine": ENGINE, "mind": args.mind, "runs": args.runs, "modes": rows}, f, indent=2
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
