"""The inspector: a local web page that shows a running world and mind, and takes orders.

``Inspector`` hooks a robot loop from outside (``hub``), ``InspectorServer`` serves the
page from another thread (``server``), ``snapshot`` keeps the ring buffer and the
JSON-lines log, ``views`` turns worlds and minds into what the page draws, and ``cli``
is ``robocog inspect FILE`` and the ``--inspect`` option of the run commands. The web
server needs the ``inspect`` extra (starlette, uvicorn); the rest needs nothing.
"""

from __future__ import annotations
