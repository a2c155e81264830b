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
class ClassRef:
    """A class a project names (``environment: RoomEnv(3)``), with its arguments and
    where it is written."""

    kind: str
    name: str
    args: list[Any] = field(default_factory=list)
    line: int = 1
    column: int = 1


@dataclass
class AgentDecl:
    """One line of a project's ``agents:`` section."""

    name: str
    file: str | None = None
    options: dict[str, Any] = field(default_factory=dict)
    instances: int = 1
    line: int = 1
    column: int = 1
    classes: list[ClassRef] = field(default_factory=list)


@dataclass
class Project:
    """What a ``.mas2j`` file says."""

    name: str
    path: Path
    agents: list[AgentDecl]
    infrastructure: str = "Local"
    environment: str | None = None
    asl_path: list[str] = field(default_factory=list)
    #: the environment, execution control, directives and infrastructure classes named
    classes: list[ClassRef] = field(default_factory=list)


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


def _class_ref(kind: str, tree: lark.Tree) -> ClassRef:
    """``Name(arg, ...)`` as a :class:`ClassRef` (arguments as Python values)."""
    ref = ClassRef(kind, str(tree.children[0]), line=tree.meta.line, column=tree.meta.column)
    for a in tree.children[1:]:
        if a is None:
            continue
        if isinstance(a, lark.Tree):  # a name, or a nested class with arguments
            ref.args.append(
                _class_ref("argument", a) if len(a.children) > 1 else str(a.children[0])
            )
        elif a.type == "NUMBER":
            # (a whole number of thousands of digits is beyond int(): kept as a float)
            ref.args.append(float(a) if "." in a or len(a) > 300 else int(a))
        else:
            ref.args.append(_text(a))
    return ref


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
            ref = _class_ref("infrastructure", section.children[0])
            project.infrastructure = ref.name
            project.classes.append(ref)
        elif kind == "environment":
            project.environment = _class_name(section.children[0])
            project.classes.append(_class_ref("environment", section.children[0]))
        elif kind == "execution_control":
            project.classes.append(_class_ref("executionControl", section.children[0]))
        elif kind == "directives":
            for ref in section.children[1::2]:
                project.classes.append(_class_ref("directive", ref))
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
            text = str(part.children[0])
            try:
                n = int(float(text))
            except (OverflowError, ValueError):  # 1e999 is infinite, nan no count
                n = 0
            if not 1 <= n <= MAX_AGENTS:
                raise ParseError(
                    f"#{text[:40]}: between 1 and {MAX_AGENTS} instances",
                    out.line,
                    out.column,
                    str(path),
                )
            out.instances = n
        elif part.data in ("arch", "agent_class", "bb_class"):
            what = {"arch": "agentArchClass", "agent_class": "agentClass"}.get(
                part.data, "beliefBaseClass"
            )
            out.classes.append(_class_ref(what, part.children[0]))
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


#: what a project may name that robocog does itself (Jason's own classes)
_JASON_OWN = {
    "infrastructure": {"Local", "Centralised", "Jade"},
    "agentArchClass": {"jason.architecture.AgArch"},
    "agentClass": {"jason.asSemantics.Agent"},
    "beliefBaseClass": {"jason.bb.DefaultBeliefBase", "jason.bb.ChainBB", "jason.bb.IndexedBB"},
    # Jason's synchronous mode: every agent one cycle per step, as robocog's rounds
    "executionControl": {"jason.control.ExecutionControl"},
}
#: Jason's persistent belief bases: robocog keeps beliefs in memory (a note says so)
_NOT_PERSISTED = {"jason.bb.TextPersistentBB", "jason.bb.JDBCPersistentBB"}

#: how to write each kind of Java part in Python (docs/bdi.md, "Java parts in Python")
_HOW = {
    "environment": "a subclass of robocog.bdi.environment.Environment",
    "agentArchClass": "a subclass of robocog.bdi.environment.AgentArch",
    "agentClass": "a subclass of robocog.bdi.agent.Agent",
}


def java_part(project: Project, ref: ClassRef, what: str | None = None) -> ParseError:
    """The error for a Java class robocog cannot run: it names the class, where the
    project names it, the ``.java`` file if the project has it, and what to write."""
    name = ref.name
    cls = name.rpartition(".")[2]
    java = next(iter(sorted(project.path.parent.rglob(f"{cls}.java"))), None)
    where = f" ({java.relative_to(project.path.parent)})" if java is not None else ""
    kind = what or ref.kind
    how = _HOW.get(ref.kind)
    if ref.kind == "internal action":
        lib, _, fn = name.rpartition(".")
        fix = (
            f"write it in Python as {lib.replace('.', '/')}.py beside the project, with a "
            f"function {fn} marked @internal_action (see docs/bdi.md, Java parts in Python)"
        )
    elif how is not None:
        module = name.rpartition(".")[0] or name
        fix = (
            f"write it in Python as {module.replace('.', '/')}.py beside the project, "
            f"holding class {cls}, {how} (see docs/bdi.md, Java parts in Python)"
        )
    else:
        fix = "it has no Python counterpart in robocog (see docs/bdi.md, Java parts in Python)"
    return ParseError(
        f"{kind} {name} is a Java class{where} and robocog runs no Java: {fix}",
        ref.line,
        ref.column,
        str(project.path),
    )


