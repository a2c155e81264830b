"""The physical tabletop's parts: tag images, the MJCF scene, the arm's motion and the
camera's perception. Needs the ``physics`` extra (mujoco, pupil-apriltags, imageio);
importing :mod:`robocog.worlds` or the symbolic tabletop never does.
"""

from robocog.worlds.physics.gl import choose_gl

# MuJoCo reads MUJOCO_GL when it is first imported, so the backend is chosen before any
# module of this package imports it.
choose_gl()
