"""robocog's AgentSpeak interpreter against python-agentspeak, in the same run.

Three workloads, the same AgentSpeak source for both interpreters:

a. counter   - a recursive goal that counts to N with ``-+counter(C+1)``;
b. contexts  - 100 beliefs and 50 plans for the same goal, told apart by their contexts;
c. qbo       - the search loop of the Q.bo paper (plans so1/so2, da1-da4) driving a
               Python action that moves a simulated robot until it is in front of the door;
d. lists     - 1,000 beliefs read into a list with ``.findall`` and worked on with
               ``.sort``, ``.length``, ``.nth`` and ``.max``, round after round;
e. ring      - 100 agents passing a token around a ring with ``.send(N, achieve, ...)``.

Each workload reports achievement goals per second for both and the ratio (robocog /
python-agentspeak); the best of ``--repeat`` runs of each is kept, the two taking turns.
Times are CPU times of the run alone (building the agent and parsing are left out for
both). Run::

    python benchmarks/bdi.py            # full sizes
    python benchmarks/bdi.py --quick    # small sizes, for a smoke test
    python benchmarks/bdi.py --jason ~/.cache/robocog-peers/jason

``--jason DIR`` adds real Jason as a third side (built by
``../shared/tools/jason/build-jason.sh``, which leaves the launcher ``DIR/jason-agent``;
not part of CI) on the workloads that need no Python action: a, b, d and e. Jason runs
the same plans in one JVM, the work ``--repeat`` times over, and is measured two ways:
"Jason CPU" is the CPU time of the whole JVM (every thread: the compiler's and the
collector's too) less that of the same program with the work taken out (start-up,
parsing, the idle wait before exit), over the repetitions; "Jason clock" is the best
repetition by ``.nano_time`` inside the agent, once the compiler has warmed up.
"robocog process" takes Jason's CPU measure of robocog: the CPU of a whole ``robocog
agent`` process running the same program (work repeated, clock readings left out) less
that of the process without the work, least of two runs of each; its ratio is to
"Jason CPU".
"""

from __future__ import annotations

import argparse
import io
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from contextlib import redirect_stdout
from dataclasses import dataclass

from robocog.bdi import Agent
from robocog.bdi.mas import MultiAgentSystem

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


def lists_source(rounds: int) -> str:
    beliefs = "\n".join(f"val({i}, {(i * 7919) % 1000})." for i in range(1000))
    return f"""{beliefs}
!rounds({rounds}).
+!rounds(0) <- done(0).
+!rounds(R) : R > 0
<- .findall(V, val(_, V), L); .sort(L, S); .length(S, N); .nth(N div 2, S, M);
   .max(L, X); !rounds(R - 1).
"""


def ring_source(first: bool, laps: int, size: int, nxt: str) -> str:
    """One agent of the ring, which hands the token to ``nxt``; the first one starts it,
    and it goes ``laps`` times around the ``size`` agents; whoever takes it at 0 reports."""
    start = f"!token({laps * size}).\n" if first else ""
    return f"""next({nxt}).
{start}+!token(0) <- done(0).
+!token(K) : next(N) <- .send(N, achieve, token(K - 1)).
"""


def ring_names(size: int) -> list[str]:
    return [f"ag{i}" for i in range(1, size + 1)]


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


def _python_agentspeak_actions(finished: list[object]):  # noqa: ANN202
    """python-agentspeak's standard actions and ``done(X)``, which records X."""
    import agentspeak
    import agentspeak.stdlib

    actions = agentspeak.Actions(agentspeak.stdlib.actions)

    @actions.add("done", 1)
    def _done(agent, term, intention):  # noqa: ANN001, ANN202
        finished.append(agentspeak.grounded(term.args[0], intention.scope))
        yield

    return actions


def run_python_agentspeak(source: str, goals: int, env: Corridor | None) -> Result:
    import agentspeak
    import agentspeak.runtime

    finished: list[object] = []
    actions = _python_agentspeak_actions(finished)

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


