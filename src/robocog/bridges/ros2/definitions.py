"""The ROS 2 message definitions robocog speaks, as ``.msg`` text: for recordings and hashes.

A recording in MCAP carries each channel's schema as the ROS 2 message definition
(``ros2msg``: the type's own fields, then each type it uses after a line of ``=`` and
``MSG: pkg/msg/Name``), which is how rosbag2 writes them and how other readers decode
them without robocog. The same definitions give each type's hash, ``RIHS01_`` and the
SHA-256 of the type description as JSON (REP 2016; ROS 2 Iron and later put it in the
discovery data, ``ros2 topic info -v`` prints it), field order and types as the layouts
in ``messages.py``. Comments and default values are not part of either.
"""

from __future__ import annotations

import hashlib
import json
import re

#: type name -> its fields, one ``type name`` a line (types of other packages in full)
DEFINITIONS: dict[str, str] = {
    "builtin_interfaces/msg/Time": "int32 sec\nuint32 nanosec",
    "builtin_interfaces/msg/Duration": "int32 sec\nuint32 nanosec",
    "std_msgs/msg/String": "string data",
    "std_msgs/msg/Header": "builtin_interfaces/msg/Time stamp\nstring frame_id",
    "geometry_msgs/msg/Vector3": "float64 x\nfloat64 y\nfloat64 z",
    "geometry_msgs/msg/Point": "float64 x\nfloat64 y\nfloat64 z",
    "geometry_msgs/msg/Quaternion": "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1",
    "geometry_msgs/msg/Pose": (
        "geometry_msgs/msg/Point position\ngeometry_msgs/msg/Quaternion orientation"
    ),
    "geometry_msgs/msg/PoseStamped": "std_msgs/msg/Header header\ngeometry_msgs/msg/Pose pose",
    "geometry_msgs/msg/PoseWithCovariance": ("geometry_msgs/msg/Pose pose\nfloat64[36] covariance"),
    "geometry_msgs/msg/PoseWithCovarianceStamped": (
        "std_msgs/msg/Header header\ngeometry_msgs/msg/PoseWithCovariance pose"
    ),
    "geometry_msgs/msg/Twist": "geometry_msgs/msg/Vector3 linear\ngeometry_msgs/msg/Vector3 angular",
    "geometry_msgs/msg/TwistWithCovariance": (
        "geometry_msgs/msg/Twist twist\nfloat64[36] covariance"
    ),
    "geometry_msgs/msg/Transform": (
        "geometry_msgs/msg/Vector3 translation\ngeometry_msgs/msg/Quaternion rotation"
    ),
    "geometry_msgs/msg/TransformStamped": (
        "std_msgs/msg/Header header\nstring child_frame_id\ngeometry_msgs/msg/Transform transform"
    ),
    "nav_msgs/msg/Odometry": (
        "std_msgs/msg/Header header\nstring child_frame_id\n"
        "geometry_msgs/msg/PoseWithCovariance pose\ngeometry_msgs/msg/TwistWithCovariance twist"
    ),
    "sensor_msgs/msg/LaserScan": (
        "std_msgs/msg/Header header\nfloat32 angle_min\nfloat32 angle_max\n"
        "float32 angle_increment\nfloat32 time_increment\nfloat32 scan_time\n"
        "float32 range_min\nfloat32 range_max\nfloat32[] ranges\nfloat32[] intensities"
    ),
    "sensor_msgs/msg/JointState": (
        "std_msgs/msg/Header header\nstring[] name\nfloat64[] position\n"
        "float64[] velocity\nfloat64[] effort"
    ),
    "tf2_msgs/msg/TFMessage": "geometry_msgs/msg/TransformStamped[] transforms",
    "std_msgs/msg/Float64": "float64 data",
    "sensor_msgs/msg/Image": (
        "std_msgs/msg/Header header\nuint32 height\nuint32 width\nstring encoding\n"
        "uint8 is_bigendian\nuint32 step\nuint8[] data"
    ),
    "sensor_msgs/msg/RegionOfInterest": (
        "uint32 x_offset\nuint32 y_offset\nuint32 height\nuint32 width\nbool do_rectify"
    ),
    "sensor_msgs/msg/CameraInfo": (
        "std_msgs/msg/Header header\nuint32 height\nuint32 width\nstring distortion_model\n"
        "float64[] d\nfloat64[9] k\nfloat64[9] r\nfloat64[12] p\nuint32 binning_x\n"
        "uint32 binning_y\nsensor_msgs/msg/RegionOfInterest roi"
    ),
    "sensor_msgs/msg/Imu": (
        "std_msgs/msg/Header header\ngeometry_msgs/msg/Quaternion orientation\n"
        "float64[9] orientation_covariance\ngeometry_msgs/msg/Vector3 angular_velocity\n"
        "float64[9] angular_velocity_covariance\ngeometry_msgs/msg/Vector3 linear_acceleration\n"
        "float64[9] linear_acceleration_covariance"
    ),
    "sensor_msgs/msg/Range": (
        "std_msgs/msg/Header header\nuint8 radiation_type\nfloat32 field_of_view\n"
        "float32 min_range\nfloat32 max_range\nfloat32 range\nfloat32 variance"
    ),
    "rosgraph_msgs/msg/Clock": "builtin_interfaces/msg/Time clock",
    "vision_msgs/msg/Point2D": "float64 x\nfloat64 y",
    "vision_msgs/msg/Pose2D": "vision_msgs/msg/Point2D position\nfloat64 theta",
    "vision_msgs/msg/BoundingBox2D": "vision_msgs/msg/Pose2D center\nfloat64 size_x\nfloat64 size_y",
    "vision_msgs/msg/ObjectHypothesis": "string class_id\nfloat64 score",
    "vision_msgs/msg/ObjectHypothesisWithPose": (
        "vision_msgs/msg/ObjectHypothesis hypothesis\ngeometry_msgs/msg/PoseWithCovariance pose"
    ),
    "vision_msgs/msg/Detection2D": (
        "std_msgs/msg/Header header\nvision_msgs/msg/ObjectHypothesisWithPose[] results\n"
        "vision_msgs/msg/BoundingBox2D bbox\nstring id"
    ),
    "vision_msgs/msg/Detection2DArray": (
        "std_msgs/msg/Header header\nvision_msgs/msg/Detection2D[] detections"
    ),
    "nav2_msgs/action/NavigateToPose_Goal": (
        "geometry_msgs/msg/PoseStamped pose\nstring behavior_tree"
    ),
    "robocog_msgs/action/Grasp_Goal": "string command\nstring target",
}

