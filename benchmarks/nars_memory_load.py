"""Loading a saved NARS memory: robocog's memory file read back, against the grammar.

A session of random taxonomy links and temporal implications is saved (about 285 KB,
gzip), then loaded five times in this process (the reasoner's rule table built once
before, as any process that has made a reasoner has it). The file's terms are also
read through the Narsese grammar (``parse_pattern``, what loading did before) to give
the ratio of the two term readers on the same texts. ONA has no saved memories, so
the grammar is the peer here.

    python benchmarks/nars_memory_load.py                   # ~285 KB memory
    python benchmarks/nars_memory_load.py --links 1200      # a larger one (~450 KB)
"""

from __future__ import annotations

import argparse
import json
import os
import random
import statistics
import tempfile
import time
import zlib
from pathlib import Path

from robocog.nars.memfile_io import read_file
from robocog.nars.nar import NAR
from robocog.nars.narsese import parse_pattern, read_canonical


def build(links: int, path: Path) -> None:
    nar = NAR(seed=1, concepts_max=20_000)
    nar.output = lambda line: None  # type: ignore[method-assign]
    rng = random.Random(1)
    for i in range(links):
        a, b = rng.randrange(4000), rng.randrange(4000)
        nar.add_input(f"<n{a} --> n{b}>.")
        if i % 7 == 0:
            nar.add_input(f"<(e{a} &/ <({{SELF}} * x{b}) --> ^op{a % 3}>) =/> g{b}>.")
        if i % 13 == 0:
            nar.add_input(f"<e{a} --> [s{b}]>. :|:")
    nar.save(path)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--links", type=int, default=850, help="taxonomy links in the session")
    p.add_argument("--rounds", type=int, default=5)
    args = p.parse_args()
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "m.nar"
        build(args.links, path)
        size = os.path.getsize(path)
        NAR(seed=1)  # the rule table, built once per process
        loads, cpu = [], []
        for _ in range(args.rounds):
            t0, c0 = time.perf_counter(), time.process_time()
            NAR.load(path)
            loads.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
        texts = json.loads(read_file(path))["terms"]
        t0 = time.perf_counter()
        for t in texts:
            read_canonical(t)
        fast = time.perf_counter() - t0
        t0 = time.perf_counter()
        for t in texts:
            parse_pattern(t)
        grammar = time.perf_counter() - t0
        expanded = len(zlib.decompress(path.read_bytes(), 31))
    print(
        f"memory file: {size / 1024:.0f} KB ({expanded / 1024:.0f} KB of JSON), {len(texts)} terms"
    )
    print(
        f"NAR.load: median {statistics.median(loads):.3f} s wall, "
        f"{statistics.median(cpu):.3f} s CPU; best {min(loads):.3f} s over {args.rounds} rounds"
    )
    print(
        f"terms: printed-form reader {fast:.3f} s, grammar {grammar:.3f} s, "
        f"ratio {grammar / fast:.1f}"
    )


if __name__ == "__main__":
    main()
