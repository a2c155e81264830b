"""Snapshots, the ring buffer that holds them, and the JSON-lines log they are saved to.

A :class:`Snapshot` is one cycle as the page shows it: the world's view, the mind's
latest view (``mind_seq`` says which cycle it was taken at), the cycle's timing and
actions. The :class:`History` keeps the newest ``capacity`` of them; adding never
waits for a reader (the lock guards a deque append or a copy, nothing more).

The log (``--inspect-record FILE``, read back by ``robocog inspect FILE``) is JSON
lines: a header line, then one line per snapshot in order::

    {"format": "robocog-inspector", "version": 1, "created": "2026-...Z", "source": "..."}
    {"seq": 0, "run": "run 1: NARS", "cycle": 0, "wall": ..., "world": {...},
     "mind": {...}, "mind_seq": 0, "stats": {...}, "actions": [...]}
    {"seq": 1, ..., "mind_seq": 0, ...}          # no "mind": the one of seq 0 still holds
    {"end": "size limit", "bytes": ...}          # only when the writer stopped early

A snapshot line carries ``mind`` only when its mind view is new (``mind_seq == seq``);
a reader carries the last one forward. The writer stops at ``max_bytes`` and says so
in a last line. The reader checks the header, the order of ``seq``, the type of every
field and the size of every line, and names the line of the first fault.
"""

from __future__ import annotations

import bisect
import dataclasses
import json
import threading
from collections import deque
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import IO, Any

FORMAT = "robocog-inspector"
VERSION = 1
#: the longest line a log may hold (bytes)
MAX_LINE = 8 << 20
#: the largest log ``read_log`` accepts, and the default limit of the writer
MAX_FILE = 1 << 30
DEFAULT_RECORD_BYTES = 200 << 20


@dataclass(slots=True)
class Snapshot:
    """One cycle as shown: the world, the mind's latest view, timing and actions."""

    seq: int
    run: str
    cycle: int
    wall: float
    world: dict[str, Any]
    mind: dict[str, Any] | None = None
    mind_seq: int = -1
    stats: dict[str, Any] = field(default_factory=dict)
    actions: list[list[str]] = field(default_factory=list)

    def to_json(self, with_mind: bool = True) -> dict[str, Any]:
        """The snapshot as a JSON object (the mind's view included or not)."""
        out = {
            "seq": self.seq,
            "run": self.run,
            "cycle": self.cycle,
            "wall": round(self.wall, 3),
            "world": self.world,
            "mind_seq": self.mind_seq,
            "stats": self.stats,
            "actions": self.actions,
        }
        if with_mind:
            out["mind"] = self.mind
        return out


def encode(obj: Any) -> Any:
    """JSON for what views keep as it is: frozen dataclasses (a frame's percepts)."""
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return {f.name: getattr(obj, f.name) for f in dataclasses.fields(obj)}
    raise TypeError(f"{type(obj).__name__} is not JSON")


def dumps(obj: Any) -> str:
    """One compact JSON text (no NaN), as the log and the server write it."""
    return json.dumps(obj, separators=(",", ":"), allow_nan=False, default=encode)


class History:
    """The newest ``capacity`` snapshots, numbered by ``seq`` without gaps."""

    def __init__(self, capacity: int = 3000) -> None:
        if capacity < 1:
            raise ValueError("a history holds at least one snapshot")
        self.capacity = capacity
        self._items: deque[Snapshot] = deque(maxlen=capacity)
        self._lock = threading.Lock()
        self.next_seq = 0
        self.dropped = 0

    def add(self, snap: Snapshot) -> None:
        """Append (dropping the oldest when full); ``snap.seq`` must be ``next_seq``."""
        with self._lock:
            if len(self._items) == self.capacity:
                self.dropped += 1
            self._items.append(snap)
            self.next_seq = snap.seq + 1

    def __len__(self) -> int:
        return len(self._items)

    def bounds(self) -> tuple[int, int]:
        """(first seq held, last seq held), or (0, -1) when empty."""
        with self._lock:
            if not self._items:
                return 0, -1
            return self._items[0].seq, self._items[-1].seq

    def latest(self) -> Snapshot | None:
        """The newest snapshot."""
        with self._lock:
            return self._items[-1] if self._items else None

    def get(self, seq: int) -> Snapshot | None:
        """The snapshot numbered ``seq``, if still held."""
        with self._lock:
            if not self._items:
                return None
            i = seq - self._items[0].seq
            if 0 <= i < len(self._items) and self._items[i].seq == seq:
                return self._items[i]
            # a log with a gap (its writer fell behind): search by number
            seqs = [s.seq for s in self._items]
            j = bisect.bisect_left(seqs, seq)
            return self._items[j] if j < len(seqs) and seqs[j] == seq else None

    def since(self, seq: int, limit: int = 10_000) -> list[Snapshot]:
        """The snapshots after ``seq`` (at most ``limit``, the newest)."""
        with self._lock:
            if not self._items:
                return []
            start = max(0, seq + 1 - self._items[0].seq)
            n = len(self._items)
            start = max(start, n - limit)
            return [self._items[i] for i in range(start, n)]

    def all(self) -> list[Snapshot]:
        """Every snapshot held, oldest first (a copy of the list)."""
        with self._lock:
            return list(self._items)


# ---- the log ---------------------------------------------------------------------------


class LogError(ValueError):
    """A log that is not one, or is damaged; the message names the line."""


def header(source: str = "") -> dict[str, Any]:
    """The first line of a log."""
    created = datetime.now(UTC).strftime("%Y-%m-%dT%H:%M:%SZ")
    return {"format": FORMAT, "version": VERSION, "created": created, "source": source[:500]}