def run_robocog_ring(laps: int, size: int) -> Result:
    finished: list[object] = []
    names = ring_names(size)
    mas = MultiAgentSystem()
    for i, name in enumerate(names):
        nxt = names[(i + 1) % size]
        ag = Agent(ring_source(i == 0, laps, size, nxt), name)
        ag.register_action("done", lambda x: finished.append(x) or True)
        mas.add(ag)
    t0 = time.process_time()
    mas.run()
    dt = time.process_time() - t0
    return Result(dt, laps * size + 1, finished[0] if finished else None)


def run_python_agentspeak_ring(laps: int, size: int) -> Result:
    import agentspeak.runtime

    finished: list[object] = []
    actions = _python_agentspeak_actions(finished)

    envr = agentspeak.runtime.Environment()
    names = ring_names(size)
    for i, name in enumerate(names):
        src = io.StringIO(ring_source(i == 0, laps, size, names[(i + 1) % size]))
        src.name = f"{name}.asl"
        envr.build_agent(src, actions, name=name)
    t0 = time.process_time()
    with redirect_stdout(io.StringIO()):
        envr.run()
    dt = time.process_time() - t0
    return Result(dt, laps * size + 1, finished[0] if finished else None)


# ---------------------------------------------------------------------------- Jason
#: the body of a repeated measurement in Jason: ``RESET`` restores the start state,
#: ``WORK`` runs the workload once (as a subgoal), then the time it took is printed
_JASON_BENCH = """!bench({repeat}).
+!bench(0).
+!bench(K) : K > 0
<- {reset}.nano_time(T0); {work}; .nano_time(T1); .print("bench-ns ", T1 - T0);
   !bench(K - 1).
"""


def jason_single(source: str, work: str, reset: str, repeat: int) -> str:
    """A workload's plans for Jason, its start goal replaced by a timed loop; the
    environment action ``done`` becomes ``true`` (Jason runs here without one)."""
    body = "\n".join(ln for ln in source.splitlines() if not ln.startswith("!"))
    body = re.sub(r"done\([^)]*\)", "true", body)
    return body + "\n" + _JASON_BENCH.format(repeat=repeat, work=work, reset=reset)


def jason_ring(folder: str, laps: int, size: int, repeat: int) -> str:
    """A Jason project of the ring: the first agent starts each lap set and is told
    when the token reaches 0; returns the .mas2j path."""
    names = ring_names(size)
    with open(os.path.join(folder, "ring.asl"), "w") as f:
        f.write(
            "+!token(0) <- .send(ag1, achieve, finished).\n"
            "+!token(K) : next(N) <- .send(N, achieve, token(K - 1)).\n"
        )
    with open(os.path.join(folder, "first.asl"), "w") as f:
        f.write(
            "+!bench(0).\n"
            f"+!bench(K) : K > 0 <- .nano_time(T0); -+started(T0, K); "
            f"!token({laps * size}).\n"
            '+!finished : started(T0, K) <- .nano_time(T1); .print("bench-ns ", T1 - T0); '
            "!bench(K - 1).\n"
            "+!token(0) <- !finished.\n"
            "+!token(K) : next(N) <- .send(N, achieve, token(K - 1)).\n"
        )
    lines = [f'    ag1 first.asl [beliefs="next({names[1]})", goals="bench({repeat})"];']
    for i, name in enumerate(names[1:], start=1):
        lines.append(f'    {name} ring.asl [beliefs="next({names[(i + 1) % size]})"];')
    path = os.path.join(folder, "ring.mas2j")
    with open(path, "w") as f:
        f.write("MAS ring {\n  agents:\n" + "\n".join(lines) + '\n  aslSourcePath: ".";\n}\n')
    return path


