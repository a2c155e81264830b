"""robocog's AtomSpace against hyperon (OpenCog Hyperon's GroundingSpace) on the same facts.

Both stores get the same 10,000 facts: 7,500 ``on(X, Y)`` and 2,500 ``clear(X)`` over
3,000 blocks, from one seed. Each then answers the same 1,000 queries of four kinds:

- ``first``:  on(B, ?y)                  first argument bound
- ``second``: on(?x, B)                  second argument bound
- ``join-first``: on(B, ?y), on(?y, ?z)  two clauses joined, bound at the first end
- ``join-last``:  on(?x, ?y), on(?y, B)  two clauses joined, bound at the last end

robocog answers through ``query()`` (a list of {variable: atom}) and through GetLink
execution; hyperon through ``GroundingSpace.query`` (a BindingsSet, read out to a list).
Patterns are built before the clock starts, on both sides, and the answer counts are
compared so that both did the same work. Hyperon's index cannot hold more than about
1,024 distinct symbols, so there a block is the expression ``(b H L)`` over 130 digit
symbols; in robocog it is the ConceptNode ``"bH_L"``.

Then the load time and memory of 10^6 atoms in robocog: built from Python, read from
Atomese text, and loaded from SQLite (resident memory measured from /proc).

    python benchmarks/atomspace.py                 # everything
    python benchmarks/atomspace.py --queries 200 --no-million
"""

from __future__ import annotations

import argparse
import gc
import os
import random
import sys
import tempfile
import time
from collections.abc import Callable

from robocog.atomspace import AtomSpace, Link, Node, query
from robocog.atomspace.persist import load, store
from robocog.atomspace.space import bulk

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


# ---------------------------------------------------------------------- robocog
def robocog_side(names, pairs, clears, work) -> dict[str, tuple[float, int]]:  # noqa: ANN001
    space = AtomSpace()
    on, clear = Node("PredicateNode", "on"), Node("PredicateNode", "clear")
    concepts = [Node("ConceptNode", f"b{h}_{lo}") for h, lo in names]
    t0 = time.perf_counter()
    for x, y in pairs:
        space.add(Link("EvaluationLink", on, Link("ListLink", concepts[x], concepts[y])))
    for x in clears:
        space.add(Link("EvaluationLink", clear, concepts[x]))
    load_s = time.perf_counter() - t0
    X, Y, Z = (Node("VariableNode", v) for v in ("$x", "$y", "$z"))

    def on_(a, b):  # noqa: ANN001, ANN202
        return Link("EvaluationLink", on, Link("ListLink", a, b))

    make: dict[str, Callable] = {
        "first": lambda b: on_(concepts[b], Y),
        "second": lambda b: on_(X, concepts[b]),
        "join-first": lambda b: Link("AndLink", on_(concepts[b], Y), on_(Y, Z)),
        "join-last": lambda b: Link("AndLink", on_(X, Y), on_(Y, concepts[b])),
    }
    out: dict[str, tuple[float, int]] = {"load": (load_s, len(space))}
    for kind in KINDS:
        patterns = [make[kind](b) for b in work[kind]]
        count = 0
        t0 = time.perf_counter()
        for p in patterns:
            count += len(query(space, p))
        out[kind] = (time.perf_counter() - t0, count)
        gets = [Link("GetLink", p) for p in patterns]
        count_get = 0
        t0 = time.perf_counter()
        for g in gets:
            count_get += len(space.execute(g).out)
        out[kind + " (GetLink)"] = (time.perf_counter() - t0, count_get)
    return out


# ---------------------------------------------------------------------- hyperon
def hyperon_side(names, pairs, clears, work) -> dict[str, tuple[float, int]]:  # noqa: ANN001
    from hyperon import E, GroundingSpaceRef, S, V

    space = GroundingSpaceRef()
    on, clear, b = S("on"), S("clear"), S("b")
    digits = [S(str(i)) for i in range(100)]
    blocks = [E(b, digits[h], digits[lo]) for h, lo in names]
    t0 = time.perf_counter()
    for x, y in pairs:
        space.add_atom(E(on, blocks[x], blocks[y]))
    for x in clears:
        space.add_atom(E(clear, blocks[x]))
    load_s = time.perf_counter() - t0
    X, Y, Z = V("x"), V("y"), V("z")
    comma = S(",")
    make: dict[str, Callable] = {
        "first": lambda k: E(on, blocks[k], Y),
        "second": lambda k: E(on, X, blocks[k]),
        "join-first": lambda k: E(comma, E(on, blocks[k], Y), E(on, Y, Z)),
        "join-last": lambda k: E(comma, E(on, X, Y), E(on, Y, blocks[k])),
    }
    out: dict[str, tuple[float, int]] = {"load": (load_s, len(pairs) + len(clears))}
    for kind in KINDS:
        patterns = [make[kind](k) for k in work[kind]]
        count = 0
        t0 = time.perf_counter()
        for p in patterns:
            count += len(list(space.query(p).iterator()))
        out[kind] = (time.perf_counter() - t0, count)
    return out


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
    ap.add_argument("--no-million", action="store_true", help="skip the 10^6-atom part")
    ap.add_argument("--no-hyperon", action="store_true", help="robocog only")
    args = ap.parse_args(argv)

    names, pairs, clears = facts(args.seed)
    work = workload(args.seed, len(names), args.queries)
    mine = robocog_side(names, pairs, clears, work)
    theirs: dict[str, tuple[float, int]] = {}
    if not args.no_hyperon:
        try:
            theirs = hyperon_side(names, pairs, clears, work)
        except ImportError:
            print("hyperon is not installed: robocog only", file=sys.stderr)

    print(
        f"facts: {len(pairs)} on, {len(clears)} clear over {len(names)} blocks; "
        f"{args.queries} queries per kind; seed {args.seed}"
    )
    print(
        f"load: robocog {mine['load'][0] * 1e3:.1f} ms ({mine['load'][1]} atoms)"
        + (f", hyperon {theirs['load'][0] * 1e3:.1f} ms" if theirs else "")
    )
    print(f"{'query':<22}{'robocog us/q':>14}{'hyperon us/q':>14}{'ratio':>8}{'answers':>10}")
    for kind in KINDS:
        t, n = mine[kind]
        tg, ng = mine[kind + " (GetLink)"]
        us = t / args.queries * 1e6
        usg = tg / args.queries * 1e6
        if theirs:
            th, nh = theirs[kind]
            ush = th / args.queries * 1e6
            agree = "" if nh == n else f"  (hyperon found {nh})"
            print(f"{kind:<22}{us:>14.1f}{ush:>14.1f}{ush / us:>7.1f}x{n:>10}{agree}")
            print(f"{'  as GetLink':<22}{usg:>14.1f}{'':>14}{ush / usg:>7.1f}x{ng:>10}")
        else:
            print(f"{kind:<22}{us:>14.1f}{'-':>14}{'-':>8}{n:>10}")
            print(f"{'  as GetLink':<22}{usg:>14.1f}{'-':>14}{'-':>8}{ng:>10}")

    if not args.no_million:
        print("10^6 atoms in robocog:")
        for how, s, mb, n in million():
            mem = f"{mb:8.0f} MB" if mb else " " * 11
            print(f"  {how:<20}{s:8.2f} s {mem}  ({n} atoms)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
