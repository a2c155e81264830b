"""``python -m robocog`` is the ``robocog`` command."""

import sys

from robocog.cli import main

sys.exit(main())
