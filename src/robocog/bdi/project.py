"""Jason projects: reading a ``.mas2j`` file and running the system it describes.

Every Jason project starts from a ``.mas2j``::

    MAS rescue {
        infrastructure: Local
        environment: rescue.env.Field
        agents: scout scout.asl [beliefs="zone(3)", goals="explore"] #3;
                base;
        aslSourcePath: "src/asl";
    }

An agent's program is ``NAME.asl`` unless a file is named, looked up beside the project,
then in each ``aslSourcePath`` folder; ``#N`` makes N agents ``NAME1`` .. ``NAMEN`` from
it (one agent keeps its name); ``beliefs`` and ``goals`` options add initial beliefs and
goals. Only the ``Local`` infrastructure exists here. The environment a project names is
Java in Jason; robocog runs a Python environment only when the user names its class
with ``--env module.Class`` (or passes one from Python), never one imported from the
file's text alone, since loading a module runs its code.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import lark

from robocog.bdi.agent import Agent
from robocog.bdi.mas import MultiAgentSystem
from robocog.bdi.parser import ParseError, parse_literal, read_source
from robocog.bdi.terms import Literal
from robocog.limits import clip

#: the most agents one project may start (a typo in ``#N`` should not eat the machine)
MAX_AGENTS = 10_000


@dataclass
class AgentDecl:
    """One line of a project's ``agents:`` section."""

    name: str
    file: str | None = None
    options: dict[str, Any] = field(default_factory=dict)
    instances: int = 1
    line: int = 1
    column: int = 1


@dataclass
class Project:
    """What a ``.mas2j`` file says."""

    name: str
    path: Path
    agents: list[AgentDecl]
    infrastructure: str = "Local"
    environment: str | None = None
    asl_path: list[str] = field(default_factory=list)


_lock = threading.Lock()
_parser: lark.Lark | None = None


def _grammar() -> lark.Lark:
    global _parser
    if _parser is None:
        text = (Path(__file__).parent / "mas2j.lark").read_text(encoding="utf-8")
        _parser = lark.Lark(text, parser="lalr", propagate_positions=True)
    return _parser


def _text(token: Any) -> str:
    s = str(token)
    if s.startswith('"') and s.endswith('"'):
        return s[1:-1].replace('\\"', '"').replace("\\\\", "\\")
    return s


def _class_name(tree: lark.Tree) -> str:
    return str(tree.children[0])


#: the largest project file read: a .mas2j names a few agents (lark reads one of this
#: size in about a second)
MAX_PROJECT_CHARS = 64 << 10


def read_project(path: str | Path) -> Project:
    """Read a ``.mas2j`` file; a malformed one is a ParseError with line and column."""
    p = Path(path)
    text = read_source(p)
    if len(text) > MAX_PROJECT_CHARS:
        raise ParseError(
            f"larger than {MAX_PROJECT_CHARS} characters (MAX_PROJECT_CHARS)", 1, 1, str(p)
        )
    with _lock:
        try:
            tree = _grammar().parse(text)
        except lark.exceptions.UnexpectedInput as exc:
            line, col = getattr(exc, "line", 1), getattr(exc, "column", 1)
            raise ParseError(f"not a Jason project: {_expected(exc)}", line, col, str(p)) from None
    project = Project(str(tree.children[0]), p, [])
    for section in tree.children[1:]:
        kind = section.data
        if kind == "infrastructure":
            project.infrastructure = str(section.children[0])
            if project.infrastructure != "Local":
                line, col = section.meta.line, section.meta.column
                raise ParseError(
                    f"not supported: infrastructure {project.infrastructure} (only Local)",
                    line,
                    col,
                    str(p),
                )
        elif kind == "environment":
            project.environment = _class_name(section.children[0])
        elif kind == "asl_path":
            project.asl_path += [_text(t) for t in section.children]
        elif kind == "agents":
            for decl in section.children:
                project.agents.append(_agent(decl, p))
    if not project.agents:
        raise ParseError("the project names no agent", 1, 1, str(p))
    return project


