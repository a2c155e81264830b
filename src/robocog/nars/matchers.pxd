# For the compiled engine: the extension types and C functions that the generated
# matchers.py names, so that a premise's fields are read as a struct and the term
# constructors and truth functions are called in C.
# matchers.py is generated from rules.py's table and stays plain Python; see setup.py.

from robocog.nars.terms cimport Term, compound
from robocog.nars.truth cimport Truth
from robocog.nars cimport truth as tf
from robocog.nars.rules cimport make
