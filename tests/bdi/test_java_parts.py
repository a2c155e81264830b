"""Java parts of a Jason project: a clear error naming each, or its Python counterpart."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from robocog.bdi.parser import ParseError
from robocog.bdi.project import build, read_project, run_files


def _project(tmp_path: Path, mas: str, **files: str) -> Path:
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    path = tmp_path / "p.mas2j"
    path.write_text(mas, encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("section", "kind", "hint"),
    [
        ("environment: RoomEnv(3)", "environment RoomEnv", "RoomEnv.py"),
        ("executionControl: MyController", "executionControl MyController", "no Python"),
    ],
)
def test_a_java_class_of_the_project_stops_with_its_name_and_place(
    tmp_path: Path, section: str, kind: str, hint: str
) -> None:
    path = _project(
        tmp_path, f"MAS p {{\n    {section}\n    agents: a;\n}}\n", **{"a.asl": "!g.\n"}
    )
    (tmp_path / f"{kind.split()[1]}.java").write_text("class X {}\n", encoding="utf-8")
    with pytest.raises(ParseError) as err:
        build(read_project(path))
    msg = str(err.value)
    assert msg.startswith(f"{path}:2:")
    assert kind in msg and f"({kind.split()[1]}.java)" in msg and hint in msg


@pytest.mark.parametrize(
    "part", ["agentArchClass arch.Spy", "agentClass MyAg", "beliefBaseClass VoidBB"]
)
def test_agent_classes_in_java_are_errors_naming_them(tmp_path: Path, part: str) -> None:
    path = _project(tmp_path, f"MAS p {{ agents: a {part}; }}\n", **{"a.asl": "!g.\n"})
    with pytest.raises(ParseError, match=f"{part.split()[0]} {part.split()[1]} is a Java class"):
        build(read_project(path))


def test_a_library_internal_action_without_python_names_its_call(tmp_path: Path) -> None:
    path = _project(
        tmp_path,
        "MAS p { agents: a; }\n",
        **{"a.asl": "!g.\n+!g <- .print(x);\n   jia.dist(1, 2, D).\n"},
    )
    with pytest.raises(ParseError) as err:
        build(read_project(path))
    assert str(err.value).startswith(f"{tmp_path / 'a.asl'}:3:")
    assert "internal action jia.dist" in str(err.value) and "jia.py" in str(err.value)


ENV = """
from robocog.bdi.environment import Environment


class Door(Environment):
    def init(self, args):
        self.add_percept(f"size({args[0]})")
        self.add_percept("locked(door)", agent="a")

    def execute_action(self, agent, action):
        if action.functor == "unlock":
            self.remove_percept("locked(door)", agent="a")
            self.add_percept("unlocked(door)")
            return True
        return False
"""

LIB = """
from robocog.bdi.environment import internal_action


@internal_action
def dist(agent, x, y, out):
    return (None, None, abs(x - y))
"""

ARCH = """
from robocog.bdi.environment import AgentArch


class Spy(AgentArch):
    seen = []

    def act(self, action, do):
        Spy.seen.append(str(action))
        return do(action)
"""


def test_python_environment_library_and_architecture(tmp_path: Path) -> None:
    path = _project(
        tmp_path,
        "MAS p {\n environment: door_env.Door(7)\n agents: a agentArchClass spy.Spy; b;\n}\n",
        **{
            "door_env.py": ENV,
            "jia.py": LIB,
            "spy.py": ARCH,
            "a.asl": "+locked(D) : size(S) <- .print(locked, D, S); unlock.\n"
            "+unlocked(D) <- jia.dist(3, 10, X); .print(X).\n",
            "b.asl": "+unlocked(D)[source(percept)] <- .print(saw, D).\n",
        },
    )
    out = io.StringIO()
    run_files([path], lambda ag, line: out.write(f"[{ag}] {line}\n"))
    lines = out.getvalue().splitlines()
    assert [x for x in lines if x.startswith("[a]")] == ["[a] lockeddoor7", "[a] 7"]
    assert [x for x in lines if x.startswith("[b]")] == ["[b] sawdoor"]
    import sys

    spy = next(m for k, m in sys.modules.items() if k.endswith("_spy"))
    assert spy.Spy.seen == ["unlock"]


def test_jason_belief_bases_and_jade_run_here(tmp_path: Path) -> None:
    # Jason 3.3 prints: [bob] Boss 2 is: Boissier (IndexedBB replaces by key)
    path = _project(
        tmp_path,
        'MAS p {\n infrastructure: Jade(main_container_host("localhost"))\n agents: bob'
        " beliefBaseClass jason.bb.ChainBB(jason.bb.TextPersistentBB, "
        'jason.bb.IndexedBB("boss(key,_)")) at "c1";\n}\n',
        **{
            "bob.asl": '!s.\n+!s <- +boss(1,"V"); +boss(2,"R"); +boss(2,"Boissier"); '
            '.count(boss(_,_),N); ?boss(2,X); .print("Boss 2 is: ",X," of ",N).\n'
        },
    )
    notes: list[str] = []
    out: list[str] = []
    mas = build(read_project(path), lambda ag, line: out.append(line), notes=notes)
    mas.run(real_time=True)
    assert out == ["Boss 2 is: Boissier of 2"]
    assert any("Jade" in n for n in notes) and any("not persisted" in n for n in notes)


def test_the_room_example_runs_with_its_python_environment(capfd: pytest.CaptureFixture) -> None:
    # Jason 3.3 with the Java RoomEnv prints "Agent porter is doing unlock", then
    # "... lock", alternating for ever
    room = Path(__file__).parents[2] / "examples" / "jason" / "room" / "room.mas2j"
    mas = build(read_project(room), lambda ag, line: None)
    mas.run(max_rounds=60, real_time=False)
    lines = capfd.readouterr().out.splitlines()
    assert len(lines) >= 4
    assert lines[:4] == [
        "Agent porter is doing unlock",
        "Agent porter is doing lock",
        "Agent porter is doing unlock",
        "Agent porter is doing lock",
    ]


def test_the_domestic_robot_runs_with_its_python_house(capfd: pytest.CaptureFixture) -> None:
    # Jason 3.3 with the Java HouseEnv (nogui) starts with these actions; the 100 ms the
    # Java environment sleeps after each one is kept, so this takes about 1.5 s
    import time

    project = Path(__file__).parents[2] / "examples/jason/domestic-robot/domestic_robot.mas2j"
    mas = build(read_project(project), lambda ag, line: print(f"[{ag}] {line}"))
    robot = mas.agents["robot"]
    give_up = time.monotonic() + 30
    mas.run(
        real_time=True,
        until=lambda: bool(robot.query("consumed(_,_,_,_,_,_,beer)")) or time.monotonic() > give_up,
    )
    lines = capfd.readouterr().out.splitlines()
    robot = [x for x in lines if x.startswith("[robot] doing")]
    fridge = ["[robot] doing: move_towards(fridge)"] * 3
    owner = ["[robot] doing: move_towards(owner)"] * 6
    assert robot[:13] == [
        *fridge,
        "[robot] doing: open(fridge)",
        "[robot] doing: get(beer)",
        "[robot] doing: close(fridge)",
        *owner,
        "[robot] doing: hand_in(beer)",
    ]
    assert "[owner] doing: sip(beer)" in lines
