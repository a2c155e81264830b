"""Whatever the operations, every world stays inside its own rules (property tests)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.worlds.procedures import Alien, Bandrobot, Cartpole, Pong, Pong2, ProcedureEnv, Robot
from robocog.worlds.procedures.cartpole import PI

OPS_PER_STEP = st.lists(
    st.sampled_from(["^left", "^right", "^stop", "^shoot", "^forward", "^pick", "^drop", "^other"]),
    max_size=3,
)
RUNS = settings(max_examples=25, deadline=None)


def drive(env: ProcedureEnv, script: list[list[str]], check: object) -> None:
    """Step the world, executing the script's operations after each feed; check after each step."""
    for ops in script:
        for _ in env.step():
            for op in ops:
                env.execute(op)
        check(env)  # type: ignore[operator]
        assert 0 <= env.score.successes <= max(env.score.trials, env.score.successes)
    assert env.steps == len(script)


@RUNS
@given(seed=st.integers(0, 10**6), script=st.lists(OPS_PER_STEP, max_size=80))
def test_pong_bat_and_ball_stay_on_the_field(seed: int, script: list[list[str]]) -> None:
    for env in (Pong(seed), Pong2(seed)):

        def check(e: Pong) -> None:
            low, high = e.bat_range
            assert low <= e.bat_x <= high
            assert 0 <= e.ball_x < 50 and 0 <= e.ball_y < 20
            assert e.score.trials == e.score.extra["hits"] + e.score.extra["misses"]

        drive(env, script, check)


@RUNS
@given(seed=st.integers(0, 10**6), script=st.lists(OPS_PER_STEP, max_size=80))
def test_alien_defender_stays_in_the_unit_interval(seed: int, script: list[list[str]]) -> None:
    def check(e: Alien) -> None:
        assert 0.0 <= e.defender_x <= 1.0 and 0.0 <= e.alien_x < 1.0
        assert e.score.successes <= e.score.trials == e.score.extra["shots"]

    drive(Alien(seed), script, check)


@RUNS
@given(script=st.lists(OPS_PER_STEP, max_size=80))
def test_cartpole_angle_wraps_and_cart_stays_on_track(script: list[list[str]]) -> None:
    def check(e: Cartpole) -> None:
        assert -PI <= e.angle <= PI
        assert 0.0 <= e.position <= 1.0
        # eight octants, and ONA's ninth value when a wrap leaves the angle exactly at pi
        assert 0 <= e.sector() <= 7 or (e.sector() == 8 and e.angle == PI)

    drive(Cartpole(0), script, check)


@RUNS
@given(seed=st.integers(0, 10**6), script=st.lists(OPS_PER_STEP, max_size=60))
def test_robot_never_enters_a_wall_and_food_is_kept_constant(
    seed: int, script: list[list[str]]
) -> None:
    def check(e: Robot) -> None:
        # a wall block may be dropped on the start cell (as in ONA); elsewhere, never
        assert e.cell(e.x, e.y) != "w" or (e.x, e.y) == (5, 5)
        assert sum(map(sum, e.food)) == 23
        assert e.score.extra["moves"] <= e.steps

    drive(Robot(seed), script, check)


@RUNS
@given(seed=st.integers(0, 10**6), script=st.lists(OPS_PER_STEP, max_size=80))
def test_bandrobot_carries_the_object_with_it(seed: int, script: list[list[str]]) -> None:
    def check(e: Bandrobot) -> None:
        assert 0 <= e.position <= 20 and 0 <= e.target <= 20 and 0 <= e.goal_position <= 20
        assert e.picked == e.holding

    drive(Bandrobot(seed), script, check)
