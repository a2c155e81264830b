"""The readers under fuzzing: one target per entry point that takes outside input.

A target turns bytes into a call of the reader's public entry point, names the error
the reader documents for input it refuses (``refused``), and lists seeds: small inputs
kept in ``tests/fuzz/corpus/<target>/``, the project's own example files, and the peer
material of ``/work/shared`` when it is present (read at run time, never copied).

A target may raise :class:`Violation` for a result that must never come out of the
reader, whatever the input (a confidence of 2.0 reaching a mind, say): that counts as
a crash as well.
"""

from __future__ import annotations

import json
import math
import os
import tempfile
import zlib
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CORPUS = Path(__file__).with_name("corpus")
SHARED = Path(os.environ.get("ROBOCOG_FUZZ_SHARED", "/work/shared"))
#: at most this many seed files of one kind are read (the seeds stay a few hundred)
MAX_SEED_FILES = 60
#: seed files larger than this are left out (mutations make large inputs anyway)
MAX_SEED_BYTES = 256 << 10


class Violation(Exception):
    """A reader's result that must never come out of it."""


@dataclass
class Target:
    """One reader: how to call it, what it refuses with, where its seeds are."""

    name: str
    run: Callable[[bytes], object]
    refused: tuple[type[BaseException], ...]
    seeds: Callable[[], list[bytes]]
    tokens: tuple[bytes, ...] = ()
    brackets: tuple[tuple[bytes, bytes], ...] = ()
    doc: str = ""
    extra: dict[str, object] = field(default_factory=dict)


def _files(*patterns: tuple[Path, str]) -> list[bytes]:
    out: list[bytes] = []
    for base, pattern in patterns:
        if not base.is_dir():
            continue
        for p in sorted(base.glob(pattern))[:MAX_SEED_FILES]:
            try:
                if p.is_file() and p.stat().st_size <= MAX_SEED_BYTES:
                    out.append(p.read_bytes())
            except OSError:
                continue
    return out


def _corpus(name: str) -> list[bytes]:
    return _files((CORPUS / name, "*"))


def _lines(blobs: list[bytes], most: int = 400) -> list[bytes]:
    seen: dict[bytes, None] = {}
    for blob in blobs:
        for line in blob.splitlines():
            line = line.strip()
            if line and not line.startswith((b"//", b"'")):
                seen[line] = None
                if len(seen) >= most:
                    return list(seen)
    return list(seen)


def _text(data: bytes) -> str:
    """Bytes as the text a reader of strings gets: a file or a line is decoded as UTF-8
    by its caller, which reports invalid bytes itself; lone surrogates are kept (a
    Python caller may pass any str)."""
    if b"\xed" in data:
        try:
            return data.decode("utf-8", "surrogatepass")
        except UnicodeDecodeError:
            pass
    return data.decode("utf-8", "replace")


_TMP: list[Path] = []


def _tmpdir() -> Path:
    if not _TMP:
        base = "/dev/shm" if os.path.isdir("/dev/shm") else None
        _TMP.append(Path(tempfile.mkdtemp(prefix="robocog-fuzz-", dir=base)))
    return _TMP[0]


def _file(data: bytes, name: str) -> Path:
    p = _tmpdir() / name
    p.write_bytes(data)
    return p


# ------------------------------------------------------------------ Narsese
NARSESE_TOKENS = tuple(
    t.encode()
    for t in (
        "<",
        ">",
        "(",
        ")",
        "{",
        "}",
        "[",
        "]",
        ",",
        "-->",
        "<->",
        "==>",
        "=/>",
        "<=>",
        "&&",
        "&/",
        "||",
        "*",
        "&",
        "|",
        "-",
        "~",
        "/1",
        "\\2",
        "!",
        "?",
        ".",
        ":|:",
        "{1.0 0.9}",
        "%1;0.9%",
        "dt=5",
        "$1",
        "#1",
        "?1",
        "^op",
        "(&&, a)",
        "(&/, a)",
        "(--, a)",
        "(*, a)",
        " ",
    )
)
NARSESE_BRACKETS = ((b"(", b")"), (b"<", b">"), (b"(&&, ", b")"), (b"{", b"}"), (b"(! ", b")"))


def _narsese_seeds() -> list[bytes]:
    return _lines(_corpus("narsese") + _files((SHARED / "nal", "**/*.nal")))


