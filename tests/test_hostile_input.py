"""Bounds found by fuzzing, each as a documented limit with a clear error (the kept
cases of tests/fuzz replay the inputs themselves; these state the rules)."""

from __future__ import annotations

import os
import zlib
from pathlib import Path

import pytest

from robocog.nars.narsese import NarseseError, parse_sentence


@pytest.mark.parametrize("line", ["(&&, a).", "(&/, x)!", "(||, a)?", "<(&&, a) --> b>."])
def test_one_component_compounds_are_refused(line: str) -> None:
    with pytest.raises(NarseseError, match="needs two components"):
        parse_sentence(line)


def test_unary_forms_ona_has_still_read() -> None:
    assert str(parse_sentence("(*, a).").term) == "(* a)"
    assert str(parse_sentence("(! a).").term) == "(! a)"


# ---------------------------------------------------------------- PDDL
def test_pddl_bounds() -> None:
    from robocog.planning import pddl
    from robocog.planning.pddl import PDDLError, read_domain, read_problem

    with pytest.raises(PDDLError, match=r"\(:domain NAME\)"):
        read_problem("(define (problem p) (:domain ))")
    deep = "(define (domain d) (:predicates (p)) (:action a :parameters () :precondition "
    deep += "(and " * 1500 + "(p)" + ")" * 1500 + " :effect (p)))"
    with pytest.raises(PDDLError, match="MAX_DEPTH"):
        read_domain(deep)
    with pytest.raises(PDDLError, match="MAX_PDDL_BYTES"):
        read_domain("(" + "a " * pddl.MAX_PDDL_BYTES + ")")
    name = "x" * 1_000_000
    with pytest.raises(PDDLError) as info:
        read_domain(f"(define (domain d) ({name}))")
    assert len(str(info.value)) < 600


def test_pddl_grounding_is_limited() -> None:
    from robocog.planning.pddl import (
        MAX_GROUND_ACTIONS,
        PDDLError,
        ground,
        read_domain,
        read_problem,
    )

    dom = read_domain(
        "(define (domain d) (:predicates (r ?a ?b ?c))"
        " (:action act :parameters (?a ?b ?c) :precondition (r ?a ?b ?c) :effect (not (r ?a ?b ?c))))"
    )
    objs = " ".join(f"o{i}" for i in range(200))
    prob = read_problem(f"(define (problem p) (:domain d) (:objects {objs}) (:init) (:goal (and)))")
    with pytest.raises(PDDLError, match="MAX_GROUND_ACTIONS"):
        ground(dom, prob)
    assert 200**3 > MAX_GROUND_ACTIONS


def test_pddl_files_that_are_not_utf8_are_refused_with_a_position(tmp_path: Path) -> None:
    from robocog.planning.pddl import PDDLError, read_file

    p = tmp_path / "d.pddl"
    p.write_bytes(b"(define\n  (domain \xff))")
    with pytest.raises(PDDLError, match=r":2:11: not UTF-8"):
        read_file(p)


# ---------------------------------------------------------------- AgentSpeak
def test_twenty_thousand_annotations_read_without_duplicates() -> None:
    from robocog.bdi.parser import parse_literal

    annots = ",".join(f"a{i % 15_000}" for i in range(20_000))
    lit = parse_literal(f"p[{annots}]")
    assert len(lit.annots) == 15_000


