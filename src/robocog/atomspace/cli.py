"""``robocog atomese FILE...``: load Atomese files and print the results of their queries.

Each file is read whole before anything is added, so a malformed file changes nothing
and is reported with its line and column. Atoms are added in file order; every
top-level query (GetLink, BindLink, QueryLink, MeetLink, SatisfactionLink, written bare
or inside ``(cog-execute! ...)``) is run where it stands and its result printed.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from robocog.argtypes import EXISTING_FILE_STR, NEW_FILE_STR
from robocog.atomspace import types as _t
from robocog.atomspace.atomese import AtomeseError, dump, parse, write_pretty
from robocog.atomspace.execute import GroundedError, execute
from robocog.atomspace.matcher import PatternError
from robocog.atomspace.space import AtomSpace


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument(
        "files", nargs="+", type=EXISTING_FILE_STR, metavar="FILE", help="Atomese (.scm) files"
    )
    parser.add_argument("--dump", action="store_true", help="print the whole AtomSpace at the end")
    parser.add_argument(
        "--db", type=EXISTING_FILE_STR, metavar="PATH", help="load this SQLite store first"
    )
    parser.add_argument(
        "--save", type=NEW_FILE_STR, metavar="PATH", help="store the AtomSpace here at the end"
    )


def run(args: argparse.Namespace) -> int:
    """Load the files, run their queries, print the results."""
    space = AtomSpace()
    out = sys.stdout
    status = 0
    if args.db:
        from robocog.atomspace.persist import StoreError, load

        try:
            load(args.db, space)
        except StoreError as exc:
            print(f"robocog atomese: {exc}", file=sys.stderr)
            return 1
    for name in args.files:
        path = Path(name)
        try:
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            print(f"robocog atomese: {name}: {exc}", file=sys.stderr)
            status = 1
            continue
        try:
            parsed = parse(text, source=name)
        except AtomeseError as exc:
            print(f"robocog atomese: {exc}", file=sys.stderr)
            status = 1
            continue
        tvs: dict = {}
        for atom, tv in parsed.tvs:
            tvs[atom] = tv
        for form in parsed.forms:
            atom = form.atom
            if form.execute or atom[0] in _t.QUERY_TYPES:
                try:
                    result = execute(space, atom)
                except (GroundedError, PatternError) as exc:
                    print(f"{name}:{form.line}:{form.column}: error: {exc}", file=sys.stderr)
                    status = 1
                    continue
                print(f"; {name}:{form.line}: {atom[0]}", file=out)
                print(write_pretty(result), file=out)
            else:
                space.add(atom)
        for atom, tv in tvs.items():
            if atom in space:
                space.set_tv(atom, tv)
    if args.dump:
        out.write(dump(space))
    if args.save:
        from robocog.atomspace.persist import StoreError, store

        try:
            store(space, args.save)
        except (StoreError, OSError) as exc:
            print(f"robocog atomese: {exc}", file=sys.stderr)
            return 1
    return status