def _narsese(data: bytes) -> object:
    from robocog.nars.narsese import parse_sentence

    s = parse_sentence(_text(data))
    # what is read must print as Narsese that reads back to the same term
    from robocog.nars.narsese import parse_pattern

    if parse_pattern(str(s.term)) is not s.term:
        raise Violation(f"{s.term} does not read back as itself")
    from robocog.nars.narsese import read_canonical

    if read_canonical(str(s.term)) is not s.term:  # (the saved memories' reader)
        raise Violation(f"{s.term} does not read back as itself from a memory")
    return s


def _shell_seeds() -> list[bytes]:
    lines = _narsese_seeds()
    out = _corpus("nars-shell")
    for i in range(0, len(lines), 6):
        out.append(b"\n".join(lines[i : i + 6]) + b"\n5\n")
    return out


#: cycle lines above this are skipped: a long run is work asked for, not a fault
SHELL_MAX_CYCLES = 200


def _shell(data: bytes) -> object:
    """Lines fed to a reasoner as ``robocog nar`` does (each line's errors refused)."""
    from robocog.nars.nar import NAR
    from robocog.nars.narsese import NarseseError

    nar = NAR(seed=1)  # a fresh one: a kept case must fail again on its own
    nar.output = lambda line: None  # type: ignore[method-assign]
    for raw in data.split(b"\n")[:200]:
        line = _text(raw).rstrip()
        if line.strip().isdigit() and int(line.strip()[:12]) > SHELL_MAX_CYCLES:
            continue
        if line.lstrip().startswith(("*save", "*load", "*concepts")):
            continue  # files: the memory targets; *concepts prints the whole memory
        try:
            nar.add_input(line)  # type: ignore[attr-defined]
        except NarseseError:
            pass
    return None


# ------------------------------------------------------------------ AgentSpeak
ASL_TOKENS = tuple(
    t.encode()
    for t in (
        "+!",
        "-!",
        "+?",
        "<-",
        ":",
        ";",
        ".",
        "[",
        "]",
        "(",
        ")",
        "{",
        "}",
        "|",
        "&",
        "not ",
        '"',
        "X",
        "_",
        "source(self)",
        ".print(",
        "if (",
        "while (",
        "for (",
        "~",
        "::",
        '{ include("x.asl") }',
        "[a,b,c,d,e]",
        "1e308",
    )
)
ASL_BRACKETS = ((b"(", b")"), (b"[", b"]"), (b"{", b"}"), (b"f(", b")"), (b"[a|", b"]"))


def _asl_seeds() -> list[bytes]:
    return _corpus("agentspeak") + _files(
        (ROOT / "src/robocog/bdi", "**/*.asl"),
        (SHARED / "asl", "**/*.asl"),
    )


def _asl(data: bytes) -> object:
    from robocog.bdi.parser import parse_program, read_source

    # through the file reader, as ``robocog jason`` reads a program (UTF-8 checked there)
    path = _file(data, "fuzz.asl")
    return parse_program(read_source(path), str(path))


def _mas2j_seeds() -> list[bytes]:
    return _corpus("mas2j") + _files((SHARED / "asl", "**/*.mas2j"), (ROOT / "tests", "**/*.mas2j"))


def _mas2j(data: bytes) -> object:
    from robocog.bdi.project import read_project

    return read_project(_file(data, "fuzz.mas2j"))


# ------------------------------------------------------------------ Atomese
SCM_TOKENS = tuple(
    t.encode()
    for t in (
        "(",
        ")",
        '"',
        "ConceptNode",
        "ListLink",
        "InheritanceLink",
        "EvaluationLink",
        "PredicateNode",
        "VariableNode",
        "DefineLink",
        "GetLink",
        "PutLink",
        "(stv 1 0.9)",
        "'",
        ";",
        "#t",
        "1e308",
    )
)


def _atomese_seeds() -> list[bytes]:
    return _corpus("atomese") + _files(
        (ROOT / "src/robocog", "**/*.scm"), (SHARED / "atomspace", "**/*.scm")
    )


def _atomese(data: bytes) -> object:
    from robocog.atomspace.atomese import load
    from robocog.atomspace.space import AtomSpace

    return load(_text(data), AtomSpace(), source="fuzz.scm")


# ------------------------------------------------------------------ PDDL
PDDL_TOKENS = tuple(
    t.encode()
    for t in (
        "(",
        ")",
        ":action",
        ":parameters",
        ":precondition",
        ":effect",
        "(and ",
        "(not ",
        "?x",
        " - ",
        ":types",
        ":objects",
        ":init",
        ":goal",
        ":domain",
        ":predicates",
        "(:domain )",
        ";",
        '"',
    )
)
PDDL_BRACKETS = ((b"(", b")"), (b"(and ", b")"), (b"(not ", b")"))


