"""robocog's AtomSpace against hyperon (OpenCog Hyperon's GroundingSpace) on the same facts.

Both stores get the same 10,000 facts: 7,500 ``on(X, Y)`` and 2,500 ``clear(X)`` over
3,000 blocks, from one seed. Each then answers the same 1,000 queries of four kinds:

- ``first``:  on(B, ?y)                  first argument bound
- ``second``: on(?x, B)                  second argument bound
- ``join-first``: on(B, ?y), on(?y, ?z)  two clauses joined, bound at the first end
- ``join-last``:  on(?x, ?y), on(?y, B)  two clauses joined, bound at the last end

robocog answers through ``query()`` (a list of {variable: atom}) and through GetLink
execution (the SetLink of answers built and added to the space, as ``cog-execute!`` does); hyperon through ``GroundingSpace.query`` (a BindingsSet, read out to a list).
"cold" rounds empty every matcher cache first; these four query shapes take the fast
path (``query`` itself and robocog.atomspace.fastpath), which reads the pattern as it
stands and compiles nothing, so cold and compiled agree.
Patterns are built before the clock starts, on both sides, and the answer counts are
compared so that both did the same work. Hyperon's index cannot hold more than about
1,024 distinct symbols, so there a block is the expression ``(b H L)`` over 100 digit
symbols; in robocog it is the ConceptNode ``"bH_L"``.

Two kinds of query hyperon has no counterpart for follow, robocog alone, through the
general matcher (the fast paths leave them to it):

- ``choice``: on(ChoiceLink(B, C), ?y)  either of two blocks in the first place
- ``glob``:   (ListLink B <glob>) over 3,000 lists of 2-4 blocks: every run after B

Then the load time and memory of 10^6 atoms in robocog: built from Python, read from
Atomese text, and loaded from SQLite (resident memory measured from /proc).

    python benchmarks/atomspace.py                 # everything
    python benchmarks/atomspace.py --queries 200 --no-million
    python benchmarks/atomspace.py --no-million --opencog ~/.cache/robocog-peers/opencog/install

``--opencog PREFIX`` adds the real OpenCog AtomSpace of 2021 as a peer (built by
``../shared/tools/opencog/build-opencog.sh``; not part of CI): the same facts and the
same queries as GetLinks run by ``cog-execute!`` in its Guile, timed inside Guile with
its CPU clock (the queries built before the clock starts), best of three rounds,
against robocog's GetLink execution.
"""

from __future__ import annotations

import argparse
import gc
import os
import random
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable

from robocog.atomspace import AtomSpace, Link, Node, matcher, query
from robocog.atomspace.atoms import bulk
from robocog.atomspace.persist import load, store

KINDS = ("first", "second", "join-first", "join-last")


