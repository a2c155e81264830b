"""Run the example projects of a Jason checkout on robocog (and on Jason) and compare them.

Jason's repository (jason-lang/jason) ships example multi-agent systems in ``examples/`` and
``demos/``. This script takes a checkout the user already has (a folder, or a git dir and a
ref; nothing is downloaded and nothing of Jason is kept), copies those two folders into a
temporary directory, and for every ``.mas2j`` project found there:

* classifies it: *Java-free*, or *needs Java* (the project names an environment, agent
  architecture, agent class, belief base class or directive written in Java, or its
  programs call internal actions whose Java source sits in the project);
* runs it on ``robocog agent`` (with a timeout), and, when a built Jason is given
  (``jason-agent`` from ``build-jason.sh``), on Jason several times;
* compares the ``[agent] text`` lines per agent, as Jason's agents run in parallel: for
  every agent Jason printed something for, robocog must print the same sequence. A
  project matches when robocog's output equals the output of any one of Jason's runs.

What varies from run to run in Jason itself is compared as a placeholder:

* everywhere: Jason's counters in fresh variable names (``_71``, ``_71X``) and generated
  plan labels (``p__4``, ``l__12``);
* per project (``NORMALIZE``, ``UNORDERED``, ``DROP`` and ``DISTINCT`` below, each with
  its reason): the random bids of the contract-net projects and the order in which the
  bids arrive, the order messages from several agents arrive in, Santa's groups (who is
  in them depends on Jason's threads), the milliseconds of the search demo;
* a difference explained in docs/bdi.md (``KNOWN``) is reported as such;
* Jason runs without the project's own ``logging.properties`` (some send the output to a
  window or print it without the agent's name), so that every line says its agent;
* a project that never ends (Jason's run was cut at its time limit) is compared on the
  lines Jason printed, which robocog's must begin with; when robocog too was stopped at
  its time limit, the shorter of the two per agent must begin the other.

A Java-needing project is expected to stop at once with an error that names the Java part
(robocog runs no Java); the table says whether it does, hangs or exits silently.

Usage::

    python tools/jason_examples.py --source PATH_TO_JASON_CHECKOUT
    python tools/jason_examples.py --git /path/to/jason.git --ref HEAD \\
        --jason ~/.cache/robocog-peers/jason/jason-agent --runs 3 --json out.json

Exit status 0 when it ran (whatever the results), 2 on a bad argument.
"""

from __future__ import annotations

import argparse
import json
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

#: Jason's counters, compared as placeholders (fresh variables, generated plan labels)
COUNTERS = [
    (re.compile(r"(?<![A-Za-z0-9])_\d+(?=[A-Za-z0-9_]*)"), "_#"),
    (re.compile(r"\b([pl])__\d+\b"), r"\1__#"),
]
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")

#: the contract-net projects' random bids, masked (the three variants print alike)
CNP_BIDS: list[tuple[str, str]] = [
    (r"Sending CFP to \[.*\]", "Sending CFP to <participants>"),
    (r"\[offer\(.*\)\]", "[offers]"),
    (r"Winner is \w+ with \S+", "Winner is <who> with <bid>"),
    (r"My proposal '[^']*' won CNP (\d+)", r"<won or lost> CNP \1"),
    (r"I lost CNP (\d+)\.", r"<won or lost> CNP \1"),
    (r" for [a-z(),]+!$", ""),
]

