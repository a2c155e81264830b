"""What every test shares: the long tests are started first.

``python -m pytest -n auto`` hands tests to its workers in collection order, a share at
the start and the rest as workers free up. A long test handed out near the end keeps
its worker busy while the others have run out of work; handed out first, it runs while
the others work through the short tests, which then fill in the end evenly. So the
tests marked ``slow`` (a few seconds or more each) are moved to the front, keeping
their order among themselves and leaving every other test where it was.
"""

from __future__ import annotations

import pytest


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The ``slow`` tests first; a stable sort, so the same order in every worker."""
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)
