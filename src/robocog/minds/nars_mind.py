"""NarsMind: the reasoner of Hammer et al. behind the robot contract.

Each frame the percepts become Narsese events (``nars_encoding``), the task goal ``G!``
is given, and the reasoner runs a few cycles. Operations it executes (``^forward
^left ^right ^goto ^pick ^drop``) are collected by the callbacks registered on it and
returned as Commands; each Outcome comes back as the events that follow from it (the
gripper holding or still open, the robot at the place it went to), so a pick that
fails leaves its anticipated ``<gripper --> [hold]>`` unfulfilled and the hypothesis
that predicted it loses evidence (Section V.D).

For each label in view the mind asks the reasoner what it is (``<bottle --> ?1>?``) and
reports the sighting under the answer as well (``<trash --> [see]>``), so the category
comes from the reasoner's own knowledge yet enters as an event it can learn from; a
sighting it would only derive is soon crowded out of its attention.

The place is told when the robot arrives at a checkpoint, not every second
(``place_on_change``): each visit is then one piece of evidence for
``<<({SELF} * {p3}) --> at> =/> <trash --> [see]>>``, as Section V.D describes it
(confidence from the visits, frequency from those with trash seen). A visit with trash
in view confirms the hypothesis by temporal induction; a visit without it leaves the
reasoner's anticipation of ``<trash --> [see]>`` unmet, which is negative evidence.
Each input event after the arrival counts as one unmet anticipation, so the detector
reports its most confident box per frame (``max_detections=1``): with three boxes,
nine events per frame, a visit to a cluttered checkpoint would weigh as more failure
than a visit to a checkpoint with a single bottle. Reporting a kind that went out of
view as not seen (``report_absence``) is possible, but then a checkpoint with trash on
fewer than about half of its visits gets net negative evidence, its hypothesis sinks to
the bottom of ONA's bounded implication table and is dropped, and the next sighting
starts it afresh from that one visit (see docs/garbage.md).

The operator's knowledge of the checkpoints (Section V.C, step 4) enters as a goal:
when ``patience`` frames have passed without an operation that succeeded (nothing
executed, or picks and drops that failed), the mind also asks it to be at the next
checkpoint of the route, which the background knowledge's ``^goto`` rule can achieve.
The reasoner then weighs that goal against ``G`` by desire: a pick whose hypothesis
has lost evidence no longer outweighs moving on. Nothing here picks or moves on by
itself: the reasoner does.
"""

from __future__ import annotations

import importlib.resources
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from robocog.minds.nars_encoding import (
    DEFAULT_FOV,
    OPERATIONS,
    TASK_GOAL,
    arrived_at,
    command_for,
    frame_events,
    goal_at,
    gripper_events,
    not_seen,
    recall_questions,
    seen_as,
    seen_kind,
)
from robocog.robot.commands import Command, Drop, GoTo, Outcome, Pick
from robocog.robot.loop import tidy as upkeep
from robocog.robot.percepts import Detection, Gripper, Obstacle, Percept, Pose

if TYPE_CHECKING:
    from robocog.nars import NAR, Term
    from robocog.nars.narsese import Sentence

TRASH_QUESTION = "<<({SELF} * {?1}) --> at> =/> <trash --> [see]>>?"

#: The first rule as the paper prints it, and the same rule bracketed as ONA's reader
#: needs it (ONA 0.9.2 reads the printed form as another term). A reasoner that rejects
#: the printed form is given the bracketed one, and the mind notes it.
PRINTED_GOTO_RULE = (
    "<<(gripper --> [open]) &/ <({SELF} * (next * $P)) --> ^goto> =/> <({SELF} * {$P}) --> at>>."
)
BRACKETED_GOTO_RULE = (
    "<(<gripper --> [open]> &/ <({SELF} * (next * $P)) --> ^goto>) =/> <({SELF} * {$P}) --> at>>."
)
BRACKETED: dict[str, str] = {PRINTED_GOTO_RULE: BRACKETED_GOTO_RULE}
#: what each rewritten rule says, in words, for the note a report shows
MEANING: dict[str, str] = {
    PRINTED_GOTO_RULE: "with the gripper open, going on to the next checkpoint, $P, brings the "
    "robot to $P"
}


