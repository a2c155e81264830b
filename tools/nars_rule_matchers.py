"""Write the NARS rule table's generated matchers, ``src/robocog/nars/matchers.py``.

The rule table (``RULES`` in ``robocog/nars/rules.py``) is the source; its matchers
are generated Python, checked in so that the compiled engine compiles them with the
rest. Run this after changing the table (``--check`` only says whether the file is
current, with exit status 1 when it is not):

    PYTHONPATH=src python tools/nars_rule_matchers.py [--check]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from robocog.nars.rulegen import MATCHERS_MODULE, matcher_source

TARGET = Path(__file__).resolve().parents[1] / "src" / "robocog" / "nars" / MATCHERS_MODULE


def main(argv: list[str] | None = None) -> int:
    """Write (or with ``--check`` compare) the generated module; 0 when it is current."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="only compare, write nothing")
    args = parser.parse_args(argv)
    text = matcher_source()
    current = TARGET.exists() and TARGET.read_text(encoding="utf-8") == text
    if args.check:
        print(f"{TARGET.name} is {'current' if current else 'out of date'}")
        return 0 if current else 1
    if not current:
        TARGET.write_text(text, encoding="utf-8")
        print(f"wrote {TARGET}")
    else:
        print(f"{TARGET.name} is current")
    return 0


if __name__ == "__main__":
    sys.exit(main())
