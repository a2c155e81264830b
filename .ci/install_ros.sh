#!/usr/bin/env bash
# Debian's ROS 1 packages for the ROS 1 bridge tests: rospy, the master and roscore,
# actionlib, and the message packages the bridge and its stand-in robot use. They are
# installed for /usr/bin/python3 only; robocog reaches them through a child process.
# Idempotent and non-interactive; does nothing when everything is already there.
set -euo pipefail

PACKAGES=(
    python3-rospy
    python3-rosmaster
    python3-roslaunch
    python3-actionlib
    python3-actionlib-msgs
    python3-std-msgs
    python3-geometry-msgs
    python3-sensor-msgs
    python3-nav-msgs
    python3-move-base-msgs
)

missing=()
for package in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
if [ "${#missing[@]}" -eq 0 ] && command -v roscore >/dev/null; then
    exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${PACKAGES[@]}"
