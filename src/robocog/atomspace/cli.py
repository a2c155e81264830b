"""``robocog atomese [FILE...]``: run Atomese programs (Scheme with OpenCog's API).

Each file is a Scheme program, as OpenCog users write them for Guile with
``(use-modules (opencog) (opencog exec))``: atoms, ``define``, procedures, the ``cog-``
API. Every top-level query (a GetLink, BindLink, QueryLink, MeetLink or SatisfactionLink
written bare, or a ``(cog-execute! ...)``/``(cog-evaluate! ...)`` form) has its result
printed after a line ``; FILE:LINE: TYPE``. A file is read whole before it runs, so a
file that does not read (unbalanced parentheses...) changes nothing. With no file, a
REPL like ``guile`` with the OpenCog modules loaded.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from robocog.argtypes import EXISTING_FILE_STR, NEW_FILE_STR
from robocog.atomspace import types as _t
from robocog.atomspace.atomese import dump
from robocog.atomspace.atoms import Atom, deep
from robocog.atomspace.scheme import (
    UNSPECIFIED,
    Form,
    SchemeError,
    Sym,
    read,
    sym,
)
from robocog.atomspace.space import AtomSpace

#: largest program file read (bytes)
MAX_FILE = 64 * 1024 * 1024
_SHOWN = {sym("cog-execute!"), sym("cog-evaluate!")}


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument(
        "files",
        nargs="*",
        type=EXISTING_FILE_STR,
        metavar="FILE",
        help="Atomese/Scheme (.scm) files; none: a REPL",
    )
    parser.add_argument("--dump", action="store_true", help="print the whole AtomSpace at the end")
    parser.add_argument(
        "--db", type=EXISTING_FILE_STR, metavar="PATH", help="load this SQLite store first"
    )
    parser.add_argument(
        "--save", type=NEW_FILE_STR, metavar="PATH", help="store the AtomSpace here at the end"
    )


def _shown(form: Any, value: Any) -> bool:
    """Is this top-level form a query whose result the command prints?"""
    if not isinstance(form, Form) or not form:
        return False
    head = form[0]
    if head.__class__ is Sym and head in _SHOWN:
        return True
    return isinstance(value, Atom) and value[0] in _t.QUERY_TYPES


def run_file(scheme: Any, name: str, text: str, out: Any) -> int:
    """Run one program; print query results; 0, or 1 after printing an error."""
    from robocog.atomspace.cogscm import pretty

    try:
        forms = list(read(text, name))
    except SchemeError as exc:
        print(f"robocog atomese: {exc}", file=sys.stderr)
        return 1
    scheme.source = name
    for form in forms:
        try:
            value = scheme.eval_top(form)
            if _shown(form, value):
                head = form[0]
                if isinstance(value, Atom) and head not in _SHOWN:
                    value = scheme.eval_top(Form([sym("cog-execute!"), value], form.line, form.col))
                label = value[0] if isinstance(value, Atom) and head not in _SHOWN else None
                if label is None:
                    inner = form[1] if len(form) > 1 else None
                    label = _label(inner, head)
                print(f"; {name}:{form.line}: {label}", file=out)
                print(pretty(value), file=out)
        except SchemeError as exc:
            print(f"robocog atomese: {exc}", file=sys.stderr)
            return 1
    return 0


def _label(inner: Any, head: Any) -> str:
    if isinstance(inner, Form) and inner and inner[0].__class__ is Sym:
        full = _t.resolve(str.__str__(inner[0]))
        if full:
            return full
    return str.__str__(head) if head.__class__ is Sym else "form"


def run(args: argparse.Namespace) -> int:
    """Run the files (or a REPL), print the results of their queries."""
    with deep():  # deep atoms are added and printed by recursion
        return _run(args)


def _run(args: argparse.Namespace) -> int:
    from robocog.atomspace.cogscm import make_scheme

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
    scheme = make_scheme(space, out=out)
    if not args.files:
        return repl(scheme)
    for name in args.files:
        path = Path(name)
        try:
            if path.stat().st_size > MAX_FILE:
                print(f"robocog atomese: {name}: larger than {MAX_FILE} bytes", file=sys.stderr)
                status = 1
                continue
            data = path.read_bytes()
            text = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            line = data.count(b"\n", 0, exc.start) + 1
            col = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
            print(f"robocog atomese: {name}:{line}:{col}: not UTF-8 text", file=sys.stderr)
            status = 1
            continue
        except OSError as exc:
            print(f"robocog atomese: {name}: {exc}", file=sys.stderr)
            status = 1
            continue
        status = max(status, run_file(scheme, name, text, out))
    space = scheme.cog.space
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


def _balanced(text: str) -> bool:
    """Does ``text`` hold complete data (so the REPL can run it)?"""
    try:
        list(read(text))
    except SchemeError as exc:
        return "unclosed" not in exc.message and "unterminated" not in exc.message
    return True


def repl(scheme: Any, stdin: Any = None) -> int:
    """Read, evaluate, print, as Guile's REPL does (``$1 = ...`` for each value)."""
    from robocog.atomspace.cogscm import pretty

    stdin = stdin or sys.stdin
    interactive = stdin.isatty()
    if interactive:
        try:
            import readline  # noqa: F401 - line editing for input()
        except ImportError:
            pass
        print("robocog atomese: Scheme with OpenCog's modules; (exit) or Ctrl-D to leave.")
    count = 0
    buf = ""
    while True:
        prompt = "scheme@(guile-user)> " if not buf else ""
        try:
            if interactive:
                line = input(prompt)
            else:
                sys.stdout.write(prompt)
                sys.stdout.flush()
                line = stdin.readline()
                if not line:
                    raise EOFError
        except EOFError:
            print()
            return 0
        except KeyboardInterrupt:
            print()
            buf = ""
            continue
        buf += line + ("\n" if interactive else "")
        if not buf.strip() or not _balanced(buf):
            continue
        text, buf = buf, ""
        try:
            for form in read(text, "<repl>"):
                value = scheme.eval_top(form)
                if value is UNSPECIFIED:
                    continue
                count += 1
                shown = pretty(value)
                sep = "\n" if "\n" in shown else " "
                print(f"${count} ={sep}{shown}")
        except SchemeError as exc:
            if exc.key == "quit":
                return 0
            print(f"ERROR: {exc}")
        except KeyboardInterrupt:
            print("\ninterrupted")
