"""What an internal action returns to the reasoning cycle besides success or failure.

Both sit below the agent and the standard library, which exchange them: an internal
action that has already changed its intention itself (suspended it, or updated it)
says so, and the cycle then leaves that intention as it is.
"""

from __future__ import annotations

#: returned by an internal action that suspended its intention itself
SUSPEND = object()
#: returned by an internal action that already updated its intention itself
DONE = object()
