"""Runs the targets on seeds and mutations, each input in a worker process, and counts.

An input is run in a worker (a forked child, one per target, restarted after a death or
a hang) with its Python allocations traced: the peak over the input is its size, its
wall time its time. An input past ``--slow`` seconds while traced is run again untraced,
so that tracing's own cost is not counted. A worker that does not answer within
``--hang`` seconds is killed and the input counted slow; a worker's address space is
limited (``--memory-limit``), so a runaway input ends in MemoryError (counted big)
instead of taking the machine.

    python -m tests.fuzz --minutes 10                 # every target, ten minutes in all
    python -m tests.fuzz --inputs 20000 --target pddl-domain
"""

from __future__ import annotations

import argparse
import gzip
import hashlib
import multiprocessing as mp
import os
import random
import resource
import sys
import time
import tracemalloc
from dataclasses import dataclass, field
from pathlib import Path

from tests.fuzz.mutators import mutate
from tests.fuzz.targets import Target, Violation, targets

REGRESSIONS = Path(__file__).with_name("regressions")
#: an input slower than this many seconds is counted slow
SLOW_SECONDS = 2.0
#: an input whose traced peak is above this many bytes is counted big
BIG_BYTES = 100 << 20
#: a worker silent for this long is killed and its input counted slow
HANG_SECONDS = 20.0
#: a kept case is at most this large, compressed
MAX_REGRESSION_BYTES = 256 << 10
#: a worker's address space (a runaway input meets MemoryError here)
MEMORY_LIMIT = 3 << 30


@dataclass
class Outcome:
    """What one input did: ``kind`` is ok, refused, crash, slow or big."""

    kind: str
    seconds: float = 0.0
    peak: int = 0
    message: str = ""


@dataclass
class Tally:
    """The counts of one target's run."""

    target: str
    inputs: int = 0
    kinds: dict[str, int] = field(default_factory=dict)
    slowest: float = 0.0
    biggest: int = 0
    examples: dict[str, str] = field(default_factory=dict)

    def add(self, o: Outcome) -> None:
        self.inputs += 1
        self.kinds[o.kind] = self.kinds.get(o.kind, 0) + 1
        self.slowest = max(self.slowest, o.seconds)
        self.biggest = max(self.biggest, o.peak)
        if o.kind in ("crash", "slow", "big") and o.message not in self.examples:
            if len(self.examples) < 20:
                self.examples[o.message] = o.kind

    @property
    def failures(self) -> int:
        return sum(self.kinds.get(k, 0) for k in ("crash", "slow", "big"))


def run_one(
    target: Target, data: bytes, slow: float = SLOW_SECONDS, big: int = BIG_BYTES
) -> Outcome:
    """Run ``target`` on ``data`` in this process (tracing allocations) and classify."""
    started = tracemalloc.is_tracing()
    if not started:
        tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        kind, message, seconds = _call(target, data)
        peak = max(0, tracemalloc.get_traced_memory()[1] - base)
    finally:
        if not started:
            tracemalloc.stop()
    if seconds > slow and kind != "crash":
        tracemalloc.stop()
        try:
            kind, message, seconds = _call(target, data)
        finally:
            tracemalloc.start()
    if kind == "crash":
        return Outcome(kind, seconds, peak, message)
    if kind == "big" or peak > big:
        return Outcome("big", seconds, peak, message or f"peak {peak >> 20} MB")
    if seconds > slow:
        return Outcome("slow", seconds, peak, f"{seconds:.1f} s")
    return Outcome(kind, seconds, peak, message)


def _call(target: Target, data: bytes) -> tuple[str, str, float]:
    t0 = time.perf_counter()
    try:
        target.run(data)
        kind, message = "ok", ""
    except target.refused as exc:
        kind, message = "refused", str(exc)[:200]
        if len(str(exc)) > 2000:
            kind, message = "crash", f"error message of {len(str(exc))} characters"
    except MemoryError:
        kind, message = "big", "MemoryError"
    except Violation as exc:
        kind, message = "crash", f"Violation: {str(exc)[:200]}"
    except Exception as exc:  # noqa: BLE001 - what the fuzzer is here to find
        kind, message = "crash", f"{type(exc).__name__}: {str(exc)[:200]}"
    return kind, message, time.perf_counter() - t0


