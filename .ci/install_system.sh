#!/usr/bin/env bash
# The Debian packages the whole test suite uses, installed only where missing and
# upgrading nothing (see apt_install.sh): ROS 1 for the rospy bridge tests; EGL with
# Mesa's software rasteriser, so that the physical tabletop's cameras render with no
# display (robocog sets MUJOCO_GL=egl itself); valgrind for the test that the AprilTag
# library touches no freed memory when a process ends; chromium for the inspector's
# browser tests (pytest-playwright drives it; Playwright's own browser download is not
# used; where Debian's chromium would upgrade installed libraries, it is unpacked into
# ~/.cache/robocog/deb-root instead). Without apt-get it says so, and the tests that
# need these skip.
set -euo pipefail
here="$(dirname "$0")"
bash "$here/install_ros.sh"
bash "$here/apt_install.sh" libegl1 libgl1-mesa-dri valgrind chromium