def test_agentspeak_and_mas2j_sizes_are_limited(tmp_path: Path) -> None:
    from robocog.bdi.parser import MAX_PROGRAM_CHARS, ParseError, parse_program
    from robocog.bdi.project import read_project

    with pytest.raises(ParseError, match="MAX_PROGRAM_CHARS"):
        parse_program("b.\n" * (MAX_PROGRAM_CHARS // 3 + 1))
    p = tmp_path / "x.mas2j"
    p.write_text("MAS m { agents: " + "a; " * 40_000 + "}")
    with pytest.raises(ParseError, match="MAX_PROJECT_CHARS"):
        read_project(p)


# ---------------------------------------------------------------- saved memories
def _saved(tmp_path: Path) -> Path:
    from robocog.nars.nar import NAR

    nar = NAR(seed=1)
    nar.output = lambda line: None  # type: ignore[method-assign]
    nar.add_input("<a --> b>.")
    path = tmp_path / "m.nar"
    nar.save(path)
    return path


def test_memories_are_read_from_regular_files_only(tmp_path: Path) -> None:
    from robocog.nars.memfile import load_file
    from robocog.nars.memfile_io import MemoryFileError

    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    with pytest.raises(MemoryFileError, match="not a regular file"):
        load_file(fifo)  # (would block for ever if opened for reading)
    with pytest.raises(MemoryFileError, match="not a regular file"):
        load_file("/dev/zero")


def test_trailing_data_and_second_members_are_refused(tmp_path: Path) -> None:
    from robocog.nars.memfile import load_file
    from robocog.nars.memfile_io import MemoryFileError

    path = _saved(tmp_path)
    good = path.read_bytes()
    for extra in (b"garbage", good):
        path.write_bytes(good + extra)
        with pytest.raises(MemoryFileError, match="after the compressed memory"):
            load_file(path)


def test_a_gzip_bomb_is_refused_at_its_bound(tmp_path: Path) -> None:
    from robocog.nars.memfile import load_file
    from robocog.nars.memfile_io import MIN_EXPANDED_BYTES, MemoryFileError

    c = zlib.compressobj(9, zlib.DEFLATED, 31)
    text = b'{"format":"robocog-nar-memory"' + b" " * (MIN_EXPANDED_BYTES + 10) + b"}"
    path = tmp_path / "bomb.nar"
    path.write_bytes(c.compress(text) + c.flush())
    with pytest.raises(MemoryFileError, match="decompresses to more than"):
        load_file(path)


# ---------------------------------------------------------------- services and topics
def test_deep_json_is_a_400_and_a_foreign_origin_a_403() -> None:
    from starlette.testclient import TestClient

    from robocog.inspector.hub import Inspector
    from robocog.inspector.server import make_app

    c = TestClient(make_app(Inspector()), base_url="http://127.0.0.1")
    json_headers = {"content-type": "application/json"}
    r = c.post("/api/command", content=b"[" * 5000 + b"]" * 5000, headers=json_headers)
    assert r.status_code == 400
    body = b'{"kind": "pause"}'
    evil = {**json_headers, "origin": "http://evil.example"}
    assert c.post("/api/command", content=body, headers=evil).status_code == 403
    own = {**json_headers, "origin": "http://127.0.0.1"}
    assert c.post("/api/command", content=body, headers=own).status_code == 202
    assert c.post("/api/command", content=body, headers=json_headers).status_code == 202


def test_absurd_finite_readings_are_dropped_and_counted() -> None:
    from robocog.bridges.body import RobotBody
    from robocog.bridges.perception import BoxReading, PoseReading, ScanReading
    from robocog.robot.percepts import Detection, Pose

    class Link:
        def start(self, body: object) -> None: ...
        def close(self) -> None: ...
        def send_velocity(self, linear: float, angular: float) -> None: ...

    body = RobotBody(Link())  # type: ignore[arg-type]
    body.on_boxes(
        [
            BoxReading("cup", 2.0, 10.0),
            BoxReading("cup", -5.0, 10.0),
            BoxReading("cup", 1e308, 10.0),
            BoxReading("cup", 0.5, 10.0, (1e308, 0.0, 0.0)),
            BoxReading("cup", 0.5, 10.0),
        ]
    )
    body.on_pose(PoseReading(1e308, 0.0, 0.0))
    body.on_scan(ScanReading(1e308, 1e308, 0.1, 10.0, [1.0, 2.0]))
    got = body.percepts()
    assert [p.confidence for p in got if isinstance(p, Detection)] == [0.5]
    assert not [p for p in got if isinstance(p, Pose)]
    assert body.dropped == {"detection": 4, "pose": 1, "scan": 1}