def _expected(exc: lark.exceptions.UnexpectedInput) -> str:
    if isinstance(exc, lark.exceptions.UnexpectedCharacters):
        return f"unexpected {exc.char!r}"
    if isinstance(exc, lark.exceptions.UnexpectedToken):
        return (
            "unexpected end of file"
            if exc.token.type == "$END"
            else f"unexpected {clip(str(exc.token), 40)}"
        )
    return "unexpected end of file"


def _agent(decl: lark.Tree, path: Path) -> AgentDecl:
    out = AgentDecl(str(decl.children[0]), line=decl.meta.line, column=decl.meta.column)
    for part in decl.children[1:]:
        if part is None:
            continue
        if part.data == "file":
            out.file = _text(part.children[0])
        elif part.data == "options":
            for option in part.children:
                if option is None:
                    continue
                key, value = option.children
                out.options[str(key)] = (
                    value.data == "true" if isinstance(value, lark.Tree) else _text(value)
                )
        elif part.data == "instances":
            n = int(float(str(part.children[0])))
            if not 1 <= n <= MAX_AGENTS:
                raise ParseError(
                    f"#{n}: between 1 and {MAX_AGENTS} instances", out.line, out.column, str(path)
                )
            out.instances = n
        elif part.data in ("arch", "agent_class", "bb_class"):
            what = {"arch": "agentArchClass", "agent_class": "agentClass"}.get(
                part.data, "beliefBaseClass"
            )
            raise ParseError(
                f"not supported: {what} (a Java class)", out.line, out.column, str(path)
            )
    return out


def _split_top(text: str) -> list[str]:
    """``"a(1), b"`` -> ``["a(1)", "b"]``: commas outside brackets and quotes."""
    parts, depth, quoted, start = [], 0, False, 0
    for i, ch in enumerate(text):
        if ch == '"' and (i == 0 or text[i - 1] != "\\"):
            quoted = not quoted
        elif not quoted and ch in "([{":
            depth += 1
        elif not quoted and ch in ")]}":
            depth -= 1
        elif not quoted and depth == 0 and ch == ",":
            parts.append(text[start:i].strip())
            start = i + 1
    parts.append(text[start:].strip())
    return [p for p in parts if p]


def build(
    project: Project,
    printer: Callable[[str, str], None] | None = None,
    environment: Callable[[str, Literal], Any] | None = None,
) -> MultiAgentSystem:
    """The system of agents a project describes, ready to run."""
    mas = MultiAgentSystem(environment)
    folder = project.path.parent
    search = [folder / d for d in project.asl_path]
    for decl in project.agents:
        file = decl.file or f"{decl.name}.asl"
        candidates = [folder / file, *(d / file for d in search)]
        source = next((c for c in candidates if c.is_file()), None)
        if source is None:
            raise ParseError(
                f"agent {decl.name}: no file {file} (looked at "
                + ", ".join(str(c) for c in candidates)
                + ")",
                decl.line,
                decl.column,
                str(project.path),
            )
        text = read_source(source)
        names = (
            [decl.name]
            if decl.instances == 1
            else [f"{decl.name}{k}" for k in range(1, decl.instances + 1)]
        )
        for name in names:
            agent = Agent(
                text, name, file=str(source), printer=printer, asl_path=[str(d) for d in search]
            )
            for belief in _split_top(str(decl.options.get("beliefs", ""))):
                agent.add_belief(parse_literal(belief))
            for goal in _split_top(str(decl.options.get("goals", ""))):
                agent.add_goal(parse_literal(goal))
            mas.add(agent)
    return mas


def run_files(
    paths: Sequence[str | Path],
    printer: Callable[[str, str], None] | None = None,
    max_rounds: int | None = None,
    environment: Callable[[str, Literal], Any] | None = None,
) -> MultiAgentSystem:
    """Run one project file, or several ``.asl`` files as one system (each agent named
    after its file), until every agent is idle or ``.stopMAS``."""
    if len(paths) == 1 and str(paths[0]).endswith(".mas2j"):
        mas = build(read_project(paths[0]), printer, environment)
    else:
        mas = MultiAgentSystem(environment)
        for path in paths:
            mas.add(Agent.from_file(path, printer=printer))
    mas.run(max_rounds)
    return mas
