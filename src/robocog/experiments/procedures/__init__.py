"""Reasoners for the procedure-learning worlds (:mod:`robocog.worlds.procedures`): ONA's
shell through pipes, robocog's NAR, scripted policies, and ONA's own built-in tests.

``benchmarks/procedure_learning.py`` sets them side by side (docs/procedure_learning.md).
"""
