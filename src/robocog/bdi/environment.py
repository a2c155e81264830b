"""Environments, internal action libraries and agent architectures written in Python.

A Jason project names Java classes for the parts AgentSpeak does not cover: the
environment (``environment: RoomEnv``), internal action libraries (``jia.dist(...)``
called in a program, ``jia/dist.java`` in the project), agent architectures. robocog runs
no Java; it takes the same parts written in Python, from ``.py`` files in the project's
own folder (the same trust as the ``.asl`` files beside them):

* ``environment: room_env.RoomEnv(3, "x")`` loads class ``RoomEnv`` from ``room_env.py``
  beside the ``.mas2j`` (``environment: RoomEnv`` looks for ``RoomEnv.py``) and calls its
  :meth:`Environment.init` with the arguments; agents' actions go to
  :meth:`Environment.execute_action`, and its percepts become the agents' beliefs
  ``[source(percept)]``, as with Jason's ``jason.environment.Environment``;
* a call of ``mylib.act(X, Y)`` in a program runs the function ``act`` of ``mylib.py``
  beside the project, marked with :func:`internal_action`;
* ``agentArchClass arch.MyArch`` loads class ``MyArch`` (an :class:`AgentArch`) from
  ``arch.py``; it sees every action and message of its agent.

Anything named that has no Python file is an error naming the class and where the
project names it, and saying what to write (see :func:`missing_java`).
"""

from __future__ import annotations

import importlib.util
import sys
import threading
from collections.abc import Callable, Iterable
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any

from robocog.bdi.parser import parse_literal
from robocog.bdi.terms import Literal

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent
    from robocog.bdi.mas import MultiAgentSystem

__all__ = ["AgentArch", "Environment", "internal_action", "load_module"]


def _lit(x: str | Literal) -> Literal:
    return x if isinstance(x, Literal) else parse_literal(x)


class Environment:
    """The Python counterpart of Jason's ``jason.environment.Environment``.

    Subclass it and override :meth:`init` and :meth:`execute_action` (Jason's
    ``executeAction``; a subclass that defines ``executeAction`` works too). Percepts
    are kept for all agents (``add_percept(lit)``) or for one (``add_percept(lit,
    agent="bob")``); an agent perceives the global ones and its own at its next cycle.
    """

    def __init__(self) -> None:
        self._lock = threading.RLock()
        self._global: dict[Literal, None] = {}
        self._own: dict[str, dict[Literal, None]] = {}
        self._mas: MultiAgentSystem | None = None
        #: bumped at every change of percepts; the system compares it with what it gave
        self.version = 0

    # ---- what a subclass overrides
    def init(self, args: list[Any]) -> None:
        """Called once with the arguments the ``.mas2j`` gives (numbers, strings, atoms
        as ``str``) before any agent runs."""

    def execute_action(self, agent: str, action: Literal) -> bool:
        """Do ``action`` for ``agent``; True when it succeeded (Jason's
        ``executeAction``)."""
        jason_style = getattr(self, "executeAction", None)
        if jason_style is not None:
            return bool(jason_style(agent, action))
        return False

    def stop(self) -> None:
        """Called when the system stops."""

    # ---- percepts (Jason: addPercept, removePercept, clearPercepts, getPercepts)
    def add_percept(self, *lits: str | Literal, agent: str | None = None) -> None:
        """Add percepts for every agent, or for ``agent`` only."""
        with self._lock:
            target = self._global if agent is None else self._own.setdefault(agent, {})
            for x in lits:
                target[_lit(x)] = None
            self.version += 1

    def remove_percept(self, *lits: str | Literal, agent: str | None = None) -> None:
        """Remove percepts (of every agent, or of ``agent``)."""
        with self._lock:
            target = self._global if agent is None else self._own.get(agent, {})
            for x in lits:
                target.pop(_lit(x), None)
            self.version += 1

    def remove_percepts_by_functor(self, functor: str, agent: str | None = None) -> None:
        """Remove every percept with this functor (Jason's ``removePerceptsByUnif`` for
        the common ``functor(_, ...)`` pattern)."""
        with self._lock:
            target = self._global if agent is None else self._own.get(agent, {})
            for lit in [p for p in target if p.functor == functor]:
                del target[lit]
            self.version += 1

    def clear_percepts(self, agent: str | None = None) -> None:
        """Remove the global percepts (or those of ``agent``)."""
        with self._lock:
            if agent is None:
                self._global.clear()
            else:
                self._own.pop(agent, None)
            self.version += 1

    def contains_percept(self, lit: str | Literal, agent: str | None = None) -> bool:
        """Whether the percept is there (globally, or for ``agent``)."""
        with self._lock:
            target = self._global if agent is None else self._own.get(agent, {})
            return _lit(lit) in target

    def percepts(self, agent: str) -> list[Literal]:
        """What ``agent`` perceives now: the global percepts, then its own."""
        with self._lock:
            return [*self._global, *self._own.get(agent, {})]

    # Jason's names, so that a port reads as its original
    addPercept = add_percept  # noqa: N815
    removePercept = remove_percept  # noqa: N815
    clearPercepts = clear_percepts  # noqa: N815
    containsPercept = contains_percept  # noqa: N815
    getPercepts = percepts  # noqa: N815

    def __call__(self, agent: str, action: Literal) -> bool:
        return self.execute_action(agent, action)


