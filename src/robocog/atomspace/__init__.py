"""A typed hypergraph store in the manner of OpenCog's AtomSpace: atoms, truth
values and Values, Atomese s-expressions, a pattern matcher and SQLite persistence.
"""