#: per project, how its lines are made comparable (regex, replacement) and why
NORMALIZE: dict[str, tuple[str, list[tuple[str, str]]]] = {
    "examples/contract-net-protocol": (
        "random bids: the amounts, the winner and the order of the offers vary in Jason; "
        "the order of the participants the directory gives depends on the order Jason's "
        "threads registered them",
        CNP_BIDS,
    ),
    "examples/contract-net-protocol-er": (
        "random bids, as in contract-net-protocol: the bids, the winners and the order of "
        "the directory's answer are masked, and the winner's 'Doing my task' and 'Done!' "
        "lines dropped (who prints them depends on the bids)",
        [*CNP_BIDS, (r"Winner for (.*) is \w+ with \S+", r"Winner for \1 is <who> with <bid>")],
    ),
    "examples/contract-net-protocol-module": (
        "random bids, as in contract-net-protocol: the bids, who wins each CNP and the "
        "order of the participants the directory gives are masked",
        [
            *CNP_BIDS,
            (r"Sending CFP for (\S+) to \[.*\]", r"Sending CFP for \1 to <participants>"),
            (r"Proposing [\d.]+ for", "Proposing <bid> for"),
            (r"Winner to fix (\w+) is \w+", r"Winner to fix \1 is <who>"),
            (r"^My proposal in (\w+) for task (.*) won!$", r"<won or lost> CNP in \1 for \2"),
            (r"^I lost CNP in (\w+) for task (.*)\.$", r"<won or lost> CNP in \1 for \2"),
        ],
    ),
    "demos/current-intention": (
        "each goal waits a random time (math.random), so which intention is inspected "
        "when, its number, the wait times and the order of the other goals vary in Jason: "
        "the goals' letters, the numbers and the times are masked, and each agent's "
        "distinct lines compared",
        [
            (r"\b(inspect|start)\([a-d]\)", r"\1(<x>)"),
            (r"terms are \[[a-d]\]", "terms are [<x>]"),
            (r"^[a-d]$", "<x>"),
            (r"number is \d+", "number is <n>"),
            (r"wait\(\d+\)\[time\(\d+\)\]", "wait(<n>)[time(<ms>)]"),
        ],
    ),
    "demos/search": ("the time the searches take (milliseconds)", [(r"\d+ ?ms", "<ms> ms")]),
    "examples/st-claus": (
        "which workers make up each group, which kind Santa serves next and when a group "
        "must wait depend on thread timing in Jason: the groups and kinds are masked, "
        "the 'waiting to proceed' lines dropped, and each agent's distinct lines compared",
        [(r"\[[^\]]*\]", "[group]"), (r"\b(elf|reindeer)s\b", "<kind>s")],
    ),
}

#: per project, lines left out of the comparison (regex), for the reason NORMALIZE gives
DROP: dict[str, str] = {
    "examples/st-claus": r"waiting to proceed",
    "examples/contract-net-protocol-er": r"^(Doing my task|Done!)",
}

#: projects compared on the distinct lines of each agent (for the reason NORMALIZE gives)
DISTINCT = {"examples/st-claus", "demos/current-intention"}

#: differences found and explained (docs/bdi.md): the project's state says so
KNOWN: dict[str, str] = {
    "demos/hard_deadline": "Jason 3.3 stops the g(9) intention with a NullPointerException "
    "(TransitionSystem.getPLForIM) and never prints the demo's expected last line "
    "'failed, deadline_reached for g(9)'; robocog prints it",
}

#: projects whose lines are compared as a set per agent (their order depends on threads)
UNORDERED: dict[str, str] = {
    "demos/distributed-jade/case1": "the hellos of b and c1..c3 reach a in any order",
    "examples/contract-net-protocol": "the offers arrive in any order",
    "examples/contract-net-protocol-er": "the offers arrive in any order",
    "examples/contract-net-protocol-module": "the offers arrive in any order",
}

LINE = re.compile(r"^\[([^\]]+)\] ?(.*)$")
_CLASS_SECTIONS = re.compile(
    r"\b(environment|agentArchClass|agentClass|beliefBaseClass|executionControl)\s*:?\s*"
    r"([A-Za-z_][\w.]*)"
)
_DIRECTIVES = re.compile(r"\bdirectives\s*:\s*([^;}]*)")
_IA_CALL = re.compile(r"(?<![\w.\"])([a-z]\w*(?:\.[a-z]\w*)+)\b(?!\")")


@dataclass
class Result:
    """One project: its class, what robocog did, and how it compares with Jason."""

    name: str
    project: str
    java: list[str] = field(default_factory=list)
    state: str = ""
    detail: str = ""
    robocog_seconds: float = 0.0
    robocog_exit: int | None = None
    robocog_lines: int = 0
    jason_runs: int = 0
    jason_lines: list[int] = field(default_factory=list)
    handling: str = ""


