"""Manipulation planning over AtomSpace states: the four blocks actions as
Atomese rules, breadth-first and A* search, controlled English and PDDL input/output.
"""
