"""Non-Axiomatic Reasoning System compatible with OpenNARS for Applications (ONA).

Narsese terms, NAL truth functions, stamps, a bounded concept memory, declarative and
sensorimotor inference, decisions, and ONA's shell protocol. Imports nothing from the
robot side of robocog, so it can be used as a library by itself.
"""

from .nar import NAR
from .narsese import NarseseError, parse_sentence, parse_term
from .terms import Term

__all__ = ["NAR", "NarseseError", "Term", "parse_sentence", "parse_term"]