def _pddl_domains() -> list[bytes]:
    return _corpus("pddl-domain") + _files((SHARED / "pddl", "**/domain*.pddl"))


def _pddl_problems() -> list[bytes]:
    return _corpus("pddl-problem") + _files((SHARED / "pddl", "**/task*.pddl"))


def _pddl_domain(data: bytes) -> object:
    from robocog.planning.pddl import ground, read_domain, read_problem

    dom = read_domain(_text(data), "fuzz-domain.pddl")
    problems = _pddl_problems()
    prob = read_problem(problems[0].decode(), "problem.pddl")
    if prob.domain == dom.name:
        ground(dom, prob)
    return dom


def _pddl_problem(data: bytes) -> object:
    from robocog.planning.pddl import ground, read_domain, read_problem

    dom = read_domain(_pddl_domains()[0].decode(), "domain.pddl")
    prob = read_problem(_text(data), "fuzz-problem.pddl")
    ground(dom, prob)
    return prob


# ------------------------------------------------------------------ English goals
EN_TOKENS = tuple(
    t.encode()
    for t in ("The ", " is ", " on ", " top of ", " the ", "hand", "a fixed object", "clear", ".")
)


def _english(data: bytes) -> object:
    from robocog.planning.english import read_sentences

    return read_sentences(_text(data))


# ------------------------------------------------------------------ saved NARS memories
def _memory_seeds() -> list[bytes]:
    """A few memories saved by small sessions: plain JSON (the reader takes it too,
    and mutations of it reach every field check) and gzip."""
    from robocog.nars import memfile
    from robocog.nars.nar import NAR

    out = list(_corpus("nars-memory"))
    for lines in (
        ["<a --> b>.", "<b --> c>.", "5", "<a --> c>?"],
        ["<a --> b>. :|:", "<(a &/ ^left) =/> g>.", "g! :|:", "10"],
        ["*setopname 1 ^go", "<{x} --> [y]>.", "<(&&, p, q) ==> r>.", "3"],
    ):
        nar = NAR(seed=1)
        nar.output = lambda line: None  # type: ignore[method-assign]
        for line in lines:
            nar.add_input(line)
        raw = memfile.encode(nar)
        out.append(raw)
        out.append(zlib.decompress(raw, 31))
    text = out[-1]
    bomb = zlib.compressobj(9, zlib.DEFLATED, 31)
    out.append(bomb.compress(text[:-1] + b" " * (8 << 20) + b"}") + bomb.flush())
    out.append(out[-3] + out[-3])  # a second gzip member
    out.append(out[-4] + b"trailing garbage")
    return out


MEMORY_TOKENS = tuple(
    t.encode()
    for t in ('"', ",", ":", "[", "]", "{", "}", "null", "true", "-1", "1e308", "NaN", '"(&& a)"')
)


def _memory(data: bytes) -> object:
    from robocog.nars.nar import NAR

    nar = NAR.load(_file(data, "fuzz.mem"))
    # what loads must run (a few cycles) and save again
    nar.output = lambda line: None  # type: ignore[method-assign]
    nar.add_input("2")
    return None


# ------------------------------------------------------------------ SQLite AtomSpaces
def _sqlite_seeds() -> list[bytes]:
    from robocog.atomspace.atomese import load
    from robocog.atomspace.persist import store
    from robocog.atomspace.space import AtomSpace

    out = []
    texts = _atomese_seeds()[:4] or [b'(InheritanceLink (ConceptNode "a") (ConceptNode "b"))']
    for i, text in enumerate(texts):
        space = AtomSpace()
        try:
            load(text.decode("utf-8", "replace"), space)
        except Exception:  # noqa: BLE001 - a seed the reader refuses is left out
            continue
        path = _tmpdir() / f"seed{i}.db"
        if path.exists():
            path.unlink()
        store(space, path)
        out.append(path.read_bytes())
        path.unlink()
    return out


def _sqlite(data: bytes) -> object:
    from robocog.atomspace.persist import load

    path = _file(data, "fuzz.db")
    for extra in ("-journal", "-wal", "-shm"):
        side = Path(str(path) + extra)
        if side.exists():
            side.unlink()
    return load(path)


# ------------------------------------------------------------------ inspector API bodies
_CLIENT: list[object] = []


def _inspector_seeds() -> list[bytes]:
    return _corpus("inspector-api") + [
        b'{"kind": "narsese", "text": "<a --> b>."}',
        b'{"kind": "pause"}',
        b'{"kind": "step", "text": ""}',
        b'{"kind": "resume", "text": 5}',
        b"[1, 2, 3]",
    ]