def rewrite_note(printed: str, reason: str) -> str:
    """The note on a rule of the paper that the reasoner read in its bracketed form, for a
    reader who has not seen Narsese: what happened, why, and that nothing changed."""
    meaning = MEANING.get(printed)
    said = f" It says: {meaning}." if meaning else ""
    return (
        "One rule of the robot's background knowledge was rewritten before the reasoner "
        "read it, without changing its meaning. The paper prints it as "
        f"`{printed}`, which this Narsese reader does not accept ({reason}): the statement "
        "`gripper --> [open]` stands in round brackets where Narsese puts a statement in "
        "angle brackets, and the two steps before `=/>` are not grouped. The mind gave the "
        f"reasoner the same rule written out in full, `{BRACKETED[printed]}`.{said} "
        "Nothing is wrong with the run: the note only records the rewriting."
    )


class NotReady(RuntimeError):
    """The reasoner cannot drive the robot yet; the message says what is missing."""


def background(name: str = "garbage.nal") -> list[str]:
    """The lines of a knowledge file shipped with robocog (Hammer et al., Section V.C.1)."""
    text = importlib.resources.files("robocog.minds").joinpath("knowledge", name).read_text()
    return [line for line in text.splitlines() if line.strip()]


@dataclass
class NarsSettings:
    """How the mind talks to the reasoner; ONA's defaults where ONA has one."""

    seed: int = 0
    cycles_per_frame: int = 10  # thinking time per frame, also after an execution
    patience: int = 2  # frames without a successful operation before the route goal
    instances: bool = True
    #: tell the place on arrival only (one piece of evidence per visit), not each second
    place_on_change: bool = True
    recall: bool = True  # ask what a seen label is; report the sighting under the answer
    #: report a kind once seen as not seen (``{0.0 0.9}``) in frames without it
    report_absence: bool = False
    max_detections: int = 1  # the most confident box per frame (see above)
    fov: float = DEFAULT_FOV
    motor_babbling: bool = False
    transcript: int = 0  # keep the last N output lines of the reasoner (0: none)
    overrides: dict[str, object] = field(default_factory=dict)


