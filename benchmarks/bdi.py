"""robocog's AgentSpeak interpreter against python-agentspeak, in the same run.

Three workloads, the same AgentSpeak source for both interpreters:

a. counter   - a recursive goal that counts to N with ``-+counter(C+1)``;
b. contexts  - 100 beliefs and 50 plans for the same goal, told apart by their contexts;
c. qbo       - the search loop of the Q.bo paper (plans so1/so2, da1-da4) driving a
               Python action that moves a simulated robot until it is in front of the door.

Each workload reports achievement goals per second for both and the ratio (robocog /
python-agentspeak); the best of ``--repeat`` runs of each is kept, the two taking turns.
Times are CPU times of the run alone (building the agent and parsing are left out for
both). Run::

    python benchmarks/bdi.py            # full sizes
    python benchmarks/bdi.py --quick    # small sizes, for a smoke test
"""

from __future__ import annotations

import argparse
import io
import sys
import time
from collections.abc import Callable
from contextlib import redirect_stdout
from dataclasses import dataclass

from robocog.bdi import Agent

# ---------------------------------------------------------------------------- workloads


def counter_source(n: int) -> str:
    return f"""counter(0).
!count({n}).
+!count(0) : counter(C) <- done(C).
+!count(N) : N > 0 & counter(C) <- -+counter(C + 1); !count(N - 1).
"""


def contexts_source(rounds: int) -> str:
    beliefs = "\n".join(f"item({i}, {(i * 37) % 100})." for i in range(100))
    plans = "\n".join(
        f"+!check(I) : item(I, V) & V mod 50 == {k} <- -+last({k})." for k in range(50)
    )
    return f"""{beliefs}
last(none).
!rounds({rounds}).
+!rounds(0) <- done(0).
+!rounds(R) : R > 0 <- !loop(0); !rounds(R - 1).
+!loop(I) : I < 100 <- !check(I); !loop(I + 1).
+!loop(I) <- true.
{plans}
"""


def contexts_goals(rounds: int) -> int:
    return rounds * (100 + 101) + rounds + 1


QBO_PLANS = """
expected_target_direction(0).
!search_object(door).
+!search_object(Object) : not front_of(Object)
<- !get_my_current_direction;
   !get_information_of_obstacle;
   !around_search(Object);
   !decide_action;
   !search_object(Object).
+!search_object(Object) <- done(Object).
+!decide_action : found_target(Object) & target_direction(Dir) & found_obstacle
<- tcp_write(search_Qbo(Dir)).
+!decide_action : found_target(Object) & target_direction(Dir)
<- tcp_write(forward_Qbo(Dir)).
+!decide_action : found_obstacle & expected_target_direction(Dir)
<- tcp_write(search_Qbo(Dir)).
+!decide_action : expected_target_direction(Dir)
<- tcp_write(forward_Qbo(Dir)).
+!get_my_current_direction <- true.
+!get_information_of_obstacle <- true.
+!around_search(Object) <- looking_Qbo(Object).
"""


def qbo_goals(steps: int) -> int:
    return steps * 5 + 1


class Corridor:
    """The robot walks towards the door; every 7th step something is in the way."""

    def __init__(self, steps: int) -> None:
        self.steps = steps
        self.pos = 0

    def move(self) -> list[str]:
        self.pos += 1
        facts = []
        if self.pos % 7 == 0:
            facts.append("found_obstacle")
        if self.pos >= self.steps:
            facts.append("front_of(door)")
        return facts


# ---------------------------------------------------------------------------- runners


@dataclass
class Result:
    seconds: float
    goals: int
    check: object


def run_robocog(source: str, goals: int, env: Corridor | None) -> Result:
    finished: list[object] = []
    ag = Agent(source, "bench", printer=lambda n, t: None)
    ag.register_action("done", lambda x: finished.append(x) or True)
    if env is not None:
        ag.register_action("looking_Qbo", lambda obj: True)

        def tcp_write(cmd: object) -> bool:
            ag.set_percepts(env.move())
            return True

        ag.register_action("tcp_write", tcp_write, raw=True)
    t0 = time.process_time()
    ag.run()
    dt = time.process_time() - t0
    return Result(dt, goals, finished[0] if finished else None)