#: rosidl's field type ids (type_description_interfaces/msg/FieldType)
_PRIMITIVES = {
    "int8": 2,
    "uint8": 3,
    "int16": 4,
    "uint16": 5,
    "int32": 6,
    "uint32": 7,
    "int64": 8,
    "uint64": 9,
    "float32": 10,
    "float64": 11,
    "char": 13,
    "bool": 15,
    "byte": 16,
    "string": 17,
}
_NESTED = 1
#: added to a type id for a fixed array, a bounded sequence, an unbounded sequence
_ARRAY, _BOUNDED, _SEQUENCE = 48, 96, 144
_FIELD = re.compile(r"^(?P<type>[A-Za-z0-9_/]+)(?P<array>\[(?P<size><=)?(?P<n>\d*)\])?$")


def fields_of(name: str) -> list[tuple[str, str, str]]:
    """The fields of a type: (base type, array suffix or '', field name)."""
    out = []
    for line in DEFINITIONS[name].splitlines():
        words = line.split()
        match = _FIELD.match(words[0])
        if match is None:
            raise ValueError(f"{name}: cannot read the field type {words[0]!r}")
        out.append((match["type"], match["array"] or "", words[1]))
    return out


def dependencies(name: str) -> list[str]:
    """Every type ``name`` uses, directly or not, depth first, each once."""
    seen: list[str] = []

    def visit(n: str) -> None:
        for base, _array, _field in fields_of(n):
            if base not in _PRIMITIVES and base not in seen:
                seen.append(base)
                visit(base)

    visit(name)
    return seen


def schema_text(name: str) -> str:
    """The ``ros2msg`` schema of a type, as rosbag2 writes it into MCAP."""
    separator = "=" * 80
    parts = [_plain(name)]
    for dep in dependencies(name):
        parts.append(f"{separator}\nMSG: {dep}\n{_plain(dep)}")
    return "\n".join(parts) + "\n"


def _plain(name: str) -> str:
    """The definition as a ``.msg`` file says it: without default values, and types of
    other packages as ``pkg/Name`` (``builtin_interfaces/Time``)."""
    lines = []
    for line in DEFINITIONS[name].splitlines():
        kind, field = line.split()[:2]
        parts = kind.split("/")
        if len(parts) == 3:
            kind = f"{parts[0]}/{parts[2]}"
        lines.append(f"{kind} {field}")
    return "\n".join(lines)


def _field_type(base: str, array: str) -> dict[str, object]:
    type_id = _PRIMITIVES.get(base, _NESTED)
    capacity = 0
    if array:
        match = _FIELD.match("x" + array)
        assert match is not None
        if match["size"]:
            type_id += _BOUNDED
            capacity = int(match["n"])
        elif match["n"]:
            type_id += _ARRAY
            capacity = int(match["n"])
        else:
            type_id += _SEQUENCE
    return {
        "type_id": type_id,
        "capacity": capacity,
        "string_capacity": 0,
        "nested_type_name": "" if base in _PRIMITIVES else base,
    }


def _description(name: str) -> dict[str, object]:
    return {
        "type_name": name,
        "fields": [
            {"name": field, "type": _field_type(base, array)}
            for base, array, field in fields_of(name)
        ],
    }


def type_hash(name: str) -> str:
    """The type's hash as ROS 2 (Iron and later) computes it: ``RIHS01_<sha256>`` of the
    type description and every type it refers to (sorted by name), as compact JSON."""
    hashable = {
        "type_description": _description(name),
        "referenced_type_descriptions": [_description(d) for d in sorted(dependencies(name))],
    }
    text = json.dumps(hashable, ensure_ascii=True, separators=(", ", ": "), sort_keys=False)
    return "RIHS01_" + hashlib.sha256(text.encode("utf-8")).hexdigest()


def ros_type_of(dds_typename: str) -> str:
    """``sensor_msgs::msg::dds_::LaserScan_`` is ``sensor_msgs/msg/LaserScan``."""
    parts = dds_typename.split("::")
    if len(parts) != 4 or parts[2] != "dds_" or not parts[3].endswith("_"):
        raise ValueError(f"not a ROS 2 DDS type name: {dds_typename!r}")
    return f"{parts[0]}/{parts[1]}/{parts[3][:-1]}"
