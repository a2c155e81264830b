"""The planner's front door: from seen objects and sentences (or PDDL) to a plan.

The phases of Chapter 4 of the thesis map onto this module:

* perception: the list of seen tags becomes the objects (``scene_from_english``);
* learning: sentences say which objects are fixed and which stands on which;
* request: sentences say what must hold (``goal_from_english``);
* search: ``Planner.plan`` grounds the Atomese action rules over the scene and searches;
* execution: ``PlanResult.steps`` are the actions, printed as the thesis prints them.

A robot-side caller keeps a ``Scene``, asks ``Planner.plan(scene, goal)``, executes the
steps one at a time with ``Step.apply`` to track the scene, and plans again from the
current scene when a step fails.
"""

from __future__ import annotations

import time
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any

from robocog.planning.english import Statement, read_sentences
from robocog.planning.heuristics import BlocksView, blind
from robocog.planning.reductions import BlocksReduction
from robocog.planning.rules import Rule
from robocog.planning.search import MODES, SearchResult, astar, bfs
from robocog.planning.task import Fact, Operator, Task
from robocog.planning.world import Scene, SceneError, build_task

#: search modes accepted by ``Planner.plan``: A* and the thesis's four BFS modes
ALL_MODES = ("astar", *MODES)


class PlanningError(ValueError):
    """A request the planner cannot take (unknown object, impossible scene, bad mode)."""


@dataclass(frozen=True)
class Step:
    """One action of a plan: its name, its arguments, and how to print it."""

    name: str
    args: tuple[str, ...]
    style: str = "atomese"

    def __str__(self) -> str:
        if self.style == "pddl":
            return "(" + " ".join((self.name, *self.args)) + ")"
        inner = " ".join(f'(ConceptNode "{a}")' for a in self.args)
        return f"({self.name} {inner})"

    def apply(self, scene: Scene) -> Scene:
        """The scene after this step (raises SceneError if it cannot be done there)."""
        new = scene.copy()
        obj = self.args[0]
        take = self.name in ("pickup", "pick-up", "unstack")
        if take:
            if new.held is not None:
                raise SceneError(f"the hand already holds the {new.held}")
            if obj in new.on.values():
                raise SceneError(f"the {obj} is not clear")
            if self.name == "unstack" and new.on.get(obj) != self.args[1]:
                raise SceneError(f"the {obj} is not on the {self.args[1]}")
            new.on.pop(obj, None)
            new.held = obj
        else:
            if new.held != obj:
                raise SceneError(f"the {obj} is not in the hand")
            new.held = None
            if self.name == "stack":
                under = self.args[1]
                if under in new.on.values() and under not in new.fixed:
                    raise SceneError(f"the {under} is not clear")
                new.on[obj] = under
        return new


@dataclass
class PlanResult:
    """A plan and what finding it cost.

    ``optimal`` is True when the plan is known to be a shortest one (A*, and BFS in the
    first, bounded and whole modes; a quick-mode plan only when its length equals the
    admissible lower bound). ``found`` is False when there is no plan, or none within
    the limits (then ``complete`` says whether the search was cut short).
    """

    steps: list[Step]
    iterations: int
    seconds: float
    optimal: bool
    found: bool
    mode: str
    complete: bool = True
    generated: int = 0
    solutions: int = 0
    lower_bound: int = 0
    message: str = ""
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def length(self) -> int:
        """Number of actions."""
        return len(self.steps)

    def lines(self) -> list[str]:
        """The steps as text, one per action."""
        return [str(s) for s in self.steps]

    def to_json(self) -> dict[str, Any]:
        """The result as the JSON object of ``robocog plan --json``."""
        return {
            "steps": self.lines(),
            "length": self.length,
            "iterations": self.iterations,
            "seconds": round(self.seconds, 6),
            "optimal": self.optimal,
            "found": self.found,
            "mode": self.mode,
        }


