"""What every test shares: the order in which pytest-xdist hands tests to its workers.

``python -m pytest -n auto`` runs the tests in worker processes. Its default (``load``)
scheduling hands each worker a block of consecutive tests at the start (a quarter of
its share) and more blocks as it runs low; a worker that drew the long tests then works
on while the others, having run out, wait. Here the tests marked ``slow`` (a few seconds
or more each) come first, and tests are handed out one at a time (as ``--maxschedchunk
1`` would), so each worker takes the next test when it is free: the long tests are
spread over the workers from the start and the short ones even out the end. The order
is a stable sort, the same in every worker, as pytest-xdist requires.
"""

from __future__ import annotations

import pytest

from robocog.worlds.physics.gl import choose_gl

# MuJoCo reads MUJOCO_GL once, when first imported: a test module that imports mujoco
# before robocog's physics package would leave every later render in its worker without
# an offscreen context, so the backend is chosen here, before any test module loads
choose_gl()


def pytest_configure(config: pytest.Config) -> None:
    """One test at a time to each free worker, unless ``--maxschedchunk`` says otherwise."""
    if hasattr(config.option, "maxschedchunk") and config.option.maxschedchunk is None:
        config.option.maxschedchunk = 1


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The ``slow`` tests first, each group keeping its order."""
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)