def _folders(project: Project) -> list[Path]:
    folder = project.path.parent
    return [folder, *(folder / d for d in project.asl_path)]


def _python_class(project: Project, ref: ClassRef, base: type) -> type:
    from robocog.bdi.environment import find_class

    try:
        cls = find_class(_folders(project), ref.name)
    except Exception as exc:  # noqa: BLE001 - the user's module failed to load
        raise ParseError(
            f"{ref.kind} {ref.name}: loading its Python file failed: {exc}",
            ref.line,
            ref.column,
            str(project.path),
        ) from None
    if cls is None:
        raise java_part(project, ref)
    if not (isinstance(cls, type) and issubclass(cls, base)):
        raise ParseError(
            f"{ref.kind} {ref.name} is not a subclass of {base.__module__}.{base.__name__}",
            ref.line,
            ref.column,
            str(project.path),
        )
    return cls


def _bb_keys(project: Project, ref: ClassRef, keys: dict, notes: list[str]) -> None:
    """Jason's belief base classes: ``IndexedBB("f(key,_)")`` sets unique keys,
    ``ChainBB(...)`` chains its arguments, the persistent ones keep beliefs in memory."""
    if ref.name in _NOT_PERSISTED:
        notes.append(f"{ref.name}: robocog keeps the beliefs in memory (not persisted)")
        return
    if ref.name not in _JASON_OWN["beliefBaseClass"]:
        raise java_part(project, ref)
    for a in ref.args:
        if isinstance(a, ClassRef):
            _bb_keys(project, ClassRef(ref.kind, a.name, a.args, ref.line, ref.column), keys, notes)
        elif isinstance(a, str) and ref.name == "jason.bb.IndexedBB":
            pattern = parse_literal(a)
            positions = tuple(
                n
                for n, t in enumerate(pattern.args)
                if isinstance(t, Literal) and t.functor == "key"
            )
            keys[(pattern.functor, len(pattern.args))] = positions
        elif isinstance(a, str) and a in _NOT_PERSISTED:
            notes.append(f"{a}: robocog keeps the beliefs in memory (not persisted)")
        elif isinstance(a, str) and a not in _JASON_OWN["beliefBaseClass"]:
            raise java_part(project, ClassRef(ref.kind, a, [], ref.line, ref.column))


def resolve_classes(
    project: Project, environment: Callable[[str, Literal], Any] | None
) -> tuple[Callable[[str, Literal], Any] | None, list[str]]:
    """Check every class the project names: Jason's own are done by robocog, the
    others must be Python files beside the project; returns the environment to use
    and notes for the user (differences that do not stop the run)."""
    from robocog.bdi.environment import Environment

    notes: list[str] = []
    for ref in project.classes:
        if ref.kind == "infrastructure":
            if ref.name not in _JASON_OWN["infrastructure"]:
                raise ParseError(
                    f"infrastructure {ref.name} is not available: robocog runs every "
                    "project in one process (write Local)",
                    ref.line,
                    ref.column,
                    str(project.path),
                )
            for a in ref.args:
                if isinstance(a, ClassRef) and a.name == "container_allocation":
                    cls = next((x for x in a.args if isinstance(x, str)), "?")
                    raise java_part(
                        project, ClassRef("agent allocator", cls, [], ref.line, ref.column)
                    )
            if ref.name == "Jade":
                notes.append("infrastructure Jade: the agents run in one process, as Local")
        elif ref.kind == "environment":
            if environment is not None:
                continue  # given by the caller (``--env``)
            cls = _python_class(project, ref, Environment)
            try:
                env = cls()
                env.init([a.name if isinstance(a, ClassRef) else a for a in ref.args])
            except Exception as exc:  # noqa: BLE001 - the user's environment failed
                raise ParseError(
                    f"environment {ref.name}: starting it failed: {exc.__class__.__name__}: {exc}",
                    ref.line,
                    ref.column,
                    str(project.path),
                ) from None
            environment = env
        elif ref.name not in _JASON_OWN.get(ref.kind, ()):
            raise java_part(project, ref)  # directives, execution control: Java only
    return environment, notes


