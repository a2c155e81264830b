"""Convert a NARS memory saved by robocog before memory files (a pickle, "format 3") into
a memory file that robocog reads today.

TRUST WARNING: reading a pickle runs whatever code its author put in it. Run this only
on a file you made yourself, or whose author you trust, and best in a throw-away
environment (a container or a scratch account). robocog itself never reads pickles;
this script lives outside the package for that reason, and does nothing unless
``--trust`` is given.

    python tools/convert_pickle_memory.py --trust old.nar new.nar
"""

from __future__ import annotations

import argparse
import pickle
import sys
from pathlib import Path

from robocog.nars import NAR

OLD_FORMAT = "robocog-nar-3"


def convert(old: Path, new: Path) -> None:
    """Read the pickled memory ``old`` (format 3) and save it as a memory file ``new``."""
    with open(old, "rb") as f:
        state = pickle.load(f)  # noqa: S301 - the user vouched for this file (--trust)
    if not isinstance(state, dict) or state.get("format") != OLD_FORMAT:
        got = state.get("format") if isinstance(state, dict) else type(state).__name__
        raise SystemExit(f"{old}: not a robocog memory of format {OLD_FORMAT} ({got!r})")
    nar = NAR(seed=state["seed"])
    for k, v in state["config"].items():
        setattr(nar.config, k, v)
    nar.memory = state["memory"]
    nar.time = state["time"]
    nar.stamp_base = state["stamp_base"]
    nar.concept_threshold = state["concept_threshold"]
    nar.matched_total = state["matched_total"]
    nar.op_names = state["op_names"]
    nar.stats = state["stats"]
    nar.pending_questions = state.get("pending", {})
    for key in (
        "time_index",
        "table_index",
        "links_by_subject",
        "general_links",
        "goal_layers",
        "recent_goal_concepts",
    ):
        if key in state:
            setattr(nar, key, state[key])
    nar.set_random_state(state["rand"])
    nar.save(new)


def main(argv: list[str] | None = None) -> int:
    """Command line: ``--trust OLD NEW``."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--trust", action="store_true", help="I trust OLD: it may run code")
    p.add_argument("old", type=Path, help="the pickled memory")
    p.add_argument("new", type=Path, help="the memory file to write")
    args = p.parse_args(argv)
    if not args.trust:
        print(
            "convert_pickle_memory: reading a pickle runs the code it holds; "
            "give --trust only for a file you trust",
            file=sys.stderr,
        )
        return 2
    convert(args.old, args.new)
    print(f"wrote {args.new}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
