"""Robot: a grid robot that learns to find food and avoid walls.

Rules (those of ONA's ``robot`` system test): a 41 x 21 grid of two 19 x 19 rooms joined
by a door, walls around (with gaps that lead nowhere), 23 food cells and 23 extra wall
cells placed at random (a wall may land on the start cell, as in ONA's test; the robot
can still leave it). The robot starts at (5, 5) facing right; it faces one of eight
directions. ``^left``/``^right`` turn it by 45 degrees, ``^forward`` moves it one cell
along its heading unless a wall or the border is there (a successful forward is a
*move*). Only the first operation after the goal of a step acts.

Each step the robot looks ahead: three sectors (left, middle, right) are scanned ring by
ring outwards; a sector keeps the first thing it meets, food at any distance or a wall
within two rings, and the scan stops once any sector sees food. One event names what is
seen (the middle sector first, then left, then right): ``mf``/``mw``/``lf``/``lw``/``rf``/
``rw``. Seeing a wall in the middle arms the collision flag; when the way ahead is free
again the flag is cleared and ``(! collision)`` is input. Food under the robot is eaten
(``eaten`` is input and new food appears elsewhere). The goal is ``(! collision)`` while
the flag is armed, otherwise ``eaten``. Figures: move success ratio = moves / steps, and
the number of foods eaten. ONA raises the motor babbling chance to 0.3 for this test.
"""

from __future__ import annotations

from collections.abc import Iterator

from .base import Feed, ProcedureEnv, event, goal

WIDTH = 41
HEIGHT = 21
ROOM = 20
DOOR = 2  # door half-width
FOODS = 23
BLOCKS = 23
VIEW_RINGS = 50
WALL_SIGHT = 2

FREE, WALL, FOOD = "o", "w", "f"

# Headings counter-clockwise from "right"; ^left turns +1, ^right -1.
HEADINGS = ((1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1))


def _quarter_turns(dx: int, dy: int, turns: int) -> tuple[int, int]:
    """Rotate an offset by ``turns`` quarter turns counter-clockwise."""
    for _ in range(turns):
        dx, dy = -dy, dx
    return dx, dy