def _jason_cpu(launcher: str, path: str) -> tuple[float, str]:
    """CPU seconds of the JVM (all its threads: the compiler's and the collector's too)
    running ``path``, and what it printed."""
    env = dict(os.environ, JRUN_OPTS="-Djrun.max=600000 -Djrun.quiet=500")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run([launcher, path], capture_output=True, text=True, timeout=900, env=env)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, done.stdout + done.stderr


def run_jason(launcher: str, path: str, goals: int, repeat: int) -> tuple[Result, Result]:
    """Run ``path`` (which starts ``bench(repeat)``) in real Jason, and once more with
    ``bench(0)``: start-up, parsing and the idle wait before exit, without the work.
    Returns (the CPU of the work alone, the difference over ``repeat``; the best
    repetition by the agent's own clock)."""
    cpu, out = _jason_cpu(launcher, path)
    times = [float(m) for m in re.findall(r"bench-ns\s+([0-9.eE+]+)", out)]
    if len(times) < repeat:
        raise SystemExit(f"Jason ran {len(times)} of {repeat} repetitions of {path}:\n{out[-800:]}")
    stem, ext = os.path.splitext(path)
    with open(path) as f:
        text = f.read()
    empty = f"{stem}-empty{ext}"
    with open(empty, "w") as f:
        f.write(text.replace(f"bench({repeat})", "bench(0)", 1))
    base, _ = _jason_cpu(launcher, empty)
    work = Result(max(cpu - base, 1e-9) / repeat, goals, None)
    return work, Result(min(times) / 1e9, goals, None)