def extract(source: Path | None, git_dir: Path | None, ref: str, into: Path) -> None:
    """Copy ``examples/`` and ``demos/`` of a checkout (or of ``ref`` in a git dir)."""
    if source is not None:
        for part in ("examples", "demos"):
            if (source / part).is_dir():
                shutil.copytree(source / part, into / part)
        return
    archive = subprocess.run(
        ["git", "--git-dir", str(git_dir), "archive", ref, "examples", "demos"],
        capture_output=True,
        check=False,
    )
    if archive.returncode != 0:
        msg = archive.stderr.decode("utf-8", "replace").strip().splitlines()
        raise SystemExit(f"jason_examples: git archive failed: {msg[-1] if msg else ''}")
    subprocess.run(["tar", "-x", "-C", str(into)], input=archive.stdout, check=True)


def projects(root: Path) -> list[tuple[str, Path]]:
    """Every ``.mas2j`` under ``examples/`` and ``demos/``, named by its folder."""
    out = []
    for mas in sorted(root.glob("*/**/*.mas2j")):
        name = str(mas.parent.relative_to(root))
        if sum(1 for _ in mas.parent.glob("*.mas2j")) > 1:
            name += "/" + mas.stem
        out.append((name, mas))
    return out


def _strip_comments(text: str) -> str:
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def java_parts(mas2j: Path) -> list[str]:
    """The Java a project needs: classes its ``.mas2j`` names (outside ``jason.``) and
    internal actions its programs call whose ``.java`` is in the project."""
    text = _strip_comments(mas2j.read_text(encoding="utf-8", errors="replace"))
    parts = []
    for kind, cls in _CLASS_SECTIONS.findall(text):
        if not cls.startswith("jason."):
            parts.append(f"{kind} {cls}")
    for cls in re.findall(r'container_allocation\s*\(\s*"([\w.]+)"', text):
        parts.append(f"agent allocator {cls}")
    for m in _DIRECTIVES.finditer(text):
        for d in m.group(1).split(";"):
            if "=" in d:
                parts.append(f"directive {d.split('=', 1)[1].strip()}")
    folder = mas2j.parent
    javas = {
        str(p.relative_to(folder).with_suffix("")).replace("/", ".") for p in folder.rglob("*.java")
    }
    suffixes = {j.split(".", 1)[1] if j.startswith("src.") else j for j in javas}
    for asl in sorted(folder.rglob("*.asl")):
        code = _strip_comments(asl.read_text(encoding="utf-8", errors="replace"))
        for ia in sorted(set(_IA_CALL.findall(code))):
            if ia in javas or ia in suffixes or any(j.endswith("." + ia) for j in javas):
                parts.append(f"internal action {ia}")
    return sorted(set(parts))


def split(text: str) -> dict[str, list[str]]:
    """``[agent] text`` lines per agent (a bracket that cannot be an agent's name, such
    as Jason's ``[RunLocalMAS]`` or ``[TextPersistentBB]``, is not an agent's line)."""
    per: dict[str, list[str]] = {}
    for ln in text.splitlines():
        m = LINE.match(ln.rstrip())
        if m and m.group(1)[:1].islower():
            per.setdefault(m.group(1), []).append(m.group(2).rstrip())
    return per


def normalize(name: str, line: str) -> str:
    """A line with Jason's counters and the project's varying values as placeholders."""
    for rx, rep in COUNTERS:
        line = rx.sub(rep, line)
    for rx, rep in NORMALIZE.get(name, ("", []))[1]:
        line = re.sub(rx, rep, line)
    return line


def compare(name: str, jason: str, robocog: str, cut: bool, robocog_cut: bool) -> str | None:
    """None when robocog's output matches this Jason run, else the first difference.

    ``cut``: Jason's run was stopped at its time limit; then robocog's lines must begin
    with Jason's, or, when robocog was stopped at its own limit too, the shorter of the
    two must begin the other."""
    drop = re.compile(DROP[name]) if name in DROP else None

    def norm(lines: list[str]) -> list[str]:
        out = [normalize(name, x) for x in lines if drop is None or not drop.search(x)]
        return sorted(set(out)) if name in DISTINCT else out

    exp = {a: norm(ls) for a, ls in split(jason).items()}
    got = {a: norm(ls) for a, ls in split(robocog).items()}
    exp.pop("RunLocalMAS", None)
    for ag in sorted(exp):
        e, g = exp[ag], got.get(ag, [])
        if name in UNORDERED:
            e, g = sorted(e), sorted(g)
        if cut:
            n = min(len(e), len(g)) if robocog_cut else len(e)
            if n == 0 and e:
                return f"[{ag}] no lines"
            e, g = e[:n], g[:n]
        if e != g:
            for i in range(max(len(e), len(g))):
                a = e[i] if i < len(e) else "<end>"
                b = g[i] if i < len(g) else "<end>"
                if a != b:
                    return f"[{ag}] line {i + 1}: Jason {a[:70]!r}, robocog {b[:70]!r}"
    return None


