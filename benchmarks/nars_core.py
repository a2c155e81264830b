"""Declarative workload: robocog's NARS in both modes against ONA on the same taxonomy.

A random tree of ``--statements`` inheritance links ``<child --> parent>`` is fed in
top-down order, then ``--questions`` questions each ask for an ancestor ``--depth``
links up (``<n17 --> n3>?``). Both reasoners run as child processes reading the same
text on stdin (``robocog nar`` and ``NAR shell``), so wall time and peak resident memory
are measured the same way (``wait4``). robocog runs once per mode (``--ona 0.9.2``, the
papers' behaviour, and ``--ona 0.9.3``, the shell's default), ONA 0.9.2's binary (the
``ona`` package's ``NAR``) beside them; prints each, the answers each found and the
ratios of every system to each robocog mode.

    python benchmarks/nars_core.py                        # 1,000 links, 100 questions
    python benchmarks/nars_core.py --statements 10000 --depth 2 --capacity 30000
    python benchmarks/nars_core.py --stream 1000000   # random valid/invalid lines, events, goals
    python benchmarks/nars_core.py --ona-source ~/OpenNARS-for-Applications  # also newest ONA
    python benchmarks/nars_core.py --modes 0.9.3 --no-ona     # robocog's default mode alone

``--ona-source`` builds ONA from a source checkout the user provides (its ``build.sh``,
with the C compiler of the machine) in a scratch directory, and runs it as a third system;
nothing is downloaded.
"""

from __future__ import annotations

import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

#: the ONA versions whose behaviour ``robocog nar --ona`` follows
ONA_MODES = ("0.9.2", "0.9.3")


def taxonomy(n: int, questions: int, depth: int, seed: int) -> tuple[list[str], list[str]]:
    """Statements of a random tree over ``n + 1`` nodes and questions ``depth`` links up."""
    rng = random.Random(seed)
    parent = [-1]
    for i in range(1, n + 1):
        parent.append(rng.randrange(max(0, i - 50), i))
    statements = [f"<n{i} --> n{parent[i]}>." for i in range(1, n + 1)]

    def up(i: int, k: int) -> int:
        for _ in range(k):
            i = parent[i]
            if i < 0:
                return -1
        return i

    deep = [i for i in range(1, n + 1) if up(i, depth) >= 0]
    asked = rng.sample(deep, min(questions, len(deep)))
    qs = [f"<n{i} --> n{up(i, depth)}>?" for i in asked]
    return statements, qs


def run(cmd: list[str], text: str, timeout: float) -> tuple[float, float, float, str]:
    """Wall seconds, CPU seconds, peak RSS in MB and stdout of ``cmd`` fed ``text``."""
    with tempfile.TemporaryFile("w+") as fin, tempfile.TemporaryFile("w+") as fout:
        fin.write(text)
        fin.seek(0)
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, stdin=fin, stdout=fout, stderr=subprocess.DEVNULL)
        deadline = t0 + timeout
        while True:
            pid, status, usage = os.wait4(p.pid, os.WNOHANG)
            if pid:
                break
            if time.perf_counter() > deadline:
                p.kill()
                pid, status, usage = os.wait4(p.pid, 0)
                break
            time.sleep(0.01)
        p.returncode = os.waitstatus_to_exitcode(status)
        wall = time.perf_counter() - t0
        fout.seek(0)
        cpu = usage.ru_utime + usage.ru_stime
        return wall, cpu, usage.ru_maxrss / 1024.0, fout.read()


