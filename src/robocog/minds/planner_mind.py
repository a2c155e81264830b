"""PlannerMind: the AtomSpace planner of Thiella (2021) driving a manipulator through the contract.

The phases of Chapter 4 of the thesis, one mind:

* perception: the ``Tag`` percepts name the objects in view;
* learning: sentences ("The table is a fixed object.", "The SnapRing1 is on the
  SnapRing2.") say what the tags cannot, and make the initial scene;
* request: sentences say what must hold; the planner searches a plan from the scene;
* execution: the plan's steps become ``PickUp``/``PutDown``/``Stack``/``Unstack``
  commands, one per cycle. Each step that succeeds moves the mind's scene on; when one
  fails (a grasp slips), the mind plans again from the scene as it now stands and goes
  on with the new plan, up to ``max_replans`` times.

With ``perceive_scene`` the mind also trusts its eyes over its bookkeeping: a body that
reports what each object rests on (:class:`~robocog.robot.percepts.Resting`, the
physical tabletop reads it from tag poses) gives the scene the planner starts from, and
after every step the mind compares what it sees with what the plan predicted. A cube
that slipped, fell or was moved by someone differs from the prediction, and the mind
plans again from what it sees; a request counts as reached only once a look confirms
its last step. An object resting on the fixed object where it was first seen in the
request rests "where it was found", as the thesis's scenes say of the parts in their
bins; the sentences still declare the fixed objects and what no camera can see.

Every search is kept (plan, iterations, seconds) so an experiment can set them beside
the thesis's tables.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from robocog.planning.planner import (
    Planner,
    PlanningError,
    PlanResult,
    Step,
    goal_from_english,
    scene_from_english,
)
from robocog.planning.task import Fact
from robocog.planning.world import Scene, SceneError
from robocog.robot.commands import Command, Outcome, PickUp, PutDown, Stack, Unstack
from robocog.robot.percepts import Gripper, Percept, Resting, Tag


def command_for_step(step: Step) -> Command:
    """The manipulator Command of one plan step (raises ValueError for an unknown action)."""
    name, args = step.name.replace("-", ""), step.args
    if name == "pickup" and len(args) == 1:
        return PickUp(args[0])
    if name == "putdown" and len(args) == 1:
        return PutDown(args[0])
    if name == "putdown" and len(args) == 2:
        return PutDown(args[0], args[1])
    if name == "stack" and len(args) == 2:
        return Stack(args[0], args[1])
    if name == "unstack" and len(args) == 2:
        return Unstack(args[0], args[1])
    raise ValueError(f"no manipulator command for {step}")


@dataclass
class RequestRecord:
    """One request: its sentences, every plan searched for it, and what was executed."""

    request: str
    goal: list[Fact]
    plans: list[PlanResult] = field(default_factory=list)
    executed: list[str] = field(default_factory=list)
    failures: list[str] = field(default_factory=list)
    status: str = "planning"
    message: str = ""

    @property
    def first_plan(self) -> PlanResult | None:
        """The plan found before any step ran."""
        return self.plans[0] if self.plans else None

    @property
    def replans(self) -> int:
        """How many times the mind planned again after a failed step."""
        return max(0, len(self.plans) - 1)

    @property
    def planning_seconds(self) -> float:
        """Time spent searching, over all plans of this request."""
        return sum(p.seconds for p in self.plans)


class PlannerMind:
    """Plans from tags and sentences, executes step by step, replans on failure."""

    def __init__(
        self,
        facts: str = "",
        planner: Planner | None = None,
        mode: str = "astar",
        max_replans: int = 20,
        perceive_scene: bool = False,
    ) -> None:
        self.facts = facts
        self.planner = planner or Planner()
        self.mode = mode
        self.max_replans = max_replans
        self.seen: list[str] = []
        self.holding: str | None = None
        self.scene: Scene | None = None
        self.records: list[RequestRecord] = []
        self._steps: list[Step] = []
        self._next = 0
        self._running: Step | None = None
        self.perceive_scene = perceive_scene
        self.resting: dict[str, str] = {}
        self._seen_now: list[str] = []
        self._fresh = False
        self._found: dict[str, str] | None = None

    # -- phases -------------------------------------------------------------------

    def request(self, sentences: str, facts: str | None = None) -> RequestRecord:
        """Start a request; ``facts`` (learning sentences) rebuild the scene from the tags.

        Without ``facts`` the mind keeps the scene it has been tracking (or builds one
        from the tags and the facts given at construction). A sentence the planner
        cannot read ends the request with status ``failed`` and the reason.
        """
        record = RequestRecord(sentences, [])
        self.records.append(record)
        self._steps, self._next, self._running = [], 0, None
        self._found = None
        try:
            record.goal = goal_from_english(sentences)
            if facts is not None:
                self.facts = facts
                self.scene = None
        except (PlanningError, ValueError) as exc:
            record.status, record.message = "failed", str(exc)
        return record

    @property
    def current(self) -> RequestRecord | None:
        """The latest request."""
        return self.records[-1] if self.records else None

    @property
    def busy(self) -> bool:
        """True while the latest request is being planned or executed."""
        return self.current is not None and self.current.status in ("planning", "executing")

    def plan_progress(self) -> tuple[list[Step], int]:
        """The plan being executed and the index of its next step (the inspector shows
        which step runs; the list is a copy)."""
        return list(self._steps), self._next

    # -- Mind ---------------------------------------------------------------------

    def perceive(self, percepts: Sequence[Percept]) -> None:
        """Tags name the objects in view (perception phase); the gripper says what it holds."""
        seen = [p.name for p in percepts if isinstance(p, Tag)]
        if seen:
            self.seen = list(dict.fromkeys(seen))
            self._seen_now = self.seen
            self.resting = {p.obj: p.on for p in percepts if isinstance(p, Resting)}
            self._fresh = True
        for p in percepts:
            if isinstance(p, Gripper):
                self.holding = p.holding

    def decide(self) -> list[Command]:
        """Plan if needed, then return the next step's command."""
        record = self.current
        if record is None or not self.busy:
            return []
        if self.scene is None:
            try:
                self.scene = scene_from_english(self.seen, self.facts)
            except (PlanningError, ValueError) as exc:
                record.status, record.message = "failed", f"learning phase: {exc}"
                return []
            if self.perceive_scene:
                self.scene = self._seen_scene(self.scene)
        if self.perceive_scene and self._fresh and record.status == "executing":
            self._fresh = False
            seen_scene = self._seen_scene(self.scene)
            differences = self._differences(self.scene, seen_scene)
            if differences:
                record.failures.append("seen: " + "; ".join(differences))
                self.scene = seen_scene
                if record.replans >= self.max_replans:
                    record.status = "failed"
                    record.message = f"gave up after {record.replans} replans"
                    return []
                record.status = "planning"
        if record.status == "planning":
            if self.perceive_scene:
                self.scene = self._seen_scene(self.scene)
            else:
                self._sync_hand()
            if not self._plan(record):
                return []
        if self._next >= len(self._steps):
            record.status = "reached"
            return []
        self._running = self._steps[self._next]
        try:
            return [command_for_step(self._running)]
        except ValueError as exc:
            record.status, record.message = "failed", str(exc)
            return []

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        """Move the scene on after a step, or plan again from it after a failure."""
        record = self.current
        step = self._running
        self._running = None
        if record is None or step is None or record.status != "executing":
            return
        if outcome.ok:
            assert self.scene is not None
            try:
                self.scene = step.apply(self.scene)
            except SceneError as exc:
                record.status, record.message = "failed", f"the scene lost track: {exc}"
                return
            record.executed.append(str(step))
            self._next += 1
            if self._next >= len(self._steps) and not self.perceive_scene:
                record.status = "reached"  # with eyes, the next look confirms it
            return
        record.failures.append(f"{step}: {outcome.reason}")
        if record.replans >= self.max_replans:
            record.status, record.message = "failed", f"gave up after {record.replans} replans"
            return
        record.status = "planning"

    def _sync_hand(self) -> None:
        """Trust the gripper over the scene about what the hand holds before planning.

        A grasp reported as failed may still have taken the object, and a slip may drop
        one; the gripper percept says which, so the new plan starts from the real hand.
        """
        assert self.scene is not None
        if self.holding == self.scene.held or not self.seen:
            return
        scene = self.scene.copy()
        if self.holding is None:
            scene.held = None  # dropped: it rests where it fell (not on anything known)
        elif self.holding in scene.objects and self.holding not in scene.on.values():
            scene.on.pop(self.holding, None)
            scene.held = self.holding
        else:
            return
        self.scene = scene

    def _seen_scene(self, base: Scene) -> Scene:
        """``base`` with what the last look saw: each object in view on what it rests on.

        An object in view resting on nothing known (in the hand, in the air, tilted) is on
        nothing; one on the fixed object where it was first seen in this request rests
        where it was found. Objects out of view keep what ``base`` says of them.
        """
        scene = base.copy()
        fixed = set(scene.fixed)
        if self._found is None:  # the request's first look: where each part was found
            self._found = {n: on for n, on in self.resting.items() if on in fixed}
        for name in self._seen_now:
            if name in fixed:
                continue
            scene.add_object(name)
            on = self.resting.get(name)
            if on is None or on == name:
                scene.on.pop(name, None)
            elif on in fixed and self._found.get(name) == on:
                scene.on.pop(name, None)
            else:
                scene.add_object(on, fixed=on in fixed)
                scene.on[name] = on
        scene.held = self.holding if self.holding in scene.objects else None
        if scene.held is not None:
            scene.on.pop(scene.held, None)
            scene.on = {top: below for top, below in scene.on.items() if below != scene.held}
        try:
            scene.check()
        except SceneError:
            return base  # a look that cannot be (two cubes on one): keep the prediction
        return scene

    def _differences(self, predicted: Scene, seen: Scene) -> list[str]:
        """What the look shows otherwise than the plan predicted, in words.

        An object the plan left on nothing that is seen on a fixed object is where the
        plan put it (a put-down returns a part to a fixed place), not a difference.
        """
        out = []
        fixed = set(seen.fixed)
        for name in self._seen_now:
            if name in fixed:
                continue
            want, have = predicted.on.get(name), seen.on.get(name)
            if want == have or (want is None and (have is None or have in fixed)):
                continue
            if want is None and have in fixed:
                continue
            out.append(
                f"the {name} is on {'the ' + have if have else 'nothing known'}, "
                f"not on {'the ' + want if want else 'nothing'}"
            )
        if predicted.held != seen.held:
            out.append(
                f"the hand holds {seen.held or 'nothing'}, not {predicted.held or 'nothing'}"
            )
        return out

    def _plan(self, record: RequestRecord) -> bool:
        assert self.scene is not None
        try:
            result = self.planner.plan(self.scene, record.goal, mode=self.mode)
        except PlanningError as exc:
            record.status, record.message = "failed", str(exc)
            return False
        record.plans.append(result)
        if not result.found:
            record.status, record.message = "failed", result.message or "no plan"
            return False
        self._steps, self._next = list(result.steps), 0
        record.status = "executing"
        return True