def run(cmd: list[str], cwd: Path, timeout: float) -> tuple[str, str, int | None, float]:
    """stdout, stderr, exit status (None on timeout) and seconds of one command."""
    t0 = time.monotonic()
    try:
        p = subprocess.run(
            cmd, cwd=cwd, capture_output=True, stdin=subprocess.DEVNULL, timeout=timeout
        )
        out, err, rc = p.stdout, p.stderr, p.returncode
    except subprocess.TimeoutExpired as exc:
        out, err, rc = exc.stdout or b"", exc.stderr or b"", None
    dec = "utf-8", "replace"
    return out.decode(*dec), err.decode(*dec), rc, time.monotonic() - t0


def check(
    name: str, mas: Path, args: argparse.Namespace, cache: Path | None
) -> tuple[Result, dict]:
    """Run one project on robocog (and Jason) and classify the outcome."""
    res = Result(name, str(mas.name), java_parts(mas))
    handling = []
    if name in NORMALIZE:
        handling.append(NORMALIZE[name][0])
    if name in UNORDERED:
        handling.append(UNORDERED[name])
    if name in KNOWN:
        handling.append("known difference: " + KNOWN[name])
    cmd = [*shlex.split(args.robocog), "--timeout", str(args.timeout), mas.name]
    out, err, rc, secs = run(cmd, mas.parent, args.timeout + 10)
    res.robocog_seconds, res.robocog_exit = round(secs, 2), rc
    res.robocog_lines = sum(len(v) for v in split(out).values())
    first_err = next((ln for ln in err.splitlines() if ln.strip()), "")
    raw = {"robocog": {"stdout": out[-20000:], "stderr": err[-4000:], "exit": rc}}
    if res.java:
        if rc is None or rc == 3:
            res.state, res.detail = "java: hangs", first_err
        elif rc != 0 and any(p.split()[-1] in err for p in res.java):
            res.state, res.detail = "java: clear error", first_err
        elif rc != 0:
            res.state, res.detail = "java: other error", first_err
        else:
            res.state, res.detail = "java: runs", f"{res.robocog_lines} lines"
        return res, raw
    if rc not in (0, 3) and rc is not None:
        res.state, res.detail = "robocog error", first_err
        return res, raw
    jason_outs = []
    if args.jason:
        # a project's own logging.properties may send Jason's output to a window or
        # drop the agent names; Jason's default console format is the one compared
        (mas.parent / "logging.properties").unlink(missing_ok=True)
        for k in range(args.runs):
            hit = cache / f"{name.replace('/', '+')}.{k}.txt" if cache else None
            if hit is not None and hit.is_file():
                jason_outs.append(json.loads(hit.read_text(encoding="utf-8")))
                continue
            jcmd = [args.jason, str(mas)]
            jout, _jerr, _jrc, jsecs = run(jcmd, mas.parent, args.jason_max / 1000 + 30)
            rec = {"stdout": jout, "seconds": round(jsecs, 2)}
            jason_outs.append(rec)
            if hit is not None:
                hit.write_text(json.dumps(rec), encoding="utf-8")
    raw["jason"] = [{"stdout": j["stdout"][-20000:], "seconds": j["seconds"]} for j in jason_outs]
    res.jason_runs = len(jason_outs)
    res.jason_lines = [sum(len(v) for v in split(j["stdout"]).values()) for j in jason_outs]
    if not jason_outs:
        res.state = "ran" if rc == 0 else "timeout"
        res.detail = f"{res.robocog_lines} lines" + (" (timeout)" if rc == 3 else "")
        res.handling = "; ".join(handling)
        return res, raw
    diffs = []
    for j in jason_outs:
        cut = j["seconds"] >= args.jason_max / 1000 - 0.5
        if cut and "never ends: compared on the lines both printed" not in handling:
            handling.append("never ends: compared on the lines both printed")
        d = compare(name, j["stdout"], out, cut, rc == 3)
        if d is None:
            diffs = []
            break
        diffs.append(d)
    res.handling = "; ".join(handling)
    if diffs:
        res.state = "differs (known)" if name in KNOWN else "differs"
        res.detail = diffs[0]
    else:
        res.state, res.detail = "matches", f"{res.robocog_lines} lines"
    return res, raw


