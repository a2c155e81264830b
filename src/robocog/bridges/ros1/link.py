"""The ROS 1 side of a bridge: a rospy node in a child process, spoken to over a pipe.

rospy from Debian lives in /usr/lib/python3/dist-packages for /usr/bin/python3, while
robocog may run on another Python. Adding that directory to ``sys.path`` would mix two
Pythons' compiled modules in one process; instead ``node.py`` runs under the Python that
owns rospy and exchanges JSON lines with this link (the protocol is in ``node.py``).
The node inherits ``ROS_MASTER_URI`` and ``ROS_IP`` from the environment.
"""

from __future__ import annotations

import itertools
import json
import logging
import math
import os
import shutil
import subprocess
import sys
import threading
from dataclasses import asdict
from pathlib import Path
from typing import IO, Any

from robocog.bridges.body import RobotBody
from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import BoxReading, PoseReading, ScanReading, quaternion_of, yaw_of

log = logging.getLogger("robocog.bridges.ros1")

NODE_SCRIPT = Path(__file__).with_name("node.py")


class Ros1Unavailable(ImportError):
    """No Python with rospy could be started."""


class Ros1Link:
    """A ``Link`` over a rospy node running in ``python`` (one that has rospy)."""

    def __init__(
        self,
        config: BridgeConfig,
        python: str = "/usr/bin/python3",
        ready_timeout: float = 20.0,
    ) -> None:
        self.config = config
        self.python = python
        self.ready_timeout = ready_timeout
        self._proc: subprocess.Popen[str] | None = None
        self._reader: threading.Thread | None = None
        self._stderr: threading.Thread | None = None
        self._write_lock = threading.Lock()
        self._tokens = itertools.count(1)
        self._ready = threading.Event()
        self._came_up = False
        self._failure = ""

    # -- lifecycle -------------------------------------------------------------------

    def start(self, body: RobotBody) -> None:
        """Start the node and wait until it reports ready (it has reached the master)."""
        if shutil.which(self.python) is None:
            raise Ros1Unavailable(f"{self.python} not found; ROS 1 needs a Python with rospy")
        settings = {
            "topics": asdict(self.config.topics),
            "pose_source": self.config.pose_source,
            "class_names": list(self.config.class_names),
        }
        self._body = body
        self._proc = subprocess.Popen(
            [self.python, str(NODE_SCRIPT), json.dumps(settings)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            bufsize=1,
            env=_node_env(),
        )
        assert self._proc.stdout is not None and self._proc.stderr is not None
        self._reader = threading.Thread(
            target=self._read, args=(self._proc.stdout,), daemon=True, name="ros1-link"
        )
        self._stderr = threading.Thread(
            target=self._drain, args=(self._proc.stderr,), daemon=True, name="ros1-stderr"
        )
        self._reader.start()
        self._stderr.start()
        if not self._ready.wait(self.ready_timeout) or not self._came_up:
            self.close()
            reason = self._failure or "it did not report ready (is roscore running?)"
            raise RuntimeError(f"the rospy node did not start: {reason}")

    def close(self) -> None:
        """Ask the node to quit, and end it if it does not within two seconds."""
        proc, self._proc = self._proc, None
        if proc is None:
            return
        try:
            if proc.poll() is None and proc.stdin is not None:
                proc.stdin.write('{"op": "quit"}\n')
                proc.stdin.flush()
                proc.stdin.close()
        except (BrokenPipeError, OSError, ValueError):
            pass
        try:
            proc.wait(timeout=2.0)
        except subprocess.TimeoutExpired:
            proc.terminate()
            try:
                proc.wait(timeout=2.0)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()

    # -- requests --------------------------------------------------------------------

    def send_velocity(self, linear: float, angular: float) -> None:
        """Publish a Twist on ``cmd_vel``."""
        self._send({"op": "twist", "linear": linear, "angular": angular})

    def send_goal(self, x: float, y: float, yaw: float) -> int:
        """Send a move_base goal in the map frame; its result comes back as a goal event."""
        token = next(self._tokens)
        self._send(
            {
                "op": "goal",
                "id": token,
                "x": x,
                "y": y,
                "q": list(quaternion_of(yaw)),
                "frame": self.config.map_frame,
            }
        )
        return token

    def cancel_goals(self) -> None:
        """Cancel every move_base goal."""
        self._send({"op": "cancel"})

    def send_gripper(self, text: str) -> None:
        """Publish a gripper request as a std_msgs/String."""
        self._send({"op": "gripper", "text": text})

    def _send(self, request: dict[str, Any]) -> None:
        proc = self._proc
        if proc is None or proc.stdin is None:
            return
        try:
            with self._write_lock:
                proc.stdin.write(json.dumps(request) + "\n")
                proc.stdin.flush()
        except (BrokenPipeError, OSError, ValueError):
            log.error("the rospy node is gone; request %s dropped", request.get("op"))

    # -- readings --------------------------------------------------------------------

    def _read(self, stream: IO[str]) -> None:
        for line in stream:
            try:
                self._handle(json.loads(line))
            except (ValueError, KeyError, TypeError) as exc:
                log.error("bad line from the rospy node (%s): %r", exc, line[:200])
        if not self._ready.is_set():
            self._failure = self._failure or "it exited"
            self._ready.set()
        elif self._proc is not None:
            log.error("the rospy node exited; the robot can no longer be reached")

    def _drain(self, stream: IO[str]) -> None:
        for line in stream:
            line = line.rstrip()
            if line:
                self._failure = line
                log.debug("rospy node: %s", line)

    def _handle(self, msg: dict[str, Any]) -> None:
        body = self._body
        kind = msg["k"]
        if kind == "scan":
            ranges = [math.inf if r is None else float(r) for r in msg["ranges"]]
            body.on_scan(
                ScanReading(
                    msg["angle_min"],
                    msg["angle_increment"],
                    msg["range_min"],
                    msg["range_max"],
                    ranges,
                ),
                _stamp(msg),
            )
        elif kind == "boxes":
            body.on_boxes(
                [
                    BoxReading(i["label"], float(i["score"]), float(i["cx"]), tuple(i["pos"]))
                    for i in msg["items"]
                ],
                _stamp(msg),
            )
        elif kind == "pose":
            qx, qy, qz, qw = msg["q"]
            body.on_pose(PoseReading(float(msg["x"]), float(msg["y"]), yaw_of(qx, qy, qz, qw)))
        elif kind == "gripper":
            body.on_gripper(msg["text"])
        elif kind == "text":
            body.on_text(msg["text"])
        elif kind == "mission":
            body.on_mission(msg["text"])
        elif kind == "goal":
            body.on_goal_result(int(msg["id"]), msg["status"])
        elif kind == "ready":
            self._came_up = True
            self._ready.set()
        elif kind == "error":
            if not self._ready.is_set():
                self._failure = msg["text"]
            log.error("rospy node: %s", msg["text"])


def _node_env() -> dict[str, str]:
    """The node's environment: the caller's, less what belongs to robocog's own Python.

    PYTHONHOME and the PYTHONPATH entries inside this interpreter's prefix or robocog's
    source tree would break (or shadow modules of) the system Python; other entries,
    such as a ROS installation's own directories, are kept.
    """
    env = dict(os.environ)
    for key in ("PYTHONHOME", "VIRTUAL_ENV"):
        env.pop(key, None)
    ours = {Path(p).resolve() for p in (sys.prefix, sys.base_prefix)}
    ours.add(Path(__file__).resolve().parents[3])  # the directory that holds robocog
    kept = [
        entry
        for entry in env.get("PYTHONPATH", "").split(os.pathsep)
        if entry and not any(_inside(Path(entry), root) for root in ours)
    ]
    if kept:
        env["PYTHONPATH"] = os.pathsep.join(kept)
    else:
        env.pop("PYTHONPATH", None)
    return env


def _inside(path: Path, root: Path) -> bool:
    try:
        path.resolve().relative_to(root)
    except ValueError:
        return False
    return True


def _stamp(msg: dict[str, Any]) -> float:
    """A reading's header time as the node reported it (0 when absent or not a number)."""
    value = msg.get("stamp", 0.0)
    return float(value) if isinstance(value, int | float) and math.isfinite(value) else 0.0