def _worker(conn, name: str, slow: float, big: int, memory_limit: int) -> None:  # noqa: ANN001
    """A worker: inputs in, outcomes out, until the pipe closes."""
    try:
        resource.setrlimit(resource.RLIMIT_AS, (memory_limit, memory_limit))
    except (ValueError, OSError):
        pass
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 1000))
    target = targets()[name]
    tracemalloc.start()
    while True:
        try:
            data = conn.recv_bytes()
        except EOFError:
            return
        o = run_one(target, data, slow, big)
        conn.send((o.kind, o.seconds, o.peak, o.message))


class Worker:
    """A worker process for one target, restarted when it dies or hangs."""

    def __init__(self, name: str, slow: float, big: int, hang: float, memory_limit: int) -> None:
        self.name, self.slow, self.big, self.hang = name, slow, big, hang
        self.memory_limit = memory_limit
        self.proc: mp.Process | None = None
        self.conn = None

    def _start(self) -> None:
        ctx = mp.get_context("fork")
        parent, child = ctx.Pipe()
        self.proc = ctx.Process(
            target=_worker,
            args=(child, self.name, self.slow, self.big, self.memory_limit),
            daemon=True,
        )
        self.proc.start()
        child.close()
        self.conn = parent

    def run(self, data: bytes) -> Outcome:
        if self.proc is None or not self.proc.is_alive():
            self._start()
        assert self.conn is not None and self.proc is not None
        try:
            self.conn.send_bytes(data)
            if self.conn.poll(self.hang):
                kind, seconds, peak, message = self.conn.recv()
                return Outcome(kind, seconds, peak, message)
            self.stop()
            return Outcome("slow", self.hang, 0, f"no answer within {self.hang:g} s")
        except (EOFError, BrokenPipeError, ConnectionResetError):
            code = self.proc.exitcode if self.proc is not None else None
            self.stop()
            return Outcome("crash", 0.0, 0, f"the worker died (exit code {code})")

    def stop(self) -> None:
        if self.proc is not None:
            if self.proc.is_alive():
                self.proc.kill()
            self.proc.join(5)
        if self.conn is not None:
            self.conn.close()
        self.proc = self.conn = None


def save_regression(target: str, data: bytes, o: Outcome) -> Path | None:
    """Keep a failing input as a regression case (named by its hash)."""
    folder = REGRESSIONS / target
    folder.mkdir(parents=True, exist_ok=True)
    digest = hashlib.sha1(data).hexdigest()[:16]
    path = folder / f"{digest}.gz"
    if path.exists():
        return None
    packed = gzip.compress(data, mtime=0)
    if len(packed) > MAX_REGRESSION_BYTES:
        return None
    path.write_bytes(packed)
    (folder / f"{digest}.txt").write_text(f"{o.kind}: {o.message[:300]}\n", encoding="utf-8")
    return path


def regressions(target: str | None = None) -> list[tuple[str, Path]]:
    """The kept cases: (target, path), every target or one."""
    out = []
    for folder in sorted(REGRESSIONS.iterdir()) if REGRESSIONS.is_dir() else []:
        if folder.is_dir() and (target is None or folder.name == target):
            out += [(folder.name, p) for p in sorted(folder.glob("*.gz"))]
    return out


def load_regression(path: Path) -> bytes:
    """A kept case's input."""
    return gzip.decompress(path.read_bytes())


