"""A fuzz harness for every reader robocog has.

Each target (``targets.py``) is one entry point that takes text or bytes from a user, a
file, a topic or a web page, with the error it documents for input it refuses. The
runner (``runner.py``) feeds it seeds taken from real inputs and mutations of them
(``mutators.py``), each in a worker process, and counts what goes wrong:

* crash: an exception other than the documented error (a wrong Python type's
  TypeError aside), a worker that died, or a value that must never come out;
* slow: an input that took more than two seconds;
* big: an input whose parse held more than 100 MB at its peak.

Inputs that went wrong are written to ``tests/fuzz/regressions/<target>/`` and replayed
by ``tests/fuzz/test_fuzz.py`` in the normal test run. ``python -m tests.fuzz --minutes
N`` runs it (docs/fuzzing.md).
"""