def build_ona(source: str) -> tuple[str, str]:
    """Build ONA from the checkout at ``source`` in a scratch copy; its binary and version.

    The copy keeps the checkout clean (ONA's build script writes ``NAR`` and a generated
    rule table into the tree it runs in)."""
    if shutil.which("gcc") is None:
        raise SystemExit("--ona-source needs gcc (Debian: apt-get install gcc)")
    if not os.path.isfile(os.path.join(source, "build.sh")):
        raise SystemExit(f"--ona-source: no build.sh in {source}")
    version = subprocess.run(
        ["git", "-C", source, "describe", "--tags", "--always"], capture_output=True, text=True
    ).stdout.strip() or os.path.basename(os.path.normpath(source))
    work = tempfile.mkdtemp(prefix="ona-build-")
    shutil.copytree(os.path.join(source, "src"), os.path.join(work, "src"))
    shutil.copy(os.path.join(source, "build.sh"), work)
    print(f"building ONA {version} from {source} ...", flush=True)
    done = subprocess.run(["sh", "build.sh"], cwd=work, capture_output=True, text=True)
    binary = os.path.join(work, "NAR")
    if done.returncode != 0 or not os.path.isfile(binary):
        tail = (done.stderr or done.stdout).strip().splitlines()[-5:]
        raise SystemExit("ONA did not build:\n" + "\n".join(tail))
    return binary, version


def engine() -> str:
    """Which NARS engine ``robocog nar`` runs here (compiled, or pure Python and why)."""
    out = subprocess.run(
        [sys.executable, "-c", "import robocog.nars as n; print(n.ENGINE)"],
        capture_output=True,
        text=True,
    )
    return out.stdout.strip() or out.stderr.strip().splitlines()[-1]


def answers(out: str, questions: list[str]) -> int:
    """Questions for which some ``Answer:`` line gave a belief (at once or later)."""
    found = {
        line.split(". ", 1)[0][len("Answer: ") :]
        for line in out.splitlines()
        if line.startswith("Answer:") and "None" not in line
    }
    return sum(1 for q in questions if q[:-1] in found)


def random_line(rng: random.Random, names: int) -> str:
    """One line of a random stream: beliefs, events, goals, questions, junk, cycles."""
    k = rng.random()

    def n() -> str:
        return f"n{rng.randrange(names)}"

    if k < 0.35:
        return f"<{n()} --> {n()}>. %{rng.random():.2f}%"
    if k < 0.6:
        return f"<{n()} --> [{n()}]>. :|:"
    if k < 0.65:
        return f"<({{SELF}} * {n()}) --> ^go>. :|:"
    if k < 0.7:
        return f"<(<{n()} --> [on]> &/ ^go) =/> <{n()} --> [on]>>."
    if k < 0.75:
        return f"<{n()} --> [on]>! :|:"
    if k < 0.8:
        return f"<{n()} --> ?1>?"
    if k < 0.9:
        return rng.choice(["<a -->", "((x)", "<a --> b>. {9 9}", "%%%", "<<a --> b>", "*nope"])
    return str(rng.randrange(3))


