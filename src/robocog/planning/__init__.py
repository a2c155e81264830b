"""Manipulation planning over AtomSpace states: the four blocks actions as
Atomese rules, breadth-first and A* search, controlled English and PDDL input/output.

Start with :class:`Planner` (``Planner().plan(scene, goal)``), :func:`scene_from_english`
and :func:`goal_from_english`; docs/planning.md has the tour.
"""

from robocog.planning.english import EnglishError, Statement, read_sentences
from robocog.planning.planner import (
    ALL_MODES,
    Planner,
    PlanningError,
    PlanResult,
    Step,
    goal_from_english,
    scene_from_english,
)
from robocog.planning.world import Scene, SceneError

__all__ = [
    "ALL_MODES",
    "EnglishError",
    "PlanResult",
    "Planner",
    "PlanningError",
    "Scene",
    "SceneError",
    "Statement",
    "Step",
    "goal_from_english",
    "read_sentences",
    "scene_from_english",
]
