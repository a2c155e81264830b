"""Embedded simulators that implement the Body protocol: the garbage field, the
room with a door and an exit, and the tabletop with bins; and the procedure-learning
worlds of ONA's system tests (``procedures``), which speak Narsese. Know no engine.
"""