def facts(seed: int, blocks: int = 3000, on: int = 7500, clear: int = 2500):
    """(block names, on pairs, clear blocks), distinct, from the seed."""
    rng = random.Random(seed)
    names = [(i // 100, i % 100) for i in range(blocks)]
    pairs: set[tuple[int, int]] = set()
    while len(pairs) < on:
        x, y = rng.randrange(blocks), rng.randrange(blocks)
        if x != y:
            pairs.add((x, y))
    clears = rng.sample(range(blocks), clear)
    return names, sorted(pairs), clears


def workload(seed: int, blocks: int, n: int) -> dict[str, list[int]]:
    """The bound block of each query, per kind."""
    rng = random.Random(seed + 1)
    return {k: [rng.randrange(blocks) for _ in range(n)] for k in KINDS}


# ---------------------------------------------------------------------- the two sides
def best_of(
    fns: dict[str, Callable[[], int]], rounds: int, budget: float = 3.0
) -> dict[str, tuple[float, int]]:
    """Per name, (smallest CPU seconds of a round, answers). The machine is shared, so
    each side is timed in up to ``rounds`` rounds and its fastest round is kept; the
    sides take turns round by round, so that they meet the same load, and a side stops
    early once its rounds have taken ``budget`` seconds (hyperon's slow kinds). Every
    side is timed the same way, with Python's cyclic collector paused as ``timeit``
    does."""
    best = dict.fromkeys(fns, float("inf"))
    count = dict.fromkeys(fns, 0)
    spent = dict.fromkeys(fns, 0.0)
    for _ in range(rounds):
        for name, fn in fns.items():
            if spent[name] > budget:
                continue
            gc.collect()
            gc.disable()  # as timeit does: the collector's pauses are not the queries' work
            try:
                t0 = time.process_time()
                count[name] = fn()
                took = time.process_time() - t0
            finally:
                gc.enable()
            best[name] = min(best[name], took)
            spent[name] += took
    return {name: (best[name], count[name]) for name in fns}


def robocog_side(names, pairs, clears):  # noqa: ANN001, ANN201
    """Load the facts into an AtomSpace; return (load seconds, space, pattern makers)."""
    space = AtomSpace()
    on, clear = Node("PredicateNode", "on"), Node("PredicateNode", "clear")
    concepts = [Node("ConceptNode", f"b{h}_{lo}") for h, lo in names]
    t0 = time.process_time()
    for x, y in pairs:
        space.add(Link("EvaluationLink", on, Link("ListLink", concepts[x], concepts[y])))
    for x in clears:
        space.add(Link("EvaluationLink", clear, concepts[x]))
    load_s = time.process_time() - t0
    X, Y, Z = (Node("VariableNode", v) for v in ("$x", "$y", "$z"))

    def on_(a, b):  # noqa: ANN001, ANN202
        return Link("EvaluationLink", on, Link("ListLink", a, b))

    make: dict[str, Callable] = {
        "first": lambda b: on_(concepts[b], Y),
        "second": lambda b: on_(X, concepts[b]),
        "join-first": lambda b: Link("AndLink", on_(concepts[b], Y), on_(Y, Z)),
        "join-last": lambda b: Link("AndLink", on_(X, Y), on_(Y, concepts[b])),
    }
    return load_s, space, make


def hyperon_side(names, pairs, clears):  # noqa: ANN001, ANN201
    """Load the facts into a GroundingSpace; return (load seconds, space, pattern makers)."""
    from hyperon import E, GroundingSpaceRef, S, V

    space = GroundingSpaceRef()
    on, clear, b = S("on"), S("clear"), S("b")
    digits = [S(str(i)) for i in range(100)]
    blocks = [E(b, digits[h], digits[lo]) for h, lo in names]
    t0 = time.process_time()
    for x, y in pairs:
        space.add_atom(E(on, blocks[x], blocks[y]))
    for x in clears:
        space.add_atom(E(clear, blocks[x]))
    load_s = time.process_time() - t0
    X, Y, Z = V("x"), V("y"), V("z")
    comma = S(",")
    make: dict[str, Callable] = {
        "first": lambda k: E(on, blocks[k], Y),
        "second": lambda k: E(on, X, blocks[k]),
        "join-first": lambda k: E(comma, E(on, blocks[k], Y), E(on, Y, Z)),
        "join-last": lambda k: E(comma, E(on, X, Y), E(on, Y, blocks[k])),
    }
    return load_s, space, make


def _forget() -> None:
    """Empty every cache of the matcher (compiled patterns and clauses, the fast path's
    table of relation types), so that each query of a "cold" round starts from its atom."""
    matcher.clear_caches()


def compare(names, pairs, clears, work, rounds: int, with_hyperon: bool):  # noqa: ANN001, ANN201
    """Per kind: robocog (cold compile, warm compile, GetLink) and hyperon CPU seconds."""
    r_load, r_space, r_make = robocog_side(names, pairs, clears)
    h = hyperon_side(names, pairs, clears) if with_hyperon else None
    rows = {"load": (r_load, h[0] if h else None, len(r_space))}
    for kind in KINDS:
        pats = [r_make[kind](b) for b in work[kind]]
        gets = [Link("GetLink", p) for p in pats]

        def cold(pats: list = pats) -> int:
            _forget()
            return sum(len(query(r_space, p)) for p in pats)

        def warm(pats: list = pats) -> int:
            return sum(len(query(r_space, p)) for p in pats)

        def getlink(gets: list = gets) -> int:
            _forget()
            return sum(len(r_space.execute(g).out) for g in gets)

        fns: dict[str, Callable[[], int]] = {"cold": cold, "warm": warm, "get": getlink}
        for fn in fns.values():
            # one untimed round first: a fresh process's first queries run up to twice
            # slower here, and the GetLinks' first round adds their SetLinks
            fn()
        if h is not None:
            hp = [h[2][kind](b) for b in work[kind]]

            def theirs(hs=h[1], hp: list = hp) -> int:  # noqa: ANN001
                return sum(len(list(hs.query(p).iterator())) for p in hp)

            fns["hyperon"] = theirs
        rows[kind] = best_of(fns, rounds)
    return rows


def robocog_only(names, pairs, work, rounds: int) -> dict[str, tuple[float, int]]:  # noqa: ANN001
    """CPU seconds (best round) and answers of the ChoiceLink and GlobNode queries."""
    space = AtomSpace()
    on = Node("PredicateNode", "on")
    concepts = [Node("ConceptNode", f"b{h}_{lo}") for h, lo in names]
    for x, y in pairs:
        space.add(Link("EvaluationLink", on, Link("ListLink", concepts[x], concepts[y])))
    rng = random.Random(len(pairs))
    n = len(concepts)
    for i in range(n):  # lists of 2-4 blocks, each starting at its own block
        space.add(
            Link(
                "ListLink",
                concepts[i],
                *(concepts[rng.randrange(n)] for _ in range(rng.randrange(1, 4))),
            )
        )
    Y, G = Node("VariableNode", "$y"), Node("GlobNode", "$rest")
    firsts = work["first"]
    seconds = work["second"]
    choice = [
        Link(
            "EvaluationLink", on, Link("ListLink", Link("ChoiceLink", concepts[a], concepts[b]), Y)
        )
        for a, b in zip(firsts, seconds, strict=True)
    ]
    glob = [Link("ListLink", concepts[a], G) for a in firsts]
    fns = {
        "choice": lambda: sum(len(query(space, p)) for p in choice),
        "glob": lambda: sum(len(query(space, p)) for p in glob),
    }
    return best_of(fns, rounds)


def opencog_side(prefix: str, names, pairs, work, rounds: int = 3) -> dict[str, tuple[float, int]]:  # noqa: ANN001
    """CPU seconds (best round) and answers per kind of OpenCog's GetLink, in its Guile."""
    guile = os.path.join(prefix, "bin", "opencog-guile")
    if not os.access(guile, os.X_OK):
        raise SystemExit(f"--opencog: no {guile} (build it with build-opencog.sh)")

    def block(k: int) -> str:
        h, lo = names[k]
        return f'(ConceptNode "b{h}_{lo}")'

    def on(a: str, b: str) -> str:
        return f'(EvaluationLink (PredicateNode "on") (ListLink {a} {b}))'

    y, z, x = '(VariableNode "$y")', '(VariableNode "$z")', '(VariableNode "$x")'
    make = {
        "first": lambda k: on(block(k), y),
        "second": lambda k: on(x, block(k)),
        "join-first": lambda k: f"(AndLink {on(block(k), y)} {on(y, z)})",
        "join-last": lambda k: f"(AndLink {on(x, y)} {on(y, block(k))})",
    }
    lines = ["(use-modules (opencog) (opencog exec))"]
    lines += [on(block(a), block(b)) for a, b in pairs]
    for kind in KINDS:
        queries = " ".join(f"(GetLink {make[kind](k)})" for k in work[kind])
        lines.append(f"(define q-{kind} (list {queries}))")
    lines.append(
        "(define (run qs) (let ((t0 (get-internal-run-time)) (n 0))"
        " (for-each (lambda (q) (set! n (+ n (length (cog-outgoing-set (cog-execute! q)))))) qs)"
        " (list (- (get-internal-run-time) t0) n)))"
    )
    for kind in KINDS:
        for _ in range(rounds):
            lines.append(
                f'(let ((r (run q-{kind}))) (format #t "{kind} ~a ~a~%" (car r) (cadr r)))'
            )
    lines.append('(format #t "units ~a~%" internal-time-units-per-second)')
    with tempfile.NamedTemporaryFile("w", suffix=".scm", delete=False) as f:
        f.write("\n".join(lines) + "\n")
        script = f.name
    try:
        # not compiled first: Guile's compiler takes minutes over ten thousand facts
        done = subprocess.run(
            [guile, "--no-auto-compile", "-s", script],
            capture_output=True,
            text=True,
            timeout=3600,
        )
    finally:
        os.unlink(script)
    if done.returncode != 0:
        raise SystemExit("OpenCog's Guile failed: " + done.stderr.strip()[-500:])
    units = 1.0
    best: dict[str, tuple[float, int]] = {}
    rows = [ln.split() for ln in done.stdout.splitlines() if ln.strip()]
    for row in rows:
        if row[0] == "units":
            units = float(row[1])
    for row in rows:
        if row[0] in KINDS:
            secs, n = float(row[1]) / units, int(row[2])
            if row[0] not in best or secs < best[row[0]][0]:
                best[row[0]] = (secs, n)
    return best


# ---------------------------------------------------------------------- 10^6 atoms
def rss_mb() -> float:
    """Resident memory of this process in MB."""
    with open("/proc/self/statm") as f:
        pages = int(f.read().split()[1])
    return pages * os.sysconf("SC_PAGE_SIZE") / 1e6


def million(target: int = 1_000_000) -> list[tuple[str, float, float, int]]:
    """Build, read and load ``target`` atoms; (how, seconds, MB, atoms) rows."""
    # facts on(bi, bj): each adds an EvaluationLink and a ListLink; blocks are nodes
    nblocks = 20_000
    nfacts = (target - nblocks - 1) // 2
    rng = random.Random(7)
    pairs = set()
    while len(pairs) < nfacts:
        pairs.add((rng.randrange(nblocks), rng.randrange(nblocks)))
    pairs_l = sorted(pairs)
    rows = []

    gc.collect()
    m0 = rss_mb()
    t0 = time.perf_counter()
    space = AtomSpace()
    on = Node("PredicateNode", "on")
    concepts = [Node("ConceptNode", f"b{i}") for i in range(nblocks)]
    with bulk():
        for x, y in pairs_l:
            space.add(Link("EvaluationLink", on, Link("ListLink", concepts[x], concepts[y])))
    rows.append(("built from Python", time.perf_counter() - t0, rss_mb() - m0, len(space)))

    with tempfile.TemporaryDirectory() as tmp:
        db = os.path.join(tmp, "m.db")
        t0 = time.perf_counter()
        store(space, db)
        rows.append(("stored to SQLite", time.perf_counter() - t0, 0.0, len(space)))
        text = "\n".join(
            f'(EvaluationLink (PredicateNode "on") (ListLink (ConceptNode "b{x}") (ConceptNode "b{y}")))'
            for x, y in pairs_l
        )
        del space, concepts
        gc.collect()
        m0 = rss_mb()
        t0 = time.perf_counter()
        s2 = AtomSpace()
        s2.load_atomese(text)
        rows.append(("read from Atomese", time.perf_counter() - t0, rss_mb() - m0, len(s2)))
        del s2, text
        gc.collect()
        m0 = rss_mb()
        t0 = time.perf_counter()
        s3 = load(db)
        rows.append(("loaded from SQLite", time.perf_counter() - t0, rss_mb() - m0, len(s3)))
        del s3
    return rows


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seed", type=int, default=2021)
    ap.add_argument("--queries", type=int, default=1000)
    ap.add_argument(
        "--rounds", type=int, default=10, help="timed rounds per side, at most (best kept)"
    )
    ap.add_argument("--no-million", action="store_true", help="skip the 10^6-atom part")
    ap.add_argument("--no-hyperon", action="store_true", help="robocog only")
    ap.add_argument("--opencog", metavar="PREFIX", help="also OpenCog 2021, built at PREFIX")
    args = ap.parse_args(argv)

    names, pairs, clears = facts(args.seed)
    work = workload(args.seed, len(names), args.queries)
    with_h = not args.no_hyperon
    if with_h:
        try:
            import hyperon  # noqa: F401
        except ImportError:
            print("hyperon is not installed: robocog only", file=sys.stderr)
            with_h = False
    rows = compare(names, pairs, clears, work, args.rounds, with_h)
    q = args.queries
    print(
        f"facts: {len(pairs)} on, {len(clears)} clear over {len(names)} blocks; "
        f"{q} queries per kind; seed {args.seed}; CPU time, best of up to {args.rounds} "
        "rounds, the sides in turn (3 s per side and kind)"
    )
    r_load, h_load, n = rows["load"]
    print(
        f"load: robocog {r_load * 1e3:.1f} ms ({n} atoms)"
        + (f", hyperon {h_load * 1e3:.1f} ms" if h_load is not None else "")
    )
    print(f"{'query (us per query)':<24}{'robocog':>10}{'hyperon':>12}{'ratio':>8}{'answers':>9}")
    for kind in KINDS:
        row = rows[kind]
        hy = row.get("hyperon")
        for label, key in (
            (kind, "cold"),
            ("  pattern compiled", "warm"),
            ("  as GetLink", "get"),
        ):
            t, count = row[key]
            us = t / q * 1e6
            if hy:
                uh = hy[0] / q * 1e6
                same = "" if hy[1] == count else f" (hyperon: {hy[1]})"
                hcol = f"{uh:>12.1f}" if key == "cold" else f"{'':>12}"
                print(f"{label:<24}{us:>10.1f}{hcol}{uh / us:>7.1f}x{count:>9}{same}")
            else:
                print(f"{label:<24}{us:>10.1f}{'-':>12}{'-':>8}{count:>9}")

    if args.opencog:
        theirs = opencog_side(os.path.expanduser(args.opencog), names, pairs, work)
        print("against OpenCog's AtomSpace of 2021 (GetLink by cog-execute!, us per query):")
        for kind in KINDS:
            ours_t, ours_n = rows[kind]["get"]
            oc_t, oc_n = theirs[kind]
            same = "" if oc_n == ours_n else f" (OpenCog: {oc_n} answers)"
            print(
                f"  {kind:<14}{ours_t / q * 1e6:>10.1f}{oc_t / q * 1e6:>12.1f}"
                f"{oc_t / ours_t:>7.1f}x{ours_n:>9}{same}"
            )

    extra = robocog_only(names, pairs, work, args.rounds)
    for kind, (t, count) in extra.items():
        print(f"{kind + ' (robocog only)':<24}{t / q * 1e6:>10.1f}{'-':>12}{'-':>8}{count:>9}")

    if not args.no_million:
        print("10^6 atoms in robocog (wall time, resident memory added):")
        for how, secs, mb, count in million():
            mem = f"{mb:8.0f} MB" if mb else " " * 11
            print(f"  {how:<20}{secs:8.2f} s {mem}  ({count} atoms)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