def _ring(heading: int, ring: int) -> list[tuple[int, int, int]]:
    """Offsets (sector, dx, dy) of one ring of the view, in the order they are examined.

    Facing along an axis, the left sector is the ring's part on the left of the heading
    (two cells per index, the near edge first), the middle is the cell straight ahead,
    the right sector mirrors the left. Facing diagonally, the left sector is the ring's
    edge through the corner ahead on the left, the right sector the other edge. Other
    headings are these two patterns turned by quarter turns.
    """
    cells: list[tuple[int, int, int]] = []
    if heading % 2 == 0:
        indices = range(1, ring + 1)
        pattern = lambda k: (  # noqa: E731
            (0, k, ring),
            (0, ring, k),
            (1, ring, 0),
            (2, ring, -k),
            (2, k, -ring),
        )
    else:
        indices = range(ring)
        pattern = lambda k: (  # noqa: E731
            (0, -k, ring),
            (0, k, ring),
            (1, ring, ring),
            (2, ring, k),
            (2, ring, -k),
        )
    for k in indices:
        for sector, dx, dy in pattern(k):
            cells.append((sector, *_quarter_turns(dx, dy, heading // 2)))
    return cells


# The view's scan order, computed once per heading.
_VIEW = [[_ring(h, r) for r in range(1, VIEW_RINGS + 1)] for h in range(8)]


class Robot(ProcedureEnv):
    """ONA's ``robot`` test."""

    name = "robot"
    operations = ("^left", "^right", "^forward")
    babbling_chance = 0.3
    reference_steps = 1_200

    def _reset_world(self) -> None:
        self.walls = [[False] * HEIGHT for _ in range(WIDTH)]
        self.food = [[False] * HEIGHT for _ in range(WIDTH)]
        self._build_rooms()
        for _ in range(FOODS):
            self._spawn(food=True)
        for _ in range(BLOCKS):
            self._spawn(food=False)
        self.x, self.y = 5, 5
        self.heading = 0
        self.may_act = False
        self.collided = False
        self.score.extra.update(moves=0, eaten=0, move_success_ratio=0.0)

    def _build_rooms(self) -> None:
        """Walls on every 20th row and column, with doors opened from each corner."""
        for x in range(WIDTH):
            for y in range(HEIGHT):
                if x % ROOM == 0 or y % ROOM == 0:
                    self.walls[x][y] = True
        for cx in range(0, WIDTH, ROOM):
            for cy in range(0, HEIGHT, ROOM):
                for k in range(-DOOR, DOOR + 1):
                    gx, gy = cx - ROOM // 2 + k, cy - ROOM // 2 + k
                    if 0 <= gx < WIDTH and 0 <= gy < HEIGHT:
                        self.walls[gx][cy] = False
                        self.walls[cx][gy] = False

    def _spawn(self, food: bool) -> None:
        """Put food (or a wall) on a random cell that holds neither."""
        while True:
            x, y = self.rng.randrange(WIDTH), self.rng.randrange(HEIGHT)
            if not self.walls[x][y] and not self.food[x][y]:
                if food:
                    self.food[x][y] = True
                else:
                    self.walls[x][y] = True
                return

    def cell(self, x: int, y: int) -> str:
        """What a cell holds; outside the grid is wall."""
        if not (0 <= x < WIDTH and 0 <= y < HEIGHT) or self.walls[x][y]:
            return WALL
        return FOOD if self.food[x][y] else FREE

    def view(self) -> tuple[list[str], tuple[int, int], bool]:
        """Look ahead and eat: (left, middle, right) sightings, cell ahead, food eaten.

        The cell ahead is the robot's own when the way is blocked. Food under the robot
        is consumed by every look, as in ONA's test.
        """
        seen = [FREE, FREE, FREE]
        blocked = [False, False, False]
        for ring_number, ring in enumerate(_VIEW[self.heading], start=1):
            if FOOD in seen:
                break
            for sector, dx, dy in ring:
                what = self.cell(self.x + dx, self.y + dy)
                if what != FREE and not blocked[sector]:
                    blocked[sector] = True
                    if not (what == WALL and ring_number > WALL_SIGHT):
                        seen[sector] = what
                if FOOD in seen:
                    break
        hx, hy = HEADINGS[self.heading]
        ahead = (self.x + hx, self.y + hy)
        if self.cell(*ahead) == WALL:
            ahead = (self.x, self.y)
        ate = self.food[self.x][self.y]
        if ate:
            self.food[self.x][self.y] = False
            self._spawn(food=True)
        return seen, ahead, ate

    def step(self) -> Iterator[Feed]:
        """Look, report, arm the single action of this step, state the goal."""
        self.steps += 1
        (left, middle, right), ahead, ate = self.view()
        if middle != FREE:
            yield [event("m" + middle)]
        elif left != FREE:
            yield [event("l" + left)]
        elif right != FREE:
            yield [event("r" + right)]
        if ahead != (self.x, self.y) and self.collided:
            self.collided = False
            yield [event("(! collision)")]
        if middle == WALL:
            self.collided = True
        if ate:
            self.score.successes += 1
            self.score.extra["eaten"] += 1
            yield [event("eaten")]
        self.may_act = True
        yield [goal("(! collision)" if self.collided else "eaten")]
        self.score.trials = self.steps
        self.score.extra["move_success_ratio"] = self.score.extra["moves"] / self.steps

    def execute(self, op: str) -> None:
        """Turn or move at once, if this step's action has not been used yet."""
        if not self.may_act or op not in self.operations:
            return
        self.may_act = False
        if op == "^left":
            self.heading = (self.heading + 1) % 8
        elif op == "^right":
            self.heading = (self.heading - 1) % 8
        else:
            _, ahead, _ = self.view()
            if ahead != (self.x, self.y):
                self.score.extra["moves"] += 1
            self.x, self.y = ahead

    def metrics(self) -> dict[str, float]:
        """ONA's figures for this test: move success ratio and foods eaten."""
        return {
            "ratio": self.score.extra["move_success_ratio"],
            "moves": self.score.extra["moves"],
            "eaten": self.score.extra["eaten"],
            "steps": self.steps,
        }