def _inspector(data: bytes) -> object:
    """A body posted to ``/api/command``: anything but a 5xx answer is fine."""
    if not _CLIENT:
        from starlette.testclient import TestClient

        from robocog.inspector.hub import Inspector
        from robocog.inspector.server import make_app

        _CLIENT.append(TestClient(make_app(Inspector()), base_url="http://127.0.0.1"))
    client = _CLIENT[0]
    r = client.post(  # type: ignore[attr-defined]
        "/api/command", content=data, headers={"content-type": "application/json"}
    )
    if r.status_code >= 500:
        raise Violation(f"status {r.status_code}")
    return r.status_code


# ------------------------------------------------------------------ bridge messages
def _bridge_seeds() -> list[bytes]:
    return _corpus("bridge") + [
        json.dumps(m).encode()
        for m in (
            {
                "scan": {
                    "angle_min": -1.57,
                    "angle_increment": 0.01,
                    "range_min": 0.1,
                    "range_max": 10,
                    "ranges": [1.0, 2.0, 0.5, 3.0],
                }
            },
            {
                "boxes": [
                    {"label": "cup", "score": 0.9, "center_x": 320, "position": [1.0, 0.2, 0.0]}
                ]
            },
            {"pose": {"x": 1.0, "y": 2.0, "yaw": 0.5}},
            {"gripper": "cup"},
            {"text": "<a --> b>. :|:"},
        )
    ]


class _Link:
    def start(self, body: object) -> None: ...
    def close(self) -> None: ...
    def send_velocity(self, linear: float, angular: float) -> None: ...
    def send_goal(self, x: float, y: float, yaw: float) -> int:
        return 1

    def cancel_goals(self) -> None: ...
    def send_gripper(self, text: str) -> int | None:
        return None


def _bridge(data: bytes) -> object:
    """A message as a bridge decodes it, handed to the robot's body; the percepts a mind
    then gets must be finite and in range."""
    from robocog.bridges.body import RobotBody
    from robocog.bridges.perception import BoxReading, PoseReading, ScanReading

    try:
        msg = json.loads(data)
    except (ValueError, RecursionError):
        return None  # not a message: the middleware would not deliver it
    if not isinstance(msg, dict):
        return None
    body = RobotBody(_Link())

    def num(x: object) -> float:
        # as a middleware's float64 field holds it (an integer past a double's range
        # is infinite there)
        if isinstance(x, bool) or not isinstance(x, int | float):
            return 0.0
        try:
            return float(x)
        except OverflowError:
            return math.inf if x > 0 else -math.inf

    scan = msg.get("scan")
    if isinstance(scan, dict):
        ranges = scan.get("ranges")
        ranges = [num(r) for r in ranges[:2000]] if isinstance(ranges, list) else []
        body.on_scan(
            ScanReading(
                num(scan.get("angle_min")),
                num(scan.get("angle_increment")),
                num(scan.get("range_min")),
                num(scan.get("range_max")),
                ranges,
            )
        )
    boxes = msg.get("boxes")
    if isinstance(boxes, list):
        readings = []
        for b in boxes[:100]:
            if isinstance(b, dict):
                pos = b.get("position")
                pos = [num(x) for x in pos[:3]] if isinstance(pos, list) else []
                pos = (pos + [0.0, 0.0, 0.0])[:3]
                readings.append(
                    BoxReading(
                        str(b.get("label", ""))[:100],
                        num(b.get("score")),
                        num(b.get("center_x")),
                        tuple(pos),
                    )  # type: ignore[arg-type]
                )
        body.on_boxes(readings)
    pose = msg.get("pose")
    if isinstance(pose, dict):
        body.on_pose(PoseReading(num(pose.get("x")), num(pose.get("y")), num(pose.get("yaw"))))
    if isinstance(msg.get("gripper"), str):
        body.on_gripper(msg["gripper"][:1000])
    if isinstance(msg.get("text"), str):
        body.on_text(msg["text"][:10000])
    for p in body.percepts():
        _check_percept(p)
    return None


def _check_percept(p: object) -> None:
    for name in ("confidence", "bearing", "distance", "x", "y", "yaw"):
        v = getattr(p, name, None)
        if isinstance(v, float):
            if name == "distance" and math.isnan(v):
                continue  # "no distance known", as the detector says
            if not math.isfinite(v):
                raise Violation(f"{type(p).__name__}.{name} = {v}")
            if name == "confidence" and not 0.0 <= v <= 1.0:
                raise Violation(f"{type(p).__name__}.{name} = {v}")
            if name in ("x", "y", "distance") and abs(v) > 1e6:
                raise Violation(f"{type(p).__name__}.{name} = {v}")


