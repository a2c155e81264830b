"""What the inspector shows of a world and of a mind, as plain JSON-ready dicts.

A view is taken in the robot's thread between two cycles and never touches the world
or the mind again afterwards: every value in it is a fresh str, number, list or dict,
so the web server can serialise it in its own thread while the robot goes on. Views
read only what the worlds, minds and engines offer publicly.

World views are cheap (they are taken after every cycle); mind views can cost a
millisecond or more on a large memory, and the :class:`~robocog.inspector.hub.Inspector`
takes them as often as its time budget allows.
"""

from __future__ import annotations

import heapq
import re
from collections import deque
from collections.abc import Callable, Sequence
from typing import Any

from robocog.robot.percepts import Detection, Percept, Pose

#: the most points of a trajectory one view carries (older ones are thinned out)
TRAJECTORY_POINTS = 300
#: bounds of the lists a mind view carries
CONCEPTS = 40
TABLE_ITEMS = 24
BELIEFS = 300
EVENTS = 100
LINES = 30

Json = dict[str, Any]


def _r(x: float, nd: int = 3) -> float:
    return round(float(x), nd)


def thin(
    points: Sequence[tuple[float, float]], limit: int = TRAJECTORY_POINTS
) -> list[list[float]]:
    """At most ``limit`` points of a path: every k-th of the older part, the newest 100
    as they are, so the robot's last moves are exact and the whole path still shows."""
    n = len(points)
    if n <= limit:
        chosen = list(points)
    else:
        recent = 100
        step = max(1, -(-(n - recent) // (limit - recent)))  # rounded up
        chosen = list(points[: n - recent : step]) + list(points[n - recent :])
    return [[_r(x, 2), _r(y, 2)] for x, y in chosen]


def _detections(percepts: Sequence[Percept] | None) -> list[Json]:
    out = []
    for p in percepts or ():
        if isinstance(p, Detection):
            out.append(
                {
                    "label": p.label,
                    "instance": p.instance,
                    "bearing": _r(p.bearing),
                    "distance": _r(p.distance),
                    "confidence": _r(p.confidence),
                }
            )
    return out


# ---- worlds --------------------------------------------------------------------------


class GarbageViewer:
    """The garbage field: fence, checkpoints, objects of this round, robot, path.

    Taken after every cycle, so what does not change is made once (the checkpoints)
    and the path is rounded as it grows; every view still gets lists of its own (the
    points inside are never changed once made).
    """

    def __init__(self) -> None:
        self._world: Any = None
        self._fixed: Json = {}
        self._points: list[list[float]] = []
        self._last: Json | None = None
        self._key: tuple[int, ...] = ()
        self._objects: dict[str, Json] = {}
        self._thinned: list[list[float]] | None = None

    def _setup(self, world: Any) -> None:
        c = world.config
        hot = {world.route[i]: w for i, w in c.hotspots.items() if i < len(world.route)}
        self._world = world
        self._points = []
        self._objects = {}
        self._thinned = None
        self._last, self._key = None, ()
        self._fixed = {
            "kind": "garbage",
            "size": c.size,
            "fov": _r(c.camera_fov),
            "camera_range": c.camera_range,
            "start": [_r(world.start[0], 2), _r(world.start[1], 2)],
            "checkpoints": [
                {"name": n, "x": _r(x, 2), "y": _r(y, 2), "hot": hot.get(n, 1.0)}
                for n, (x, y) in world.checkpoints.items()
            ],
        }

    def _path(self, trajectory: Sequence[tuple[float, float]]) -> list[list[float]]:
        points = self._points
        if len(points) > len(trajectory):  # a path that shrank: start again
            points.clear()
        elif len(points) == len(trajectory) and self._thinned is not None:
            return self._thinned  # shared by the views: never changed once made
        for x, y in trajectory[len(points) :]:
            points.append([round(x, 2), round(y, 2)])
        n = len(points)
        if n <= TRAJECTORY_POINTS:
            self._thinned = points[:]
        else:
            recent = 100
            step = -(-(n - recent) // (TRAJECTORY_POINTS - recent))
            self._thinned = points[: n - recent : step] + points[n - recent :]
        return self._thinned

    def __call__(self, world: Any, percepts: Sequence[Percept] | None = None) -> Json:
        if world is not self._world:
            self._setup(world)
        # What the objects are doing changes only through events the field logs (pick,
        # tip, drop, arrival, a new round): the part of the view about them is made
        # again only then, and shared (never changed) by the views in between.
        key = (len(world.events), world.rounds)
        if key != self._key or self._last is None:
            self._key = key
            self._last = self._objects_part(world)
        view = dict(self._last)
        view["time"] = round(world.clock, 2)
        view["robot"] = {
            "x": round(world.x, 2),
            "y": round(world.y, 2),
            "theta": round(world.theta, 3),
        }
        view["trajectory"] = self._path(world.trajectory)
        # the frame's Detection percepts themselves (frozen): made JSON when sent
        view["detections"] = (
            tuple(p for p in percepts if isinstance(p, Detection)) if percepts else ()
        )
        view["done"] = world.done
        return view

    def _objects_part(self, world: Any) -> Json:
        rounds = world.rounds
        objects = []
        collected = collected_round = 0
        static = self._objects
        for t in world.trash:
            if t.collected:
                collected += 1
            if t.round != rounds and not t.held:
                continue
            state = "held" if t.held else "collected" if t.collected else "field"
            if state == "collected":
                collected_round += 1
            fixed = static.get(t.instance)
            if fixed is None:  # an object does not move while it lies on the field
                fixed = static[t.instance] = {
                    "id": t.instance,
                    "label": t.label,
                    "x": round(t.x, 2),
                    "y": round(t.y, 2),
                }
            objects.append({**fixed, "upright": t.upright, "state": state, "seen": t.times_seen})
        part = dict(self._fixed)
        part.update(
            round=rounds,
            holding=world.holding.instance if world.holding is not None else None,
            visited=list(world.visited),
            objects=objects,
            collected=collected,
            collected_round=collected_round,
            events=[[e.time, e.kind, e.detail] for e in world.events[-8:]],
        )
        return part


def garbage_view(world: Any, percepts: Sequence[Percept] | None = None) -> Json:
    """The garbage field's view, made afresh (the inspector keeps a GarbageViewer)."""
    return GarbageViewer()(world, percepts)


def stacks(on: dict[str, str], fixed: Sequence[str]) -> dict[str, list[list[str]]]:
    """Each fixed object -> the stacks standing on it, each bottom to top."""
    above: dict[str, list[str]] = {}
    for obj, support in on.items():
        above.setdefault(support, []).append(obj)
    out: dict[str, list[list[str]]] = {}
    for f in fixed:
        piles = []
        for bottom in sorted(above.get(f, [])):
            pile, seen = [bottom], {bottom}
            while above.get(pile[-1]):
                nxt = sorted(above[pile[-1]])[0]
                if nxt in seen:  # a loop cannot stand; stop rather than spin
                    break
                pile.append(nxt)
                seen.add(nxt)
            piles.append(pile)
        out[f] = piles
    return out


def tabletop_view(world: Any, percepts: Sequence[Percept] | None = None) -> Json:
    """The tabletop: each fixed object (table, workbench, bins) with its stacks, the hand."""
    last = world.log[-8:]
    return {
        "kind": "tabletop",
        "time": _r(world.clock, 2),
        "fixed": list(world.fixed),
        "stacks": stacks(dict(world.on), world.fixed),
        "held": world.held,
        "grasps": world.grasps,
        "failed_grasps": world.failed_grasps,
        "log": [[_r(e.t, 1), str(e.command), e.outcome.status.value] for e in last],
    }


def room_view(world: Any, percepts: Sequence[Percept] | None = None) -> Json:
    """The room of Fujita et al.: walls, the door leaf, targets, the Q.bo and its path."""

    def seg(g: Any) -> list[float]:
        return [_r(g.ax, 2), _r(g.ay, 2), _r(g.bx, 2), _r(g.by, 2)]

    path = [(p.x, p.y) for p in world.trajectory]
    return {
        "kind": "room",
        "time": _r(world.clock, 2),
        "phase": world.phase,
        "robot": {"x": _r(world.x, 2), "y": _r(world.y, 2), "theta": _r(world.theta)},
        "walls": [seg(g) for g in world.solids],
        "targets": [{"id": t.id, "label": t.label, "face": seg(t.face)} for t in world.targets],
        "trajectory": thin(path),
        "marks": [[_r(x, 2), _r(y, 2), str(m)] for x, y, m in world.marks[-50:]],
        "seen": {
            k: {"source": v.source, "certainty": _r(v.certainty)}
            for k, v in world.last_seen.items()
        },
        "detections": _detections(percepts),
        "exited": bool(world.exited()),
    }


class BodyViewer:
    """Any other Body (a real robot behind a bridge): its clock, and what its percepts
    say: the pose (and the path it makes, kept bounded), detections, obstacles; the
    named places of its configuration when it has one."""

    def __init__(self, keep: int = 5000) -> None:
        self._path: deque[tuple[float, float]] = deque(maxlen=keep)
        self._pose: Json | None = None

    def __call__(self, world: Any, percepts: Sequence[Percept] | None = None) -> Json:
        out: Json = {"kind": "generic", "name": type(world).__name__}
        try:
            out["time"] = _r(world.time(), 2)
        except Exception:  # a body whose clock fails still shows the rest
            out["time"] = None
        for p in percepts or ():
            if isinstance(p, Pose):
                self._pose = {
                    "x": _r(p.x, 2),
                    "y": _r(p.y, 2),
                    "theta": _r(p.theta),
                    "place": p.place,
                }
                self._path.append((p.x, p.y))
        if self._pose is not None:
            out["robot"] = dict(self._pose)
            out["trajectory"] = thin(list(self._path))
        places = getattr(getattr(world, "config", None), "places", None)
        if isinstance(places, dict):
            out["places"] = [
                {"name": str(n), "x": _r(v[0], 2), "y": _r(v[1], 2)}
                for n, v in list(places.items())[:200]
                if isinstance(v, tuple | list) and len(v) >= 2
            ]
        out["percepts"] = [repr(p) for p in (percepts or ()) if not isinstance(p, Detection)][:20]
        out["detections"] = _detections(percepts)
        return out


def generic_world_view(world: Any, percepts: Sequence[Percept] | None = None) -> Json:
    """Any other Body's view, made afresh (the inspector keeps a BodyViewer)."""
    return BodyViewer()(world, percepts)


def world_viewer(world: Any) -> Callable[[Any, Sequence[Percept] | None], Json]:
    """The view function for this world's type."""
    from robocog.worlds.garbage import GarbageField
    from robocog.worlds.room import RoomWorld
    from robocog.worlds.tabletop import TabletopWorld

    if isinstance(world, GarbageField):
        return GarbageViewer()
    if isinstance(world, TabletopWorld):
        return tabletop_view
    if isinstance(world, RoomWorld):
        return room_view
    if type(world).__name__ == "MujocoRoom":  # the physical room (not imported: mujoco)
        return room_view
    return BodyViewer()


# ---- NARS ----------------------------------------------------------------------------

#: a checkpoint's hypothesis of Hammer et al., Section V.D (not the longer sequences
#: that end the same way)
_HYPOTHESIS = re.compile(r"<<\(\{SELF\} \* \{([^}]+)\}\) --> at> =/> <trash --> \[see\]>>")
_DECISION = re.compile(
    r"decision expectation=([0-9.]+) implication: (.*?)\. Stamp=.*precondition: (.*?)\. :\|:"
)


def _truth(t: Any) -> Json:
    f, c = float(t.f), float(t.c)
    return {"f": _r(f), "c": _r(c), "exp": _r(c * (f - 0.5) + 0.5)}


class NarsView:
    """Reads a robocog NAR: concepts by priority, implication tables, goals, decisions,
    anticipations. The reasoner's output lines are tapped (``NAR.output``, chained to
    whatever was there) to keep its recent decisions with their desire."""

    kind = "nars"

    def __init__(self, nar: Any, mind: Any = None) -> None:
        from robocog.nars import parse_term

        self.nar = nar
        self.mind = mind
        #: set by the inspector: true ends a console command at its next slice
        self.should_stop: Callable[[], bool] | None = None
        self.decisions: deque[Json] = deque(maxlen=LINES)
        self.answers: deque[str] = deque(maxlen=LINES)
        self._before = nar.output
        nar.output = self._tap
        #: the consequents whose implication tables are always shown
        self.watched = [parse_term("<trash --> [see]>"), parse_term("<gripper --> [hold]>")]

    def _tap(self, line: str) -> None:
        if line.startswith("decision expectation="):
            m = _DECISION.match(line)
            if m:
                self.decisions.append(
                    {
                        "time": self.nar.time,
                        "desire": _r(float(m.group(1))),
                        "implication": m.group(2),
                        "precondition": m.group(3),
                    }
                )
        elif " executed with args" in line:
            self.decisions.append({"time": self.nar.time, "executed": line})
        elif line.startswith("Answer:"):
            self.answers.append(line)
        if self._before is not None:
            self._before(line)

    def detach(self) -> None:
        """Give the reasoner its own output back."""
        if self.nar.output == self._tap:
            self.nar.output = self._before

    def _table(self, concept: Any, limit: int | None = TABLE_ITEMS) -> list[Json]:
        rows = []
        names = self.nar.op_names
        for opi, table in enumerate(concept.precondition_beliefs or ()):
            for imp in table.items[:limit]:
                row = {"term": str(imp.term), **_truth(imp.truth), "dt": _r(imp.dt, 1)}
                if opi:
                    row["op"] = names[opi - 1] if opi - 1 < len(names) else f"op{opi}"
                m = _HYPOTHESIS.fullmatch(row["term"])
                if m:
                    row["place"] = m.group(1)
                rows.append(row)
        rows.sort(key=lambda r: -r["exp"])
        return rows[:limit]

    def view(self) -> Json:
        nar = self.nar
        now = nar.time
        durability = nar.config.concept_durability
        memory = nar.memory
        top = heapq.nlargest(CONCEPTS, memory, key=lambda c: c.priority_at(now, durability))
        concepts = []
        for c in top:
            b = c.belief
            tables = sum(len(t) for t in c.precondition_beliefs or ())
            concepts.append(
                {
                    "term": str(c.term),
                    "priority": _r(c.priority_at(now, durability), 4),
                    "belief": _truth(b.truth) if b is not None else None,
                    "spike": _truth(c.belief_spike.truth) if c.belief_spike is not None else None,
                    "uses": c.use_count,
                    "links": tables,
                }
            )
        tables = []
        shown: set[str] = set()
        hypotheses: dict[str, Json] = {}
        for term in self.watched:
            c = memory.find(term)
            if c is not None:
                rows = self._table(c, None)  # the whole table (bounded by its size)
                if not hypotheses:
                    hypotheses = {r["place"]: r for r in reversed(rows) if "place" in r}
                tables.append({"consequent": str(c.term), "rows": rows[:TABLE_ITEMS]})
                shown.add(str(c.term))
        for c in top:
            if len(tables) >= 8:
                break
            if str(c.term) not in shown and any(len(t) for t in c.precondition_beliefs or ()):
                tables.append({"consequent": str(c.term), "rows": self._table(c)})
                shown.add(str(c.term))
        goals = []
        for layer, q in enumerate(nar.goal_layers):
            for priority, g in q.items[:EVENTS]:
                goals.append(
                    {
                        "term": str(g.term),
                        "layer": layer,
                        "priority": _r(priority, 4),
                        **_truth(g.truth),
                        "time": g.occurrence_time,
                    }
                )
        goals.sort(key=lambda g: -g["priority"])
        anticipations = []
        for c in memory:
            p = c.predicted_belief
            if p is not None and p.occurrence_time >= now - 5:
                anticipations.append(
                    {"term": str(p.term), **_truth(p.truth), "time": p.occurrence_time}
                )
        anticipations.sort(key=lambda a: -a["time"])
        out: Json = {
            "kind": "nars",
            "time": now,
            "concepts": concepts,
            "memory": {"concepts": len(memory), "capacity": memory.capacity},
            "tables": tables,
            "hypotheses": hypotheses,
            "goals": goals[:EVENTS],
            "threshold": nar.config.decision_threshold,
            "decisions": list(self.decisions),
            "answers": list(self.answers),
            "anticipations": anticipations[:EVENTS],
        }
        executed = getattr(self.mind, "decisions", None)
        if isinstance(executed, list):
            out["executed"] = [f"{op} {args or ''}".strip() for op, args in executed[-LINES:]]
        return out

    def command(self, kind: str, text: str) -> str:
        """``tell`` a line (Narsese, ``*command`` or cycles) or ``ask`` a question."""
        nar = self.nar
        if kind == "ask" or (kind == "tell" and text.rstrip().endswith("?")):
            answer = nar.ask(text)
            if answer is None:
                return "Answer: None."
            return f"Answer: {answer.term}. Truth: frequency={answer.truth.f:f}, confidence={answer.truth.c:f}"
        if kind == "tell":
            # a cycles line runs in slices, asking between them whether to stop: a
            # hundred million cycles do not hold the loop (nor, compiled, the server's
            # thread) past the page's stop or the end of the process
            before = nar.stop_requested
            nar.stop_requested = self.should_stop
            try:
                nar.add_input(text)
            finally:
                nar.stop_requested = before
            return f"Input: {text.strip()}"
        raise ValueError(f"NARS takes tell or ask, not {kind}")


# ---- BDI -----------------------------------------------------------------------------


class BdiView:
    """Reads an AgentSpeak agent: belief base, event queue, intentions as stacks."""

    kind = "bdi"

    def __init__(self, agent: Any, mind: Any = None) -> None:
        self.agent = agent
        self.mind = mind

    def view(self) -> Json:
        from robocog.bdi.plans import chain_steps

        a = self.agent
        circ = a.C
        beliefs = [str(b) for b in a.beliefs()][:BELIEFS]
        events = []
        for e in list(circ.events)[:EVENTS]:
            where = f" (intention {e.intention.id})" if e.intention is not None else ""
            events.append(f"{e.trigger}{where}")
        running = {i.id for i in circ.running}
        pending = {k: why for k, (_i, why) in circ.pending.items()}
        intentions = []
        for i in a.intentions()[:EVENTS]:
            frames = []
            for im in reversed(i.stack):
                plan = im.plan
                label = str(plan.label) if plan.label is not None else None
                steps = [str(s) for s in chain_steps(im.cur)[:5]] if im.cur is not None else []
                frames.append({"trigger": str(im.trigger), "plan": label, "next": steps})
            state = (
                "running"
                if i.id in running
                else f"waiting: {pending[i.id]}"
                if i.id in pending
                else "in an event"
            )
            intentions.append({"id": i.id, "state": state, "stack": frames})
        out: Json = {
            "kind": "bdi",
            "name": a.name,
            "cycle": a.cycle,
            "beliefs": beliefs,
            "events": events,
            "intentions": intentions,
        }
        actions = getattr(self.mind, "actions", None)
        if isinstance(actions, list):
            out["actions"] = actions[-LINES:]
        output = getattr(self.mind, "output", None)
        if isinstance(output, deque):
            out["output"] = list(output)[-LINES:]
        return out

    def command(self, kind: str, text: str) -> str:
        """``belief`` adds one (``-`` first removes it), ``goal`` posts ``+!g``,
        ``query`` answers a formula from the belief base."""
        a = self.agent
        text = text.strip()
        if kind == "belief":
            if text.startswith("-"):
                a.remove_belief(text[1:].strip().rstrip("."))
                return f"-{text[1:].strip()}"
            a.add_belief(text.lstrip("+").strip().rstrip("."))
            return f"+{text.lstrip('+').strip()}"
        if kind == "goal":
            a.add_goal(text.lstrip("+!").strip().rstrip("."))
            return f"+!{text.lstrip('+!').strip()}"
        if kind == "query":
            solutions = a.query(text.lstrip("?").strip().rstrip("."))
            if not solutions:
                return "no"
            shown = [
                "yes" if not s else ", ".join(f"{k}={v}" for k, v in s.items()) for s in solutions
            ]
            return "; ".join(shown[:20])
        raise ValueError(f"the agent takes belief, goal or query, not {kind}")


# ---- planner -------------------------------------------------------------------------


def scene_json(scene: Any) -> Json | None:
    """A planner scene as plain data (objects, fixed, on, held)."""
    if scene is None:
        return None
    return {
        "objects": list(scene.objects),
        "fixed": list(scene.fixed),
        "on": dict(scene.on),
        "held": scene.held,
    }


class PlannerView:
    """Reads a PlannerMind: the scene it tracks, the request, its plans and the step."""

    kind = "planner"

    def __init__(self, mind: Any) -> None:
        self.mind = mind

    def view(self) -> Json:
        m = self.mind
        record = m.current
        steps, index = m.plan_progress()
        req = None
        if record is not None:
            req = {
                "text": record.request,
                "goal": [list(f) for f in record.goal],
                "status": record.status,
                "message": record.message,
                "plans": [
                    {
                        "steps": p.lines(),
                        "iterations": p.iterations,
                        "seconds": _r(p.seconds, 4),
                        "mode": p.mode,
                        "found": p.found,
                    }
                    for p in record.plans[-5:]
                ],
                "executed": list(record.executed),
                "failures": list(record.failures),
                "replans": record.replans,
            }
        return {
            "kind": "planner",
            "seen": list(m.seen),
            "holding": m.holding,
            "scene": scene_json(m.scene),
            "request": req,
            "plan": [str(s) for s in steps],
            "step": index,
            "requests": len(m.records),
            "history": [
                {"text": r.request, "status": r.status, "replans": r.replans}
                for r in m.records[-10:]
            ],
        }

    def command(self, kind: str, text: str) -> str:
        """``english``: sentences of what must hold, planned from the tracked scene."""
        if kind != "english":
            raise ValueError(f"the planner takes English goals, not {kind}")
        record = self.mind.request(text)
        if record.status == "failed":
            raise ValueError(record.message)
        return "goal: " + "; ".join(" ".join(f) for f in record.goal)


def mind_viewer(mind: Any) -> NarsView | BdiView | PlannerView | None:
    """The view for this mind, by what it offers; None for a mind the inspector cannot read."""
    from robocog.minds.planner_mind import PlannerMind

    if isinstance(mind, PlannerMind):
        return PlannerView(mind)
    nar = getattr(mind, "nar", None)
    if nar is not None:
        from robocog.nars import NAR

        if isinstance(nar, NAR):
            return NarsView(nar, mind)
        return None
    agent = getattr(mind, "agent", None)
    if agent is not None:
        from robocog.bdi.agent import Agent

        if isinstance(agent, Agent):
            return BdiView(agent, mind)
    return None