def fuzz(
    target: Target,
    count: int,
    seconds: float,
    seed: int = 0,
    slow: float = SLOW_SECONDS,
    big: int = BIG_BYTES,
    hang: float = HANG_SECONDS,
    memory_limit: int = MEMORY_LIMIT,
    keep: bool = True,
    progress: bool = False,
) -> Tally:
    """Run ``target`` on its seeds, then on mutations, until ``count`` inputs or
    ``seconds`` have gone; failing inputs are kept as regressions when ``keep``."""
    rng = random.Random(f"{seed}:{target.name}")
    seeds = [s for s in target.seeds() if s is not None] or [b""]
    tally = Tally(target.name)
    worker = Worker(target.name, slow, big, hang, memory_limit)
    kept_per_message: dict[str, int] = {}
    deadline = time.monotonic() + seconds
    last_note = time.monotonic()
    try:
        i = 0
        while i < count and time.monotonic() < deadline:
            if i < len(seeds):
                data = seeds[i]
            else:
                data = mutate(
                    rng.choice(seeds), rng.choice(seeds), target.tokens, target.brackets, rng
                )
            o = worker.run(data)
            tally.add(o)
            if o.kind in ("crash", "slow", "big") and keep:
                sig = f"{o.kind}:{o.message.split(':')[0]}"
                if kept_per_message.get(sig, 0) < 3:
                    if save_regression(target.name, data, o) is not None:
                        kept_per_message[sig] = kept_per_message.get(sig, 0) + 1
            i += 1
            if progress and time.monotonic() - last_note > 30:
                last_note = time.monotonic()
                print(f"  {target.name}: {i} inputs, {tally.failures} failures", flush=True)
    finally:
        worker.stop()
    return tally


def report(tallies: list[Tally]) -> str:
    """The run's table: inputs, refused, crash, slow, big, slowest and largest per target."""
    rows = [
        f"{'target':<17} {'inputs':>7} {'refused':>7} {'crash':>5} {'slow':>5} {'big':>5}"
        f" {'max s':>6} {'max MB':>7}"
    ]
    for t in tallies:
        k = t.kinds
        rows.append(
            f"{t.target:<17} {t.inputs:>7} {k.get('refused', 0):>7} {k.get('crash', 0):>5}"
            f" {k.get('slow', 0):>5} {k.get('big', 0):>5} {t.slowest:>6.2f}"
            f" {t.biggest / (1 << 20):>7.1f}"
        )
    for t in tallies:
        for message, kind in t.examples.items():
            rows.append(f"  {t.target}: {kind}: {message[:150]}")
    return "\n".join(rows)


def main(argv: list[str] | None = None) -> int:
    """``python -m tests.fuzz``: 0 when no input crashed, was slow or big."""
    all_targets = targets()
    p = argparse.ArgumentParser(prog="python -m tests.fuzz", description=__doc__.split("\n")[0])
    p.add_argument("--minutes", type=float, default=1.0, help="time for the whole run")
    p.add_argument("--inputs", type=int, default=20_000, help="most inputs per target")
    p.add_argument(
        "--target",
        action="append",
        choices=list(all_targets),
        help="run this target only (repeatable; default all)",
    )
    p.add_argument("--seed", type=int, default=0, help="random seed of the mutations")
    p.add_argument("--slow", type=float, default=SLOW_SECONDS, help="seconds counted slow")
    p.add_argument("--big", type=float, default=BIG_BYTES >> 20, help="MB counted big")
    p.add_argument(
        "--hang", type=float, default=HANG_SECONDS, help="seconds after which a worker is killed"
    )
    p.add_argument("--no-keep", action="store_true", help="do not save failing inputs")
    p.add_argument("--list", action="store_true", help="list the targets and exit")
    args = p.parse_args(argv)
    if args.list:
        for t in all_targets.values():
            print(f"{t.name:<17} {t.doc}")
        return 0
    if args.minutes <= 0 or args.inputs <= 0:
        print("python -m tests.fuzz: --minutes and --inputs must be positive", file=sys.stderr)
        return 2
    names = args.target or list(all_targets)
    share = args.minutes * 60 / len(names)
    tallies = []
    try:
        for name in names:
            t0 = time.monotonic()
            tally = fuzz(
                all_targets[name],
                args.inputs,
                share,
                args.seed,
                args.slow,
                int(args.big * (1 << 20)),
                args.hang,
                keep=not args.no_keep,
                progress=True,
            )
            tallies.append(tally)
            print(
                f"{name}: {tally.inputs} inputs in {time.monotonic() - t0:.0f} s,"
                f" {tally.failures} failures",
                flush=True,
            )
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
    print(report(tallies))
    return 1 if any(t.failures for t in tallies) else 0


if __name__ == "__main__":
    os.environ.setdefault("PYTHONHASHSEED", "0")
    sys.exit(main())