def stream(count: int, seed: int, capacity: int) -> int:
    """Feed ``count`` random lines in this process; report memory and cycle-time bounds."""
    import gc
    import resource
    import statistics

    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "src"))
    from robocog.nars import ENGINE, NAR, NarseseError

    print(f"robocog NARS engine: {ENGINE}")

    gc.set_threshold(1_000_000, 20, 100)  # as ``robocog nar`` does (see there)
    rng = random.Random(seed)
    nar = NAR(seed=seed, **({"concepts_max": capacity} if capacity else {}))
    window = min(10_000, max(1, count // 10))
    first: list[float] = []
    last: list[float] = []
    errors = 0
    biggest = 0
    t0 = time.perf_counter()
    for i in range(count):
        line = random_line(rng, 100_000)
        t = time.perf_counter()
        try:
            nar.add_input(line)
        except NarseseError:
            errors += 1
        dt = time.perf_counter() - t
        if i < window:
            first.append(dt)
        elif i >= count - window:
            last.append(dt)
        biggest = max(biggest, len(nar.memory))
        if (i + 1) % max(1, count // 10) == 0:
            rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
            print(
                f"{i + 1:>9} lines  {len(nar.memory):>5} concepts  peak RSS {rss:.0f} MB",
                flush=True,
            )

    def p99(xs: list[float]) -> float:
        return statistics.quantiles(xs, n=100)[98] * 1000 if len(xs) >= 100 else max(xs) * 1000

    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"lines {count}, rejected {errors}, wall {time.perf_counter() - t0:.1f} s")
    print(f"concepts max {biggest} (capacity {nar.memory.capacity}), peak RSS {rss:.0f} MB")
    print(
        f"p99 time per line: first {window} {p99(first):.2f} ms, last {window} {p99(last or first):.2f} ms"
    )
    return 0 if biggest <= nar.memory.capacity else 1


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--statements", type=int, default=1000)
    ap.add_argument("--questions", type=int, default=100)
    ap.add_argument("--depth", type=int, default=2, help="links between asked node and answer")
    ap.add_argument("--capacity", type=int, default=0, help="robocog concepts_max (0: default)")
    ap.add_argument("--cycles", type=int, default=0, help="extra cycles before the questions")
    ap.add_argument("--think", type=int, default=0, help="cycles after each question")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=600.0)
    ap.add_argument("--no-ona", action="store_true", help="run robocog only")
    ap.add_argument("--stream", type=int, default=0, help="random-stream run of N lines instead")
    ap.add_argument("--ona-source", help="also build and run ONA from this source checkout")
    ap.add_argument(
        "--modes",
        default=",".join(ONA_MODES),
        help="robocog's ONA versions to run (`robocog nar --ona V`), comma-separated "
        "(default: %(default)s; 0.9.3 is the shell's default); a version may carry "
        "parameters after a colon, `0.9.3:declarative_pass_disjoint_evidence=true`, "
        "given to that run as `--set`",
    )
    args = ap.parse_args(argv)
    args.modes = [m.strip() for m in args.modes.split(",") if m.strip()]
    for m in args.modes:
        if m.split(":")[0] not in ONA_MODES:
            ap.error(f"--modes: {m!r} is not one of {', '.join(ONA_MODES)}")
    if args.stream:
        return stream(args.stream, args.seed, args.capacity)

    statements, questions = taxonomy(args.statements, args.questions, args.depth, args.seed)
    lines = ["*volume=0", *statements]
    if args.cycles:
        lines.append(str(args.cycles))
    for q in questions:
        lines += [q, str(args.think)] if args.think else [q]
    text = "\n".join(lines) + "\n"

    rows = []
    marked: list[str] = []  # the legend of the runs given parameters
    for mode in args.modes:
        version, *settings = mode.split(":")
        ours = [sys.executable, "-m", "robocog", "nar", "--quiet", "--ona", version]
        for setting in settings:
            ours += ["--set", setting]
        if args.capacity:
            ours += ["--set", f"concepts_max={args.capacity}"]
        w, cpu, rss, out = run(ours, text, args.timeout)
        if settings:
            marked.append(f"{'*' * (len(marked) + 1)} --set {' --set '.join(settings)}")
            version += "*" * len(marked)
        rows.append((f"robocog {version}", w, cpu, rss, answers(out, questions)))
    ona = shutil.which("NAR")
    if ona and not args.no_ona:
        w, cpu, rss, out = run([ona, "shell"], text, args.timeout)
        rows.append(("ONA 0.9.2", w, cpu, rss, answers(out, questions)))
    if args.ona_source:
        binary, version = build_ona(os.path.expanduser(args.ona_source))
        w, cpu, rss, out = run([binary, "shell"], text, args.timeout)
        rows.append((f"ONA {version}", w, cpu, rss, answers(out, questions)))

    print(f"robocog NARS engine: {engine()}")
    print(
        f"taxonomy: {args.statements} links, {len(questions)} questions {args.depth} links deep"
        + (f", robocog concepts_max={args.capacity}" if args.capacity else "")
        + f"; timeout {args.timeout:.0f} s"
    )
    print(f"{'system':<16} {'wall s':>8} {'CPU s':>8} {'RSS MB':>8} {'answered':>9}")
    for name, w, cpu, rss, n in rows:
        print(f"{name:<16} {w:8.2f} {cpu:8.2f} {rss:8.1f} {n:5d}/{len(questions)}")
    for line in marked:
        print(line)
    ours_rows = [r for r in rows if r[0].startswith("robocog")]
    for peer in rows:
        for mine in ours_rows:
            if peer is mine or (peer[0].startswith("robocog") and peer[0] <= mine[0]):
                continue
            print(
                f"ratio {peer[0]} / {mine[0]}: wall {peer[1] / mine[1]:.2f}, "
                f"CPU {peer[2] / mine[2]:.2f} (above 1: {mine[0]} faster)"
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