# ------------------------------------------------------------------ the table
def _errors() -> dict[str, tuple[type[BaseException], ...]]:
    from robocog.atomspace.atomese import AtomeseError
    from robocog.atomspace.persist import StoreError
    from robocog.bdi.parser import ParseError
    from robocog.nars.memfile_io import MemoryFileError
    from robocog.nars.narsese import NarseseError
    from robocog.planning.english import EnglishError
    from robocog.planning.pddl import PDDLError
    from robocog.planning.sexpr import SexprError

    return {
        "narsese": (NarseseError,),
        "nars-shell": (),
        "agentspeak": (ParseError,),
        "mas2j": (ParseError,),
        "atomese": (AtomeseError,),
        "pddl-domain": (PDDLError, SexprError),
        "pddl-problem": (PDDLError, SexprError),
        "english": (EnglishError,),
        "nars-memory": (MemoryFileError,),
        "sqlite-atomspace": (StoreError,),
        "inspector-api": (),
        "bridge": (),
    }


def targets() -> dict[str, Target]:
    """Every target by name."""
    errors = _errors()
    table = [
        Target(
            "narsese",
            _narsese,
            (),
            _narsese_seeds,
            NARSESE_TOKENS,
            NARSESE_BRACKETS,
            "one line of Narsese (parse_sentence)",
        ),
        Target(
            "nars-shell",
            _shell,
            (),
            _shell_seeds,
            NARSESE_TOKENS
            + (b"\n", b"*volume=", b"*stampid=", b"*currenttime=", b"*setopname 1 ", b"\n3\n"),
            NARSESE_BRACKETS,
            "lines for a reasoner: Narsese, commands, cycles (NAR.add_input)",
        ),
        Target(
            "agentspeak",
            _asl,
            (),
            _asl_seeds,
            ASL_TOKENS,
            ASL_BRACKETS,
            "an AgentSpeak program file (parse_program)",
        ),
        Target(
            "mas2j",
            _mas2j,
            (),
            _mas2j_seeds,
            ASL_TOKENS + (b"agents:", b"MAS ", b"infrastructure:"),
            ASL_BRACKETS,
            "a Jason project file (read_project)",
        ),
        Target(
            "atomese",
            _atomese,
            (),
            _atomese_seeds,
            SCM_TOKENS,
            ((b"(", b")"), (b"(ListLink ", b")")),
            "Atomese text (atomese.load)",
        ),
        Target(
            "pddl-domain",
            _pddl_domain,
            (),
            _pddl_domains,
            PDDL_TOKENS,
            PDDL_BRACKETS,
            "a PDDL domain, grounded with a problem (read_domain, ground)",
        ),
        Target(
            "pddl-problem",
            _pddl_problem,
            (),
            _pddl_problems,
            PDDL_TOKENS,
            PDDL_BRACKETS,
            "a PDDL problem, grounded (read_problem, ground)",
        ),
        Target(
            "english",
            _english,
            (),
            lambda: _corpus("english"),
            EN_TOKENS,
            ((b"The ", b" is clear."),),
            "English goal sentences (read_sentences)",
        ),
        Target(
            "nars-memory",
            _memory,
            (),
            _memory_seeds,
            MEMORY_TOKENS,
            ((b"[", b"]"), (b'{"a":', b"}")),
            "a saved NARS memory file (NAR.load)",
        ),
        Target(
            "sqlite-atomspace",
            _sqlite,
            (),
            _sqlite_seeds,
            (b"\x00", b"SQLite format 3\x00"),
            (),
            "an SQLite AtomSpace file (persist.load)",
        ),
        Target(
            "inspector-api",
            _inspector,
            (),
            _inspector_seeds,
            (b'"kind"', b'"text"', b"\\u0000", b"\\ud800"),
            ((b"[", b"]"), (b'{"a":', b"}")),
            "a JSON body posted to the inspector's /api/command",
        ),
        Target(
            "bridge",
            _bridge,
            (),
            _bridge_seeds,
            (b"1e308", b"-1e308", b"2.0", b"-5", b"NaN"),
            ((b"[", b"]"),),
            "robot messages handed to the bridge's body (RobotBody.on_*, percepts)",
        ),
    ]
    for t in table:
        t.refused = errors[t.name]
    return {t.name: t for t in table}


def iter_names() -> Iterator[str]:
    """The targets' names, in the table's order."""
    yield from targets()
