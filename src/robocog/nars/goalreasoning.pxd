# For the compiled engine: the extension types and C functions that goalreasoning.py
# names, so that its annotated variables are read as structs and its calls made in C.
# goalreasoning.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term, compound
from robocog.nars.truth cimport Truth
from robocog.nars cimport truth as tf
from robocog.nars.stamp cimport has_duplicate, merge, overlap
from robocog.nars.event cimport Event
from robocog.nars.unify cimport apply, unify