def run_python_agentspeak(source: str, goals: int, env: Corridor | None) -> Result:
    import agentspeak
    import agentspeak.runtime
    import agentspeak.stdlib

    finished: list[object] = []
    actions = agentspeak.Actions(agentspeak.stdlib.actions)

    @actions.add("done", 1)
    def _done(agent, term, intention):  # noqa: ANN001, ANN202
        finished.append(agentspeak.grounded(term.args[0], intention.scope))
        yield

    if env is not None:

        @actions.add("looking_Qbo", 1)
        def _look(agent, term, intention):  # noqa: ANN001, ANN202
            yield

        def _set(agent, facts: list[str]) -> None:  # noqa: ANN001
            for functor, args in (("found_obstacle", ()), ("front_of", ("door",))):
                key = (functor, len(args))
                lit = agentspeak.Literal(functor, tuple(agentspeak.Literal(a) for a in args))
                present = any(b.functor == functor for b in agent.beliefs[key])
                wanted = any(f.startswith(functor) for f in facts)
                if wanted and not present:
                    agent.add_belief(lit, {})
                elif present and not wanted:
                    agent.beliefs[key].clear()

        @actions.add("tcp_write", 1)
        def _tcp(agent, term, intention):  # noqa: ANN001, ANN202
            _set(agent, env.move())
            yield

    envr = agentspeak.runtime.Environment()
    src = io.StringIO(source)
    src.name = "bench.asl"
    agent = envr.build_agent(src, actions)
    t0 = time.process_time()
    with redirect_stdout(io.StringIO()):
        envr.run_agent(agent)
    dt = time.process_time() - t0
    return Result(dt, goals, finished[0] if finished else None)


def best_pair(
    ours: Callable[[], Result], peer: Callable[[], Result], repeat: int
) -> tuple[Result, Result]:
    """The best run of each, the two interpreters taking turns so that a burst of load
    on the shared machine falls on both rather than on one of them."""
    a: list[Result] = []
    b: list[Result] = []
    for _ in range(repeat):
        a.append(ours())
        b.append(peer())
    return min(a, key=lambda r: r.seconds), min(b, key=lambda r: r.seconds)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes (smoke test)")
    ap.add_argument("--repeat", type=int, default=3, help="runs per measurement (best kept)")
    args = ap.parse_args(argv)
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 100_000))

    n_count = 1_000 if args.quick else 10_000
    rounds = 2 if args.quick else 20
    qsteps = 200 if args.quick else 2_000
    workloads = [
        (f"a. counter -+ to {n_count}", counter_source(n_count), n_count + 1, None, n_count),
        (
            f"b. 100 beliefs, 50 plans ({rounds} rounds)",
            contexts_source(rounds),
            contexts_goals(rounds),
            None,
            0,
        ),
        (f"c. Q.bo search loop ({qsteps} steps)", QBO_PLANS, qbo_goals(qsteps), qsteps, "door"),
    ]
    rows = []
    for name, source, goals, steps, expected in workloads:
        ours, peer = best_pair(
            lambda s=source, g=goals, st=steps: run_robocog(s, g, Corridor(st) if st else None),
            lambda s=source, g=goals, st=steps: run_python_agentspeak(
                s, g, Corridor(st) if st else None
            ),
            args.repeat,
        )
        if expected is not None:
            assert ours.check == expected, (name, ours.check)
            assert str(peer.check).removesuffix(".0") == str(expected), (name, peer.check)
        rows.append((name, goals, goals / ours.seconds, goals / peer.seconds))

    try:
        from rich.console import Console
        from rich.table import Table

        table = Table(title="AgentSpeak: robocog vs python-agentspeak (achievement goals/s)")
        for col in ("workload", "goals", "robocog", "python-agentspeak", "ratio"):
            table.add_column(col, justify="left" if col == "workload" else "right")
        for name, goals, a, b in rows:
            table.add_row(name, str(goals), f"{a:,.0f}", f"{b:,.0f}", f"{a / b:.1f}x")
        Console().print(table)
    except ImportError:
        for name, goals, a, b in rows:
            print(f"{name:40s} {goals:8d} {a:12,.0f} {b:12,.0f} {a / b:6.1f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