class NarsMind:
    """A Mind whose decisions are the reasoner's operation executions."""

    name = "NARS"

    def __init__(
        self,
        places: Sequence[str] = (),
        settings: NarsSettings | None = None,
        knowledge: Sequence[str] | None = None,
        nar: NAR | None = None,
    ) -> None:
        self.settings = settings or NarsSettings()
        self.places = list(places)
        if nar is None:
            from robocog.nars import NAR  # a reasoner is made only when none is given

            nar = NAR(seed=self.settings.seed, **self.settings.overrides)
        self.nar = nar
        self.lines: deque[str] = deque(maxlen=self.settings.transcript or 1)
        if self.settings.transcript:
            self.nar.output = self.lines.append
        self._executed: list[tuple[str, Term | None]] = []
        self._place: list[Sentence] = []  # where the robot is, told first
        self._frame: list[Sentence] = []  # the rest of the frame
        self._questions: list[Term] = []
        self._kinds: set[Term] = set()  # kinds of things reported seen so far
        self._idle = 0
        self._last_place: str | None = None
        self._reported_place: str | None = None  # the place last told to the reasoner
        self._holding = False
        self.inputs = 0
        self.notes: list[str] = []  # what had to be adapted for this reasoner
        self.decisions: list[tuple[str, str | None]] = []
        self._setup(background() if knowledge is None else list(knowledge))

    # ---- wiring ---------------------------------------------------------------

    def _setup(self, knowledge: list[str]) -> None:
        for slot, op in enumerate(OPERATIONS, start=1):
            self._input(f"*setopname {slot} {op}")
        if not self.settings.motor_babbling:
            self._input("*motorbabbling=false")
        for op in OPERATIONS:
            self.nar.register_operation(op, self._callback(op))
        for line in knowledge:
            try:
                self._input(line)
            except NotReady as exc:
                if line not in BRACKETED:
                    raise
                self._input(BRACKETED[line])
                self.notes.append(rewrite_note(line, str(exc.__cause__ or exc)))

    def _callback(self, op: str):  # noqa: ANN202 - the reasoner's callback type
        def execute(args: Term | None = None) -> None:
            self._executed.append((op, args))

        return execute

    def _input(self, line: str) -> None:
        """A line of text: a shell command or a line of the knowledge file."""
        try:
            self.nar.add_input(line)
        except Exception as exc:  # the reasoner names the line and column
            raise NotReady(f"the reasoner rejected {line.strip()!r}: {exc}") from exc
        self.inputs += 1

    def _tell(self, sentence: Sentence) -> None:
        """An event or goal the mind built: handed to the reasoner as it is, unparsed."""
        try:
            self.nar.add_sentence(sentence)
        except Exception as exc:
            raise NotReady(f"the reasoner rejected {sentence}: {exc}") from exc
        self.inputs += 1

    # ---- the Mind protocol ----------------------------------------------------

    def perceive(self, percepts: Sequence[Percept]) -> None:
        """Encode the frame; the place is remembered to know the next checkpoint."""
        repeated = False
        for p in percepts:
            if isinstance(p, Pose):
                if p.place:
                    self._last_place = p.place
                repeated = p.place == self._reported_place
                self._reported_place = p.place
            elif isinstance(p, Gripper):
                self._holding = p.holding is not None
        if repeated and self.settings.place_on_change:
            percepts = [p for p in percepts if not isinstance(p, Pose)]
        self._questions = (
            recall_questions(percepts, self.settings.max_detections) if self.settings.recall else []
        )
        self._place, self._frame = frame_events(
            percepts,
            self.settings.fov,
            self.settings.instances,
            self.settings.max_detections,
        )

    def decide(self) -> list[Command]:
        """Feed the frame and the goals, cycle, and return what the reasoner executed."""
        for event in self._place:
            self._tell(event)
        sightings: list[Sentence] = []
        for question in self._questions:  # what is seen, as what it is, right after where
            answer = self.nar.answer(question)
            if answer is not None:
                truth = answer.truth
                event = seen_as(question, answer.term, float(truth.f), float(truth.c))
                if event is not None and event not in sightings:
                    sightings.append(event)
                    self._kinds.add(seen_kind(event))
                    self._tell(event)
        seen = {seen_kind(e) for e in sightings}
        if self.settings.report_absence:
            for kind in sorted(self._kinds - seen, key=str):  # looked for, and not there
                self._tell(not_seen(kind))
        for event in self._frame:
            self._tell(event)
        self._tell(TASK_GOAL)
        if self._idle >= self.settings.patience and not self._holding:
            nxt = self.next_place()
            if nxt is not None:
                self._tell(goal_at(nxt))
        self.nar.cycles(self.settings.cycles_per_frame)
        executed, self._executed = self._executed, []
        commands: list[Command] = []
        for op, args in executed:
            self.decisions.append((op, None if args is None else str(args)))
            command = command_for(op, args, [*self.places, "start"])
            if command is not None:
                commands.append(command)
        self._idle += 1  # reset by on_outcome when one of these succeeds
        return commands

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        """Feed back the events that follow from how the command ended."""
        if outcome.ok:
            self._idle = 0
        if isinstance(command, Pick):
            self._holding = outcome.ok
            for event in gripper_events(outcome.ok):
                self._tell(event)
        elif isinstance(command, GoTo) and outcome.ok:
            place = command.place
            if place == "next":
                place = self.next_place() or place
            if place in self.places:
                self._last_place = self._reported_place = place
                self._tell(arrived_at(place))
        elif isinstance(command, Drop) and outcome.ok:
            self._holding = False
            for event in gripper_events(False):
                self._tell(event)

    def tidy(self) -> None:
        """Between cycles: the reasoner's upkeep (robocog's sweeps the process's term
        table when due, see ``NAR.tidy``; ONA in another process has none)."""
        upkeep(self.nar)

    # ---- the operator's route and the user's questions --------------------------

    def close(self) -> None:
        """Release the reasoner (a reasoner in another process is ended)."""
        close = getattr(self.nar, "close", None)
        if callable(close):
            close()

    def new_round(self) -> None:
        """The operator restarts the route: the next checkpoint is the first again."""
        self._last_place = None
        self._reported_place = None  # the robot starts again from the start corner
        self._idle = 0

    def next_place(self) -> str | None:
        """The checkpoint after the last one visited; ``start`` closes the route."""
        if not self.places:
            return None
        if self._last_place not in self.places:
            return self.places[0]
        i = self.places.index(self._last_place)
        return self.places[i + 1] if i + 1 < len(self.places) else "start"

    def ask(self, question: str) -> tuple[str, float, float] | None:
        """The reasoner's answer as (statement, frequency, confidence), or None.

        A question the reasoner cannot read raises its error (naming line and column).
        """
        answer = self.nar.ask(question)
        if answer is None:
            return None
        return str(answer.term), float(answer.truth.f), float(answer.truth.c)

    def pick_evidence(self, instances: Sequence[str] = ()) -> dict[str, tuple[float, float]]:
        """The reasoner's evidence that picking brings ``<gripper --> [hold]>``: for the
        background rule and, where it formed one, for each named instance (Section V.D's
        ``<(<{instanceX} --> [see]> &/ ^pick) =/> <gripper --> [hold]>>``)."""
        out: dict[str, tuple[float, float]] = {}
        subjects = {"trash": "<trash --> [see]>"}
        subjects.update({i: f"<{{{i}}} --> [see]>" for i in instances})
        for key, subject in subjects.items():
            answer = self.ask(f"<({subject} &/ ^pick) =/> <gripper --> [hold]>>?")
            if answer is not None:
                out[key] = (answer[1], answer[2])
        return out

    def trash_places(self) -> list[tuple[str, float, float, float]]:
        """Every checkpoint with the evidence for ``<<(SELF at P)> =/> <trash --> [see]>>``,
        best expectation first: (place, frequency, confidence, expectation)."""
        ranked = []
        for place in self.places:
            ans = self.ask(f"<<({{SELF}} * {{{place}}}) --> at> =/> <trash --> [see]>>?")
            if ans is None:
                continue
            _term, f, c = ans
            ranked.append((place, f, c, c * (f - 0.5) + 0.5))
        ranked.sort(key=lambda r: -r[3])
        return ranked


def probe(seed: int = 0, frames: int = 12) -> str | None:
    """Why NarsMind cannot run yet, or None when the reasoner can drive the robot.

    Loads the background knowledge, then shows the reasoner a checkpoint with a bottle
    in front and an open gripper while it wants ``G``: a working reasoner picks.
    """
    try:
        mind = NarsMind(["p0", "p1"], NarsSettings(seed=seed))
    except NotReady as exc:
        return f"the background knowledge does not load: {exc}"
    except Exception as exc:  # a broken knowledge file or installation may fail in any way
        return f"the reasoner cannot start: {type(exc).__name__}: {exc}"
    frame: list[Percept] = [
        Detection("bottle", 0.0, 1.0, 0.9, "bottle1"),
        Obstacle("none", 2.0),
        Gripper(None),
        Pose(0.0, 0.0, 0.0, "p0"),
    ]
    try:
        for _ in range(frames):
            mind.perceive(frame)
            for command in mind.decide():
                if isinstance(command, Pick):
                    return None
    except Exception as exc:
        return f"the reasoner fails while deciding: {type(exc).__name__}: {exc}"
    return (
        "the reasoner does not act on its goals yet: shown a bottle at a checkpoint with "
        "an open gripper while wanting G, it did not execute ^pick"
    )