class LogWriter:
    """Writes the history's new snapshots to a JSON-lines file from its own thread.

    The robot's thread never writes: this thread wakes every ``period`` seconds and
    writes what the history gained. If it falls behind by more than the history holds,
    the snapshots it missed are lost (the ``seq`` numbers show the gap). It stops at
    ``max_bytes``, with a last line saying so. Writes are serialised by a lock: ``close``
    writes the rest from the caller's thread, which may come while the writer's own
    thread is still in a write (its join has a time limit).
    """

    def __init__(
        self,
        history: History,
        path: Path,
        source: str = "",
        max_bytes: int = DEFAULT_RECORD_BYTES,
        period: float = 0.2,
    ) -> None:
        self.history = history
        self.path = Path(path)
        self.max_bytes = max_bytes
        self.period = period
        self.written = 0
        self.bytes = 0
        self.full = False
        self._last = -1
        self._mind_written = -1
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._file: IO[str] = self.path.open("w", encoding="utf-8")
        self._line(header(source))
        self._thread = threading.Thread(target=self._run, name="inspector-log", daemon=True)
        self._thread.start()

    def _line(self, obj: dict[str, Any]) -> None:
        text = dumps(obj) + "\n"
        self._file.write(text)
        self.bytes += len(text.encode("utf-8"))

    def flush(self) -> None:
        """Write whatever the history gained since the last flush."""
        with self._lock:
            self._flush()

    def _flush(self) -> None:
        if self.full or self._file.closed:
            return
        for snap in self.history.since(self._last):
            obj = snap.to_json(with_mind=snap.mind_seq > self._mind_written)
            if "mind" in obj:
                self._mind_written = snap.mind_seq
            text = dumps(obj) + "\n"
            size = len(text.encode("utf-8"))
            if self.bytes + size > self.max_bytes or size > MAX_LINE:
                self._line({"end": "size limit", "bytes": self.bytes})
                self.full = True
                break
            self._file.write(text)
            self.bytes += size
            self.written += 1
            self._last = snap.seq
        self._file.flush()

    def _run(self) -> None:
        while not self._stop.wait(self.period):
            self.flush()

    def close(self) -> None:
        """Write the rest and close the file."""
        self._stop.set()
        self._thread.join(timeout=5)
        with self._lock:
            self._flush()
            self._file.close()


def _expect(cond: bool, lineno: int, what: str) -> None:
    if not cond:
        raise LogError(f"line {lineno}: {what}")


def read_log(path: Path, capacity: int = 100_000) -> tuple[dict[str, Any], History]:
    """Read a log written by :class:`LogWriter`: its header and a History of its
    snapshots (the newest ``capacity``). Raises LogError naming the first bad line."""
    path = Path(path)
    size = path.stat().st_size
    if size > MAX_FILE:
        raise LogError(f"{path}: {size} bytes, more than the {MAX_FILE} a log may have")
    history = History(capacity)
    head: dict[str, Any] | None = None
    mind: dict[str, Any] | None = None
    last_seq = -1
    with path.open("rb") as f:
        for lineno, raw in enumerate(iter(lambda: f.readline(MAX_LINE + 1), b""), start=1):
            _expect(len(raw) <= MAX_LINE, lineno, f"longer than {MAX_LINE} bytes")
            try:
                obj = json.loads(raw.decode("utf-8"))
            except (UnicodeDecodeError, ValueError) as exc:
                raise LogError(f"line {lineno}: not JSON ({exc})") from exc
            _expect(isinstance(obj, dict), lineno, "not a JSON object")
            if head is None:
                _expect(obj.get("format") == FORMAT, lineno, f"not a {FORMAT} log (no header)")
                _expect(
                    obj.get("version") == VERSION,
                    lineno,
                    f"version {obj.get('version')!r}, expected {VERSION}",
                )
                head = obj
                continue
            if "end" in obj:
                head["end"] = str(obj["end"])
                continue
            seq = obj.get("seq")
            _expect(type(seq) is int and seq > last_seq, lineno, "seq missing or not increasing")
            _expect(isinstance(obj.get("world"), dict), lineno, "world is not an object")
            _expect(isinstance(obj.get("run", ""), str), lineno, "run is not text")
            _expect(type(obj.get("cycle", 0)) is int, lineno, "cycle is not an integer")
            _expect(isinstance(obj.get("stats", {}), dict), lineno, "stats is not an object")
            _expect(isinstance(obj.get("actions", []), list), lineno, "actions is not a list")
            mind_seq = obj.get("mind_seq", -1)
            _expect(type(mind_seq) is int and mind_seq <= seq, lineno, "mind_seq is bad")
            if "mind" in obj:
                _expect(
                    obj["mind"] is None or isinstance(obj["mind"], dict),
                    lineno,
                    "mind is not an object",
                )
                mind = obj["mind"]
            wall = obj.get("wall", 0.0)
            _expect(isinstance(wall, int | float), lineno, "wall is not a number")
            history.add(
                Snapshot(
                    seq=seq,
                    run=obj.get("run", ""),
                    cycle=obj.get("cycle", 0),
                    wall=float(wall),
                    world=obj["world"],
                    mind=mind,
                    mind_seq=mind_seq,
                    stats=obj.get("stats", {}),
                    actions=obj.get("actions", []),
                )
            )
            last_seq = seq
    if head is None:
        raise LogError(f"{path}: empty, not a {FORMAT} log")
    return head, history