def scene_from_english(objects: Iterable[str], facts: str | Sequence[Statement] = "") -> Scene:
    """Perception + learning: seen objects and sentences make the initial scene.

    A name that appears only in a sentence is added as a movable object, unless a
    sentence says it is fixed.
    """
    statements = read_sentences(facts) if isinstance(facts, str) else list(facts)
    scene = Scene()
    for name in objects:
        scene.add_object(name)
    for st in statements:
        if st.kind == "fixed":
            scene.add_object(st.subject, fixed=True)
    for st in statements:
        if st.kind == "movable":
            if st.subject in scene.fixed:
                raise PlanningError(f"{st.text!r}: the {st.subject} was said to be fixed")
            scene.add_object(st.subject)
        elif st.kind in ("on", "in-hand", "clear"):
            scene.add_object(st.subject)
            if st.other is not None:
                scene.add_object(st.other)
    for st in statements:
        if st.kind == "on":
            assert st.other is not None
            if st.subject in scene.on and scene.on[st.subject] != st.other:
                raise PlanningError(
                    f"{st.text!r}: the {st.subject} is already on the {scene.on[st.subject]}"
                )
            scene.on[st.subject] = st.other
        elif st.kind == "in-hand":
            if scene.held not in (None, st.subject):
                raise PlanningError(f"{st.text!r}: the hand already holds the {scene.held}")
            scene.held = st.subject
    try:
        scene.check()
    except SceneError as exc:
        raise PlanningError(str(exc)) from None
    for st in statements:
        if st.kind == "clear" and (st.subject in scene.on.values() or scene.held == st.subject):
            if st.subject not in scene.fixed:
                raise PlanningError(f"{st.text!r}: something is on the {st.subject}")
    return scene


def goal_from_english(text: str | Sequence[Statement]) -> list[Fact]:
    """Request: the sentences of a request as the goal list of facts."""
    statements = read_sentences(text) if isinstance(text, str) else list(text)
    goal: list[Fact] = []
    for st in statements:
        if st.kind in ("fixed", "movable"):
            raise PlanningError(f"{st.text!r}: a request says where objects should be")
        goal.append(st.fact())
    return goal


def goal_objects(goal: Iterable[Fact]) -> set[str]:
    """The objects named in a goal (the quick search acts only on these)."""
    return {name for fact in goal for name in fact[1:]}


class Planner:
    """Plans pick-and-place tasks with the Atomese action rules.

    ``mode`` is ``astar`` (default: shortest plans, fast) or one of the thesis's BFS
    modes ``first``, ``bounded`` (with ``max_iterations``), ``whole`` and ``quick``.
    ``max_nodes`` bounds memory; ``max_seconds`` bounds A*'s time.
    """

    def __init__(
        self,
        rules: Sequence[Rule] | None = None,
        max_nodes: int = 3_000_000,
        max_seconds: float | None = None,
    ) -> None:
        self.rules = list(rules) if rules is not None else None
        self.max_nodes = max_nodes
        self.max_seconds = max_seconds

    def task(self, scene: Scene, goal: Iterable[Fact]) -> Task:
        """Ground the rules over *scene* for *goal* (checks every goal name is known)."""
        goal = list(goal)
        known = set(scene.names())
        for fact in goal:
            for name in fact[1:]:
                if name not in known:
                    raise PlanningError(f"the request names the {name}, which is not known")
        try:
            return build_task(scene, goal, self.rules)
        except SceneError as exc:
            raise PlanningError(str(exc)) from None

    def plan(
        self,
        scene: Scene,
        goal: Iterable[Fact] | str,
        mode: str = "astar",
        max_iterations: int | None = None,
        prune: str = "global",
        strict: bool = False,
        engine: str = "compiled",
        goal_test: str = "created",
    ) -> PlanResult:
        """Search a plan from *scene* to *goal* (facts or request sentences).

        A name the request mentions but the scene lacks is learnt as a movable object
        resting where it is (the thesis's Table 5.8 names BlockC only in its request);
        with ``strict`` it is an error instead. ``engine="atomspace"`` runs the BFS modes
        with one AtomSpace per state and the AtomSpace pattern matcher at every node, as
        the thesis did (slow; for small scenes and for checking).
        """
        start = time.perf_counter()
        if isinstance(goal, str):
            goal = goal_from_english(goal)
        goal = list(goal)
        added = sorted(goal_objects(goal) - set(scene.names()))
        if added and not strict:
            scene = scene.copy()
            for name in added:
                scene.add_object(name)
        task = self.task(scene, goal)
        if engine == "atomspace":
            return _solve_atomspace(scene, goal, task, mode, max_iterations, prune, start)
        if engine != "compiled":
            raise PlanningError(f"unknown engine {engine!r}; choose compiled or atomspace")
        result = solve_task(
            task,
            mode=mode,
            max_iterations=max_iterations,
            prune=prune,
            quick_names=goal_objects(goal),
            max_nodes=self.max_nodes,
            max_seconds=self.max_seconds,
            started=start,
            goal_test=goal_test,
        )
        if added and not strict:
            result.extra["learnt_objects"] = added
        return result

    def plan_english(
        self, objects: Iterable[str], facts: str, request: str, mode: str = "astar", **kw: Any
    ) -> PlanResult:
        """All phases at once: seen objects, learning sentences, request sentences."""
        return self.plan(scene_from_english(objects, facts), request, mode=mode, **kw)