def build(
    project: Project,
    printer: Callable[[str, str], None] | None = None,
    environment: Callable[[str, Literal], Any] | None = None,
    notes: list[str] | None = None,
) -> MultiAgentSystem:
    """The system of agents a project describes, ready to run. Classes the project
    names are checked first (a Java one is an error naming it, see :func:`java_part`);
    ``notes`` receives what runs differently from Jason without stopping the run."""
    from robocog.bdi.environment import AgentArch

    environment, found = resolve_classes(project, environment)
    if notes is not None:
        notes += found
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
        agent_class: type = Agent
        arch_class: type | None = None
        keys: dict = {}
        for ref in decl.classes:
            if ref.name in _JASON_OWN.get(ref.kind, ()) and ref.kind != "beliefBaseClass":
                continue
            if ref.kind == "agentClass":
                agent_class = _python_class(project, ref, Agent)
            elif ref.kind == "agentArchClass":
                arch_class = _python_class(project, ref, AgentArch)
            else:
                _bb_keys(project, ref, keys, notes if notes is not None else [])
        for name in names:
            try:
                agent = agent_class(
                    text, name, file=str(source), printer=printer, asl_path=[str(d) for d in search]
                )
                if arch_class is not None:
                    agent.arch = arch_class(agent)
            except ParseError:
                raise
            except Exception as exc:  # noqa: BLE001 - the user's agent class failed
                raise ParseError(
                    f"agent {name}: making it failed: {exc.__class__.__name__}: {exc}",
                    decl.line,
                    decl.column,
                    str(project.path),
                ) from None
            try:  # Jason names a program relative to the project: file:a.asl
                agent.url = f"file:{source.relative_to(folder)}"
            except ValueError:
                pass
            if keys:
                agent.bb.unique_keys = keys
            _load_libraries(project, agent, source)
            for belief in _split_top(str(decl.options.get("beliefs", ""))):
                agent.add_belief(parse_literal(belief))
            for goal in _split_top(str(decl.options.get("goals", ""))):
                agent.add_goal(parse_literal(goal))
            mas.add(agent)
    return mas


def _load_libraries(project: Project, agent: Agent, source: Path) -> None:
    """Register the library internal actions the agent's plans call (``mylib.act``)
    from Python files beside the project; one with no Python file is an error naming
    it and where it is called."""
    from robocog.bdi.environment import library_actions, load_module

    for name, line in agent.library_calls():
        if agent.internal_action(name) is not None:
            continue
        lib = name.rpartition(".")[0]
        module = None
        for folder in _folders(project):
            try:
                module = load_module(folder, lib)
            except Exception as exc:  # noqa: BLE001 - the user's module failed to load
                raise ParseError(
                    f"internal action {name}: loading {lib}.py failed: {exc}", line, 1, str(source)
                ) from None
            if module is not None:
                break
        if module is not None:
            for full, fn in library_actions(module, lib).items():
                agent.register_internal_action(full, _library_action(fn))
        if agent.internal_action(name) is None:
            err = java_part(project, ClassRef("internal action", name, [], line, 1))
            raise ParseError(err.reason, line, 1, str(source))


def _library_action(fn: Callable) -> Callable:
    """A user's ``fn(agent, *args)`` as an internal action (see
    :func:`robocog.bdi.environment.internal_action`)."""
    from robocog.bdi.actions import from_python
    from robocog.bdi.logic import ActionError
    from robocog.bdi.unifier import resolve, unify

    def action(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
        try:
            result = fn(ag, *(resolve(a, s) for a in args))
        except ActionError:
            raise
        except Exception as exc:  # noqa: BLE001 - the user's code failed: the action fails
            raise ActionError(f"{getattr(fn, '__name__', 'action')}: {exc}") from None
        if result is None or result is True:
            return True
        if result is False:
            return False
        if isinstance(result, (tuple, list)):
            for a, v in zip(args, result, strict=False):
                if v is not None and not unify(a, from_python(v), s, trail):
                    return False
            return True
        raise ActionError(f"{getattr(fn, '__name__', 'action')}: returned {result!r}")

    return action


def run_files(
    paths: Sequence[str | Path],
    printer: Callable[[str, str], None] | None = None,
    max_rounds: int | None = None,
    environment: Callable[[str, Literal], Any] | None = None,
    real_time: bool = True,
    notes: list[str] | None = None,
) -> MultiAgentSystem:
    """Run one project file, or several ``.asl`` files as one system (each agent named
    after its file), until every agent is idle or ``.stopMAS``; ``real_time``: on the
    wall clock, as Jason runs them (see :meth:`MultiAgentSystem.run`)."""
    if len(paths) == 1 and str(paths[0]).endswith(".mas2j"):
        mas = build(read_project(paths[0]), printer, environment, notes)
    else:
        mas = MultiAgentSystem(environment)
        for path in paths:
            mas.add(Agent.from_file(path, printer=printer))
    mas.run(max_rounds, real_time=real_time)
    return mas
