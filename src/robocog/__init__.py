"""robocog: a reasoning mind for robots that a person can read, instruct and question.

Three engines stand alone (``robocog.nars``, ``robocog.bdi``, ``robocog.atomspace`` with
``robocog.planning``); ``robocog.robot`` is the contract they share with the worlds and
bridges, and ``robocog.minds`` is the only place that knows both sides.
"""

__version__ = "0.1.0"
