"""The procedure-learning worlds follow their rules, replay from a seed, and can be won."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocog.experiments.procedures.reasoners import PolicyReasoner, TracingReasoner
from robocog.nars import parse_sentence
from robocog.worlds.procedures import (
    ENVIRONMENTS,
    Alien,
    Bandrobot,
    Cartpole,
    Pong,
    Pong2,
    ProcedureEnv,
    Robot,
    run,
)

from .policies import PERFECT, random_policy, scripted

NAMES = sorted(ENVIRONMENTS)


def transcript(env: ProcedureEnv, reasoner: PolicyReasoner, steps: int) -> list[object]:
    """Everything the world said and every operation answered, step by step."""
    env.reset(7)
    reasoner.start(env, 7)
    said: list[object] = []
    for _ in range(steps):
        for feed in env.step():
            said.append(tuple(feed))
            for op in reasoner.feed(feed):
                said.append(op)
                env.execute(op)
    return said


def feeds_of_one_step(env: ProcedureEnv, ops: list[str] | None = None) -> list[str | int]:
    """Run one step, executing ``ops`` after the first feed; return everything fed."""
    fed: list[str | int] = []
    for i, feed in enumerate(env.step()):
        fed += feed
        if i == 0:
            for op in ops or []:
                env.execute(op)
    return fed


# ---------------------------------------------------------------- all worlds


@pytest.mark.parametrize("name", NAMES)
def test_a_seed_replays_the_same_run(name: str) -> None:
    env = ENVIRONMENTS[name](0)
    first = transcript(env, random_policy(3), 300)
    again = transcript(env, random_policy(3), 300)
    assert first == again
    assert len(first) > 300


@pytest.mark.parametrize("name", ["pong", "pong2", "alien", "robot"])
def test_another_seed_gives_another_world(name: str) -> None:
    env = ENVIRONMENTS[name](0)
    first = transcript(env, random_policy(3), 400)
    env.reset(8)
    other = []
    reasoner = random_policy(3)
    reasoner.start(env, 8)
    for _ in range(400):
        for feed in env.step():
            other.append(tuple(feed))
            for op in reasoner.feed(feed):
                other.append(op)
                env.execute(op)
    assert first != other


@pytest.mark.parametrize("name", NAMES)
def test_every_input_is_a_present_tense_event_or_goal(name: str) -> None:
    env = ENVIRONMENTS[name](1)
    seen_goal = False
    for item in transcript(env, random_policy(1), 400):
        if not isinstance(item, tuple):
            assert item in env.operations
            continue
        for part in item:
            if isinstance(part, int):
                assert part > 0
                continue
            sentence = parse_sentence(part)
            assert sentence.tense == ":|:", part
            assert sentence.punctuation in ".!", part
            seen_goal |= sentence.punctuation == "!"
    assert seen_goal


@pytest.mark.parametrize("name", NAMES)
def test_every_step_states_the_goal_once(name: str) -> None:
    env = ENVIRONMENTS[name](2)
    for _ in range(50):
        fed = [x for feed in env.step() for x in feed]
        goals = [x for x in fed if isinstance(x, str) and "!" in x]
        assert len(goals) == 1, fed


@pytest.mark.parametrize("name", NAMES)
def test_a_scripted_policy_beats_a_random_one_by_far(name: str) -> None:
    steps = ENVIRONMENTS[name].reference_steps // 5 if name != "robot" else 600
    good = run(ENVIRONMENTS[name](1), scripted(name), steps, seed=1)
    bad = run(ENVIRONMENTS[name](1), random_policy(1), steps, seed=1)
    if name == "robot":
        assert good.metrics["eaten"] >= 30 > 12 >= bad.metrics["eaten"]
        assert good.ratio >= 0.5 > 0.25 >= bad.ratio
    elif name == "bandrobot":
        assert good.ratio >= 20 > 3 >= bad.ratio
    else:
        assert good.ratio >= 0.75, good.metrics
        assert bad.ratio <= 0.3, bad.metrics
    assert set(PERFECT) == set(ENVIRONMENTS)


# ---------------------------------------------------------------- Pong


def test_pong_reports_the_side_of_the_ball_and_nothing_when_aligned() -> None:
    env = Pong(0)
    env.ball_x, env.bat_x = 30, 20
    assert env.observation() == "ball_right"
    env.ball_x = 10
    assert env.observation() == "ball_left"
    env.ball_x = 20
    assert env.observation() is None


def test_pong_velocity_persists_and_the_bat_stays_on_the_field() -> None:
    env = Pong(0)
    env.ball_y = 10  # far from the bat's row: no hit or miss this step
    feeds_of_one_step(env, ["^left"])
    assert env.bat_x == 16
    env.ball_y = 10
    feeds_of_one_step(env)
    assert env.bat_x == 12  # still moving left without a new operation
    for _ in range(10):
        env.ball_y = 10
        feeds_of_one_step(env)
    assert env.bat_x == 0


def test_pong_hit_is_rewarded_with_the_goal_event() -> None:
    env = Pong(0)
    env.ball_x, env.ball_y, env.vx, env.vy, env.bat_x = 20, 1, 1, -1, 22
    fed = feeds_of_one_step(env)
    assert "good_nar. :|:" in fed
    assert (env.score.successes, env.score.trials) == (1, 1)
    assert env.ball_y >= 10  # respawned in the lower half
    env.ball_x, env.ball_y, env.vx, env.vy, env.bat_x = 40, 1, 1, -1, 0
    fed = feeds_of_one_step(env)
    assert "good_nar. :|:" not in fed
    assert (env.score.successes, env.score.trials) == (1, 2)


def test_pong2_sees_the_ball_equal_within_reach_and_stops() -> None:
    env = Pong2(0)
    env.ball_x, env.bat_x = 25, 20
    assert env.observation() == "ball_equal"
    env.ball_x = 26
    assert env.observation() == "ball_right"
    env.ball_x, env.ball_y = 26, 10
    column = env.ball_x
    feeds_of_one_step(env, ["^right"])
    assert env.bat_x == 29
    assert env.ball_x == column  # the ball only falls
    env.ball_y = 10
    feeds_of_one_step(env, ["^stop"])
    assert env.bat_x == 29


# ---------------------------------------------------------------- Alien


def test_alien_hit_only_when_in_reach() -> None:
    env = Alien(0)
    fed = feeds_of_one_step(env, ["^shoot"])  # both start at 0.5: in reach
    assert fed[:2] == ["c0. :|:", "s0! :|:"] and "s0. :|:" in fed
    assert (env.score.successes, env.score.trials) == (1, 1)
    env.alien_x, env.defender_x = 0.9, 0.1
    fed = feeds_of_one_step(env, ["^shoot"])
    assert fed[0] == "r0. :|:" and "s0. :|:" not in fed
    assert (env.score.successes, env.score.trials) == (1, 2)


def test_alien_moves_the_defender_in_tenths_within_bounds() -> None:
    env = Alien(0)
    env.alien_x = 0.0
    for _ in range(7):
        feeds_of_one_step(env, ["^left"])
    assert env.defender_x == 0.0
    assert env.relation() == "c0"
    env.alien_x = 0.9
    assert env.relation() == "r0"
    feeds_of_one_step(env, ["^right"])
    assert env.defender_x == pytest.approx(0.1)


# ---------------------------------------------------------------- Cartpole


def test_cartpole_falls_without_help_and_counts_failures() -> None:
    env = Cartpole(0)
    for _ in range(200):
        feeds_of_one_step(env)
    assert env.score.extra["failures"] > 100
    assert env.score.ratio < 0.3


def test_cartpole_operations_act_at_once_and_mirror_with_the_angle() -> None:
    env = Cartpole(0)
    env.execute("^left")
    assert env.angular_velocity == pytest.approx(0.2)  # angle < 0: mirrored
    assert env.velocity == pytest.approx(-0.1)
    env.angle = 1.0
    env.execute("^left")
    assert env.angular_velocity == pytest.approx(0.0)
    fed = feeds_of_one_step(env)
    assert fed[-3:] == [f"{env.sector()}. :|:", "good! :|:", 3]
    assert env.velocity == 0.0  # friction


def test_cartpole_sectors_cover_the_circle() -> None:
    env = Cartpole(0)
    sectors = set()
    for tenth in range(-31, 32):
        env.angle = tenth / 10
        sectors.add(env.sector())
    assert sectors == set(range(8))


# ---------------------------------------------------------------- Robot


def test_robot_world_has_rooms_a_door_and_the_food() -> None:
    env = Robot(0)
    assert all(env.walls[x][0] for x in range(41))
    assert not any(env.walls[20][y] for y in range(8, 13))  # the door between the rooms
    assert env.walls[20][5] and env.walls[20][15]
    assert sum(map(sum, env.food)) == 23
    walls_inside = sum(env.walls[x][y] for x in range(1, 40) for y in range(1, 20) if x != 20)
    assert walls_inside == 23


def _empty_robot() -> Robot:
    env = Robot(0)
    env.walls = [[False] * 21 for _ in range(41)]
    env.food = [[False] * 21 for _ in range(41)]
    env.x, env.y, env.heading = 10, 10, 0
    return env


def test_robot_sees_food_far_and_walls_only_near() -> None:
    env = _empty_robot()
    env.food[18][10] = True
    assert env.view()[0] == ["o", "f", "o"]
    env.food[18][10] = False
    env.food[14][12] = True  # ahead and to the left (up) when facing right
    assert env.view()[0][0] == "f"
    env.food[14][12] = False
    env.walls[14][10] = True
    assert env.view()[0][1] == "o"  # a wall four cells away is not seen
    env.walls[12][10] = True
    assert env.view()[0][1] == "w"


def test_robot_only_the_first_operation_of_a_step_acts() -> None:
    env = _empty_robot()
    fed = [x for feed in env.step() for x in feed]
    assert fed[-1] == "eaten! :|:"
    env.execute("^left")
    env.execute("^forward")
    assert (env.heading, env.x, env.y) == (1, 10, 10)
    list(env.step())
    env.execute("^forward")
    assert (env.x, env.y) == (11, 11)  # diagonal move
    assert env.score.extra["moves"] == 1


def test_robot_blocked_by_a_wall_then_rewarded_for_getting_free() -> None:
    env = _empty_robot()
    env.walls[11][10] = True
    fed = [x for feed in env.step() for x in feed]
    assert fed == ["mw. :|:", "(! collision)! :|:"]
    env.execute("^forward")
    assert (env.x, env.y) == (10, 10)
    assert env.score.extra["moves"] == 0
    list(env.step())
    env.execute("^left")
    fed = [x for feed in env.step() for x in feed]
    assert "(! collision). :|:" in fed and fed[-1] == "eaten! :|:"


def test_robot_eats_food_it_stands_on_and_food_reappears() -> None:
    env = _empty_robot()
    env.food[11][10] = True
    list(env.step())
    env.execute("^forward")
    fed = [x for feed in env.step() for x in feed]
    assert "eaten. :|:" in fed
    assert env.score.extra["eaten"] == 1
    assert sum(map(sum, env.food)) == 1 and not env.food[11][10]


# ---------------------------------------------------------------- Bandrobot


def test_bandrobot_picks_only_on_the_object_and_delivers_on_the_goal() -> None:
    env = Bandrobot(0)
    feeds_of_one_step(env, ["^pick"])  # robot at 0, object at 1
    fed = feeds_of_one_step(env, ["^right"])
    assert not env.picked and "picked. :|:" not in fed
    feeds_of_one_step(env, ["^pick"])
    fed = feeds_of_one_step(env, ["^right"])
    assert env.holding
    assert fed[0] == "<{position} |-> [dropPosX]>. :|: %0.050000%"
    assert fed[1] == "<{targetposition} |-> [dropPosX]>. :|: %0.150000%"
    assert "picked. :|:" in fed
    feeds_of_one_step(env, ["^right"])
    feeds_of_one_step(env, ["^drop"])
    fed = feeds_of_one_step(env)
    assert env.position == 3 and "delivered. :|:" in fed
    assert env.score.successes == 1


def test_a_trace_holds_the_configuration_every_input_and_every_operation(tmp_path: Path) -> None:
    path = tmp_path / "alien.nal"
    result = run(Alien(0), TracingReasoner(scripted("alien"), path), 30, seed=0)
    lines = path.read_text().splitlines()
    assert lines[0] == "//alien seed=0 reasoner=scripted-alien"
    assert lines[1:6] == [
        "*setopname 1 ^left",
        "*setopname 2 ^right",
        "*setopname 3 ^shoot",
        "*babblingops=3",
        "*motorbabbling=0.2",
    ]
    assert lines.count("s0! :|:") == 30
    executed = [line.removeprefix("//executed ") for line in lines if line.startswith("//executed")]
    assert len(executed) == sum(result.operations.values()) > 0
    assert lines.count("s0. :|:") == result.metrics["hits"]


def test_a_time_limit_stops_a_run_and_says_how_far_it_got() -> None:
    full = run(Pong(0), scripted("pong"), 40, seed=0)
    cut = run(Pong(0), scripted("pong"), 40, seed=0, time_limit=0.0)
    assert (full.completed_steps, cut.completed_steps) == (40, 1)
    assert cut.steps == 40
