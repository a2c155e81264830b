"""Recording ROS 2 traffic into MCAP as rosbag2 does: ``cdr`` messages, ``ros2msg`` schemas.

Every message a sim or a bridge sends or reads on a ROS topic (``rt/...``) is written
with the ROS 2 topic name (``/scan``), the ROS type name (``sensor_msgs/msg/LaserScan``)
and its message definition as the channel's schema, and the serialized bytes exactly as
they travel (CDR with its 4-byte encapsulation header), so that any ROS 2 tool or
library reads the file. Navigation goals travel as action requests, which carry the
rmw request header; their goal part is recorded as ``nav2_msgs/action/NavigateToPose_Goal``
on ``/<action>/_action/send_goal`` (``robocog_msgs/action/Grasp_Goal`` likewise), so a
replay sees what a mind asked for.
"""

from __future__ import annotations

import threading
import time
from pathlib import Path
from typing import Any

from mcap.writer import Writer

from robocog.bridges.ros2.definitions import DEFINITIONS, ros_type_of, schema_text

#: the channel metadata rosbag2 writes for each topic (offered QoS and type hash)
ENCODING = "cdr"
SCHEMA_ENCODING = "ros2msg"


class Recorder:
    """An MCAP file being written; ``write(dds_topic, message)`` from any thread."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self._stream = open(self.path, "wb")  # noqa: SIM115 - closed by close()
        self._writer = Writer(self._stream)
        self._writer.start(profile="ros2", library="robocog")
        self._schemas: dict[str, int] = {}
        self._channels: dict[str, int] = {}
        self._lock = threading.Lock()
        self._closed = False
        self.count = 0

    def write(self, dds_topic: str, *args: Any) -> None:
        """Record one message seen on ``dds_topic`` (``rt/scan``; the message is the last
        argument, so that ``on_message(topic, kind, message)`` callbacks fit)."""
        message = args[-1]
        topic, payload = _channel_of(dds_topic, message)
        if topic is None:
            return
        ros_type = ros_type_of(type(payload).__idl_typename__)
        if ros_type not in DEFINITIONS:
            return
        data = payload.serialize()
        now = time.time_ns()
        with self._lock:
            if self._closed:
                return
            channel = self._channel(topic, ros_type)
            self._writer.add_message(channel, log_time=now, data=data, publish_time=now)
            self.count += 1

    def _channel(self, topic: str, ros_type: str) -> int:
        channel = self._channels.get(topic)
        if channel is None:
            schema = self._schemas.get(ros_type)
            if schema is None:
                schema = self._writer.register_schema(
                    ros_type, SCHEMA_ENCODING, schema_text(ros_type).encode("utf-8")
                )
                self._schemas[ros_type] = schema
            channel = self._writer.register_channel(topic, ENCODING, schema)
            self._channels[topic] = channel
        return channel

    def close(self) -> None:
        """Finish the file (its summary and index) and close it."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            self._writer.finish()
            self._stream.close()


def _channel_of(dds_topic: str, message: Any) -> tuple[str | None, Any]:
    """The recorded topic and message of a DDS sample, or (None, None) when it is
    service plumbing (replies, result and cancel requests)."""
    if dds_topic.startswith("rt/"):
        return "/" + dds_topic[3:], message
    if dds_topic.startswith("rq/") and dds_topic.endswith("/_action/send_goalRequest"):
        return "/" + dds_topic[3 : -len("Request")], message.goal
    return None, None