class AgentArch:
    """An agent architecture hook (Jason's ``AgArch``): it sees the agent's actions and
    the messages it sends before they go out. Override and call the base method to let
    them through."""

    def __init__(self, agent: Agent) -> None:
        self.agent = agent

    def act(self, action: Literal, do: Callable[[Literal], Any]) -> Any:
        """Run an environment action (``do(action)`` runs it as usual)."""
        return do(action)

    def send(self, message: Any, do: Callable[[Any], Any]) -> Any:
        """Send a message (``do(message)`` sends it)."""
        return do(message)


def internal_action(fn: Callable | None = None, *, name: str | None = None) -> Any:
    """Mark a function of a library module as an internal action.

    ``fn(agent, *args)`` gets the agent and the arguments (resolved terms: numbers,
    ``str`` for strings, :class:`~robocog.bdi.terms.Literal` for atoms and structures,
    ``Var`` when unbound) and returns True or False (success or failure), or a tuple with
    one value per argument, each unified with its argument (``None`` leaves it alone)."""

    def mark(f: Callable) -> Callable:
        f.__robocog_internal__ = name or f.__name__  # type: ignore[attr-defined]
        return f

    return mark(fn) if fn is not None else mark


_modules: dict[str, ModuleType] = {}
_mod_lock = threading.Lock()


def load_module(folder: Path, dotted: str) -> ModuleType | None:
    """The module ``dotted`` (``a.b`` is ``a/b.py``, or ``a.py`` for a package-less
    name) from ``folder``, or None when there is no such file."""
    path = folder.joinpath(*dotted.split(".")).with_suffix(".py")
    if not path.is_file():
        return None
    key = str(path.resolve())
    with _mod_lock:
        mod = _modules.get(key)
        if mod is None:
            name = f"robocog_project_{len(_modules)}_{path.stem}"
            spec = importlib.util.spec_from_file_location(name, path)
            if spec is None or spec.loader is None:
                return None
            mod = importlib.util.module_from_spec(spec)
            sys.modules[name] = mod
            spec.loader.exec_module(mod)
            _modules[key] = mod
    return mod


def library_actions(module: ModuleType, prefix: str) -> dict[str, Callable]:
    """The internal actions a library module marks, by their full name (``prefix.act``)."""
    out = {}
    for value in vars(module).values():
        name = getattr(value, "__robocog_internal__", None)
        if name is not None and callable(value):
            out[f"{prefix}.{name}"] = value
    return out


def find_class(folders: Iterable[Path], spec: str) -> type | None:
    """Class ``C`` of ``m.C`` from ``m.py`` (``C`` alone: ``C.py``) in the first of
    ``folders`` that has the file; None when none has."""
    module, _, cls = spec.rpartition(".")
    module = module or cls
    for folder in folders:
        mod = load_module(folder, module)
        if mod is not None:
            return getattr(mod, cls, None)
    return None
