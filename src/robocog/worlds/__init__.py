"""Embedded simulators that implement the Body protocol: the garbage field, the
room with a door and an exit, and the tabletop with bins. Know no engine.
"""