def table(results: list[Result]) -> None:
    """Print the results as a table (rich when it is installed)."""
    try:
        from rich.console import Console
        from rich.table import Table
    except ImportError:
        for r in results:
            print(f"{r.name:42} {r.state:18} {r.detail[:80]}")
        return
    t = Table(title="Jason's examples on robocog")
    for col in ("project", "Java", "state", "detail"):
        t.add_column(col, overflow="fold")
    for r in results:
        java = r.java[0] + (f" (+{len(r.java) - 1})" if len(r.java) > 1 else "") if r.java else "-"
        t.add_row(r.name, java, r.state, r.detail[:160])
    Console(width=max(100, shutil.get_terminal_size().columns)).print(t)


def main(argv: list[str] | None = None) -> int:
    """Extract, run, compare, print the table and write the JSON."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--source", type=Path, help="a Jason checkout (a folder)")
    src.add_argument("--git", type=Path, help="a git dir of jason-lang/jason")
    ap.add_argument("--ref", default="HEAD", help="the ref to extract from --git (HEAD)")
    ap.add_argument("--jason", help="Jason's launcher (jason-agent made by build-jason.sh)")
    ap.add_argument("--runs", type=int, default=3, help="Jason runs per project (3)")
    ap.add_argument("--jason-max", type=int, default=20000, help="Jason's run cap in ms (20000)")
    ap.add_argument("--jason-cache", type=Path, help="a folder keeping Jason's outputs")
    ap.add_argument("--robocog", default="robocog agent", help="the robocog command")
    ap.add_argument("--timeout", type=float, default=15.0, help="seconds per robocog run (15)")
    ap.add_argument("--only", nargs="*", default=[], help="project names (or parts of them)")
    ap.add_argument("--java-free", action="store_true", help="only the Java-free projects")
    ap.add_argument("--json", type=Path, help="write the results here")
    args = ap.parse_args(argv)
    if args.source is not None and not (args.source / "examples").is_dir():
        print(f"jason_examples: {args.source} has no examples/ folder", file=sys.stderr)
        return 2
    if args.git is not None and not args.git.is_dir():
        print(f"jason_examples: {args.git}: no such git dir", file=sys.stderr)
        return 2
    if args.jason and not Path(args.jason).is_file():
        print(f"jason_examples: {args.jason}: no such launcher", file=sys.stderr)
        return 2
    if not 1 <= args.runs <= 20 or not 0 < args.timeout <= 3600:
        print("jason_examples: --runs 1..20 and --timeout 0..3600", file=sys.stderr)
        return 2
    if args.jason_cache is not None:
        args.jason_cache.mkdir(parents=True, exist_ok=True)
    results, raws = [], {}
    with tempfile.TemporaryDirectory(prefix="jason-examples.") as tmp:
        root = Path(tmp)
        extract(args.source, args.git, args.ref, root)
        for name, mas in projects(root):
            if args.only and not any(o in name for o in args.only):
                continue
            if args.java_free and java_parts(mas):
                continue
            res, raw = check(name, mas, args, args.jason_cache)
            results.append(res)
            raws[name] = raw
            print(f"{name}: {res.state} {res.detail[:100]}", file=sys.stderr, flush=True)
    table(results)
    free = [r for r in results if not r.java]
    matched = sum(r.state == "matches" for r in free)
    java = [r for r in results if r.java]
    clear = sum(r.state in ("java: clear error", "java: runs") for r in java)
    print(f"Java-free: {matched}/{len(free)} match; needing Java: {clear}/{len(java)} stop clearly")
    if args.json is not None:
        doc = {"results": [asdict(r) for r in results], "outputs": raws}
        args.json.write_text(json.dumps(doc, indent=1), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