def _robocog_cpu(path: str) -> float:
    """CPU seconds of a whole ``robocog agent`` process running ``path`` (Python's
    start-up, the imports, parsing and the run), on the virtual clock."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run(
        [sys.executable, "-m", "robocog", "agent", path, "--clock", "virtual"],
        capture_output=True,
        text=True,
        timeout=900,
    )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise SystemExit(f"robocog agent {path} failed:\n{done.stderr[-800:]}")
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def run_robocog_process(jason_path: str, goals: int, repeat: int, tries: int = 2) -> Result | None:
    """The measure Jason's "CPU" column uses, taken of robocog too: the CPU of the
    whole process running the work ``repeat`` times, less that of the same process
    with the work taken out (start-up, imports, parsing), per repetition; the least of
    ``tries`` runs of each. The program is Jason's, its clock readings left out."""

    def untimed(text: str) -> str:
        text = re.sub(r"\.nano_time\((T[01])\)", r"\1 = 0", text)
        # a constraint that holds (``true`` past a body's start is an action)
        return text.replace('.print("bench-ns ", T1 - T0)', "T1 >= T0")

    with open(jason_path) as f:
        text = untimed(f.read())
    first = os.path.join(os.path.dirname(jason_path), "first.asl")
    if jason_path.endswith(".mas2j") and os.path.exists(first):  # the ring's timer
        with open(first) as f:
            timed = f.read()
        with open(first, "w") as f:
            f.write(untimed(timed))
    stem, ext = os.path.splitext(jason_path)
    work, empty = f"{stem}-rc{ext}", f"{stem}-rc-empty{ext}"
    with open(work, "w") as f:
        f.write(text)
    with open(empty, "w") as f:
        f.write(text.replace(f"bench({repeat})", "bench(0)", 1))
    cpu = min(_robocog_cpu(work) for _ in range(tries))
    base = min(_robocog_cpu(empty) for _ in range(tries))
    if cpu - base <= 0.005:
        return None  # the work is lost in the noise of start-up (use full sizes)
    return Result((cpu - base) / repeat, goals, None)


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
    ap.add_argument(
        "--jason", metavar="DIR", help="real Jason as a peer: the folder of its jason-agent"
    )
    args = ap.parse_args(argv)
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 100_000))
    launcher = None
    if args.jason:
        launcher = os.path.join(os.path.expanduser(args.jason), "jason-agent")
        if not os.access(launcher, os.X_OK):
            raise SystemExit(f"--jason: no {launcher} (build it with build-jason.sh)")

    n_count = 1_000 if args.quick else 10_000
    rounds = 2 if args.quick else 20
    qsteps = 200 if args.quick else 2_000
    lrounds = 5 if args.quick else 50
    laps = 2 if args.quick else 20
    size = 100
    # (name, source, goals, Q.bo steps, expected result, Jason's work and reset)
    workloads = [
        (
            f"a. counter -+ to {n_count}",
            counter_source(n_count),
            n_count + 1,
            None,
            n_count,
            (f"!count({n_count})", "-+counter(0); "),
        ),
        (
            f"b. 100 beliefs, 50 plans ({rounds} rounds)",
            contexts_source(rounds),
            contexts_goals(rounds),
            None,
            0,
            (f"!rounds({rounds})", ""),
        ),
        (
            f"c. Q.bo search loop ({qsteps} steps)",
            QBO_PLANS,
            qbo_goals(qsteps),
            qsteps,
            "door",
            None,
        ),
        (
            f"d. lists over 1,000 beliefs ({lrounds} rounds)",
            lists_source(lrounds),
            lrounds + 1,
            None,
            0,
            (f"!rounds({lrounds})", ""),
        ),
    ]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, source, goals, steps, expected, jason in workloads:
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
            theirs = None
            if launcher and jason is not None:
                path = os.path.join(tmp, f"w{len(rows)}.asl")
                with open(path, "w") as f:
                    f.write(jason_single(source, jason[0], jason[1], args.repeat))
                cpu, wall = run_jason(launcher, path, goals, args.repeat)
                proc = run_robocog_process(path, goals, args.repeat)
                theirs = (goals / cpu.seconds, goals / wall.seconds, proc and goals / proc.seconds)
            rows.append((name, goals, goals / ours.seconds, goals / peer.seconds, theirs))
        name = f"e. ring of {size} agents, {laps} laps"
        ours, peer = best_pair(
            lambda: run_robocog_ring(laps, size),
            lambda: run_python_agentspeak_ring(laps, size),
            args.repeat,
        )
        assert ours.check == 0 and str(peer.check).removesuffix(".0") == "0", (ours, peer)
        theirs = None
        if launcher:
            path = jason_ring(tmp, laps, size, args.repeat)
            cpu, wall = run_jason(launcher, path, ours.goals, args.repeat)
            proc = run_robocog_process(path, ours.goals, args.repeat)
            theirs = (
                ours.goals / cpu.seconds,
                ours.goals / wall.seconds,
                ours.goals / proc.seconds,
            )
        rows.append(
            (name, ours.goals, ours.goals / ours.seconds, peer.goals / peer.seconds, theirs)
        )

    cols = ["workload", "goals", "robocog", "python-agentspeak", "ratio"]
    if launcher:
        cols += ["Jason CPU", "ratio", "Jason clock", "ratio", "robocog process", "ratio"]

    def cells(goals: int, a: float, b: float, j: tuple | None) -> list[str]:
        out = [str(goals), f"{a:,.0f}", f"{b:,.0f}", f"{a / b:.1f}x"]
        if launcher:
            if j is None:
                out += ["-"] * 6
            else:
                out += [f"{j[0]:,.0f}", f"{a / j[0]:.2f}x", f"{j[1]:,.0f}", f"{a / j[1]:.2f}x"]
                out += [f"{j[2]:,.0f}", f"{j[2] / j[0]:.2f}x"] if j[2] else ["-", "-"]
        return out

    try:
        from rich.console import Console
        from rich.table import Table

        table = Table(title="AgentSpeak (achievement goals/s)")
        for col in cols:
            table.add_column(col, justify="left" if col == "workload" else "right")
        for name, goals, a, b, j in rows:
            table.add_row(name, *cells(goals, a, b, j))
        Console(width=200).print(table)
    except ImportError:
        for name, goals, a, b, j in rows:
            print(f"{name:44s} " + " ".join(f"{c:>12s}" for c in cells(goals, a, b, j)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