def _solve_atomspace(
    scene: Scene,
    goal: list[Fact],
    task: Task,
    mode: str,
    max_iterations: int | None,
    prune: str,
    start: float,
) -> PlanResult:
    """BFS with the AtomSpace pattern matcher expanding every node."""
    from robocog.planning.atomspace_rules import AtomSpaceSearch

    if mode not in MODES:
        raise PlanningError("the atomspace engine runs the BFS modes only")
    space = AtomSpaceSearch(scene, goal)
    if mode == "quick":
        names = goal_objects(goal)
        full = space.successors

        def restricted(state: frozenset) -> Iterator[tuple[tuple[str, tuple[str, ...]], frozenset]]:
            for label, nxt in full(state):
                if names.intersection(label[1]):
                    yield label, nxt

        space.successors = restricted  # type: ignore[method-assign]
    result = bfs(space, mode, max_iterations, prune=prune)
    steps = [Step(name, args) for name, args in result.plan or []]
    message = "" if result.plan is not None else "no plan found"
    bound = BlocksView(task)(task.init)
    return _plan_result(result, steps, mode, bound, start, message, {"engine": "atomspace"})


def _plan_result(
    result: SearchResult,
    steps: list[Step],
    mode: str,
    bound: int,
    start: float,
    message: str,
    extra: dict[str, Any] | None = None,
) -> PlanResult:
    """Wrap a search outcome for either engine.

    A quick plan is known shortest only when it meets the admissible *bound*; the other
    modes say themselves whether their plan is shortest.
    """
    found = result.plan is not None
    optimal = (found and len(steps) == bound) if mode == "quick" else result.optimal
    return PlanResult(
        steps=steps,
        iterations=result.iterations,
        seconds=time.perf_counter() - start,
        optimal=optimal,
        found=found,
        mode=mode,
        complete=result.complete,
        generated=result.generated,
        solutions=result.solutions,
        lower_bound=bound,
        message=message,
        extra=extra if extra is not None else {},
    )


def solve_task(
    task: Task,
    mode: str = "astar",
    max_iterations: int | None = None,
    prune: str = "global",
    quick_names: set[str] | None = None,
    max_nodes: int = 3_000_000,
    max_seconds: float | None = None,
    started: float | None = None,
    style: str = "atomese",
    view: BlocksView | None = None,
    reduce: bool = True,
    goal_test: str = "created",
) -> PlanResult:
    """Search *task* in *mode* and wrap the outcome as a ``PlanResult``.

    With ``reduce`` A* skips the moves ``reductions.BlocksReduction`` shows unnecessary
    (only when the goal is about supports alone); plans stay shortest. ``goal_test``
    is passed to the BFS modes (see ``search.bfs``).
    """
    if mode not in ALL_MODES:
        raise PlanningError(f"unknown mode {mode!r}; choose one of {', '.join(ALL_MODES)}")
    start = time.perf_counter() if started is None else started
    h: Any = view
    if h is None:
        h = BlocksView(task) if BlocksView.fits(task) else blind
    bound = h(task.init)
    result: SearchResult
    if mode == "astar":
        space: Any = task
        if reduce and isinstance(h, BlocksView) and BlocksReduction.applies(task, h):
            space = BlocksReduction(task, h)
        result = astar(space, h, max_nodes=max_nodes, max_seconds=max_seconds)
    elif mode == "quick":
        space = task.restricted(quick_names or set())
        result = bfs(
            space, "quick", max_iterations, prune=prune, max_nodes=max_nodes, goal_test=goal_test
        )
    else:
        try:
            result = bfs(
                task, mode, max_iterations, prune=prune, max_nodes=max_nodes, goal_test=goal_test
            )
        except ValueError as exc:
            raise PlanningError(str(exc)) from None
    plan: list[Operator] = result.plan or []
    message = ""
    if result.plan is None:
        if not result.complete:
            message = "no plan found within the search limits"
        elif mode == "quick":
            message = "the quick search found no plan; try the mode 'first' or 'astar'"
        else:
            message = "no plan exists: the request cannot be reached from this scene"
    steps = [Step(op.name, op.args, style) for op in plan]
    return _plan_result(result, steps, mode, bound, start, message)
