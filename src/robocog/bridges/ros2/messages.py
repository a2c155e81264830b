"""ROS 2 message layouts as Cyclone DDS types, named as rmw_cyclonedds names them.

A ROS 2 message ``pkg/msg/Name`` travels on DDS as the type ``pkg::msg::dds_::Name_``,
a final (non-extensible) struct in plain CDR. Declaring the same layouts here, field for
field and in the same order, is all it takes for real ROS 2 nodes to see this traffic;
no ROS installation is needed. vision_msgs follows the Humble (4.x) layout, where a
hypothesis nests ``ObjectHypothesis`` and a box centre is ``vision_msgs/Pose2D``.
"""

from dataclasses import dataclass, field
from typing import Any

import cyclonedds.idl.types as t
from cyclonedds.idl import IdlStruct


def _zeros36() -> list[float]:
    return [0.0] * 36


# -- builtin_interfaces, std_msgs ----------------------------------------------------


@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: t.int32 = 0
    nanosec: t.uint32 = 0


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time = field(default_factory=Time)
    frame_id: str = ""


@dataclass
class String(IdlStruct, typename="std_msgs::msg::dds_::String_"):
    data: str = ""


# -- geometry_msgs -------------------------------------------------------------------


@dataclass
class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
    x: t.float64 = 0.0
    y: t.float64 = 0.0
    z: t.float64 = 0.0


@dataclass
class Point(IdlStruct, typename="geometry_msgs::msg::dds_::Point_"):
    x: t.float64 = 0.0
    y: t.float64 = 0.0
    z: t.float64 = 0.0


@dataclass
class Quaternion(IdlStruct, typename="geometry_msgs::msg::dds_::Quaternion_"):
    x: t.float64 = 0.0
    y: t.float64 = 0.0
    z: t.float64 = 0.0
    w: t.float64 = 1.0


@dataclass
class Pose(IdlStruct, typename="geometry_msgs::msg::dds_::Pose_"):
    position: Point = field(default_factory=Point)
    orientation: Quaternion = field(default_factory=Quaternion)


@dataclass
class PoseStamped(IdlStruct, typename="geometry_msgs::msg::dds_::PoseStamped_"):
    header: Header = field(default_factory=Header)
    pose: Pose = field(default_factory=Pose)


@dataclass
class PoseWithCovariance(IdlStruct, typename="geometry_msgs::msg::dds_::PoseWithCovariance_"):
    pose: Pose = field(default_factory=Pose)
    covariance: t.array[t.float64, 36] = field(default_factory=_zeros36)


@dataclass
class PoseWithCovarianceStamped(
    IdlStruct, typename="geometry_msgs::msg::dds_::PoseWithCovarianceStamped_"
):
    header: Header = field(default_factory=Header)
    pose: PoseWithCovariance = field(default_factory=PoseWithCovariance)


@dataclass
class Twist(IdlStruct, typename="geometry_msgs::msg::dds_::Twist_"):
    linear: Vector3 = field(default_factory=Vector3)
    angular: Vector3 = field(default_factory=Vector3)


@dataclass
class TwistWithCovariance(IdlStruct, typename="geometry_msgs::msg::dds_::TwistWithCovariance_"):
    twist: Twist = field(default_factory=Twist)
    covariance: t.array[t.float64, 36] = field(default_factory=_zeros36)


# -- nav_msgs, sensor_msgs -----------------------------------------------------------


@dataclass
class Odometry(IdlStruct, typename="nav_msgs::msg::dds_::Odometry_"):
    header: Header = field(default_factory=Header)
    child_frame_id: str = ""
    pose: PoseWithCovariance = field(default_factory=PoseWithCovariance)
    twist: TwistWithCovariance = field(default_factory=TwistWithCovariance)


@dataclass
class LaserScan(IdlStruct, typename="sensor_msgs::msg::dds_::LaserScan_"):
    header: Header = field(default_factory=Header)
    angle_min: t.float32 = 0.0
    angle_max: t.float32 = 0.0
    angle_increment: t.float32 = 0.0
    time_increment: t.float32 = 0.0
    scan_time: t.float32 = 0.0
    range_min: t.float32 = 0.0
    range_max: t.float32 = 0.0
    ranges: t.sequence[t.float32] = field(default_factory=list)
    intensities: t.sequence[t.float32] = field(default_factory=list)


# -- vision_msgs (Humble and later) --------------------------------------------------


@dataclass
class Point2D(IdlStruct, typename="vision_msgs::msg::dds_::Point2D_"):
    x: t.float64 = 0.0
    y: t.float64 = 0.0


@dataclass
class Pose2D(IdlStruct, typename="vision_msgs::msg::dds_::Pose2D_"):
    position: Point2D = field(default_factory=Point2D)
    theta: t.float64 = 0.0


@dataclass
class BoundingBox2D(IdlStruct, typename="vision_msgs::msg::dds_::BoundingBox2D_"):
    center: Pose2D = field(default_factory=Pose2D)
    size_x: t.float64 = 0.0
    size_y: t.float64 = 0.0


@dataclass
class ObjectHypothesis(IdlStruct, typename="vision_msgs::msg::dds_::ObjectHypothesis_"):
    class_id: str = ""
    score: t.float64 = 0.0


@dataclass
class ObjectHypothesisWithPose(
    IdlStruct, typename="vision_msgs::msg::dds_::ObjectHypothesisWithPose_"
):
    hypothesis: ObjectHypothesis = field(default_factory=ObjectHypothesis)
    pose: PoseWithCovariance = field(default_factory=PoseWithCovariance)


@dataclass
class Detection2D(IdlStruct, typename="vision_msgs::msg::dds_::Detection2D_"):
    header: Header = field(default_factory=Header)
    results: t.sequence[ObjectHypothesisWithPose] = field(default_factory=list)
    bbox: BoundingBox2D = field(default_factory=BoundingBox2D)
    id: str = ""


@dataclass
class Detection2DArray(IdlStruct, typename="vision_msgs::msg::dds_::Detection2DArray_"):
    header: Header = field(default_factory=Header)
    detections: t.sequence[Detection2D] = field(default_factory=list)


# -- actions: the cancel service of a ROS 2 action -----------------------------------


@dataclass
class UUID(IdlStruct, typename="unique_identifier_msgs::msg::dds_::UUID_"):
    uuid: t.array[t.uint8, 16] = field(default_factory=lambda: [0] * 16)


@dataclass
class GoalInfo(IdlStruct, typename="action_msgs::msg::dds_::GoalInfo_"):
    goal_id: UUID = field(default_factory=UUID)
    stamp: Time = field(default_factory=Time)


@dataclass
class CancelGoalRequest(IdlStruct, typename="action_msgs::srv::dds_::CancelGoal_Request_"):
    """rmw_cyclonedds puts a request header (the client's id and a sequence number)
    before the request itself; a zero goal id and a zero stamp cancel every goal."""

    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    goal_info: GoalInfo = field(default_factory=GoalInfo)


def stamp_now(now: float) -> Time:
    """A ROS time from seconds since the epoch."""
    sec = int(now)
    return Time(sec, int((now - sec) * 1e9))


def topic_name(ros_name: str, prefix: str = "rt") -> str:
    """The DDS topic of a ROS 2 name: ``/scan`` is ``rt/scan``, a service request
    ``rq/<name>Request``. A name must be absolute or relative without a ``~``."""
    name = ros_name.strip()
    if not name or "~" in name or "//" in name:
        raise ValueError(f"not a usable ROS 2 topic name: {ros_name!r}")
    return f"{prefix}/{name.lstrip('/')}"


# -- more of a mobile manipulator's interfaces ----------------------------------------


@dataclass
class Duration(IdlStruct, typename="builtin_interfaces::msg::dds_::Duration_"):
    sec: t.int32 = 0
    nanosec: t.uint32 = 0


@dataclass
class Clock(IdlStruct, typename="rosgraph_msgs::msg::dds_::Clock_"):
    clock: Time = field(default_factory=Time)


@dataclass
class Transform(IdlStruct, typename="geometry_msgs::msg::dds_::Transform_"):
    translation: Vector3 = field(default_factory=Vector3)
    rotation: Quaternion = field(default_factory=Quaternion)


@dataclass
class TransformStamped(IdlStruct, typename="geometry_msgs::msg::dds_::TransformStamped_"):
    header: Header = field(default_factory=Header)
    child_frame_id: str = ""
    transform: Transform = field(default_factory=Transform)


@dataclass
class TFMessage(IdlStruct, typename="tf2_msgs::msg::dds_::TFMessage_"):
    transforms: t.sequence[TransformStamped] = field(default_factory=list)


@dataclass
class JointState(IdlStruct, typename="sensor_msgs::msg::dds_::JointState_"):
    header: Header = field(default_factory=Header)
    name: t.sequence[str] = field(default_factory=list)
    position: t.sequence[t.float64] = field(default_factory=list)
    velocity: t.sequence[t.float64] = field(default_factory=list)
    effort: t.sequence[t.float64] = field(default_factory=list)


@dataclass
class Float64(IdlStruct, typename="std_msgs::msg::dds_::Float64_"):
    data: t.float64 = 0.0


@dataclass
class Image(IdlStruct, typename="sensor_msgs::msg::dds_::Image_"):
    header: Header = field(default_factory=Header)
    height: t.uint32 = 0
    width: t.uint32 = 0
    encoding: str = ""
    is_bigendian: t.uint8 = 0
    step: t.uint32 = 0
    data: t.sequence[t.uint8] = field(default_factory=list)


def rgb8(header: Header, pixels: Any) -> Image:
    """An ``rgb8`` Image of a height x width x 3 array of bytes (a rendered camera frame);
    the pixels go as bytes, which serialize as the ``uint8[]`` they are."""
    height, width = int(pixels.shape[0]), int(pixels.shape[1])
    return Image(header, height, width, "rgb8", 0, width * 3, pixels.tobytes())


@dataclass
class RegionOfInterest(IdlStruct, typename="sensor_msgs::msg::dds_::RegionOfInterest_"):
    x_offset: t.uint32 = 0
    y_offset: t.uint32 = 0
    height: t.uint32 = 0
    width: t.uint32 = 0
    do_rectify: bool = False


@dataclass
class CameraInfo(IdlStruct, typename="sensor_msgs::msg::dds_::CameraInfo_"):
    header: Header = field(default_factory=Header)
    height: t.uint32 = 0
    width: t.uint32 = 0
    distortion_model: str = ""
    d: t.sequence[t.float64] = field(default_factory=list)
    k: t.array[t.float64, 9] = field(default_factory=lambda: [0.0] * 9)
    r: t.array[t.float64, 9] = field(default_factory=lambda: [0.0] * 9)
    p: t.array[t.float64, 12] = field(default_factory=lambda: [0.0] * 12)
    binning_x: t.uint32 = 0
    binning_y: t.uint32 = 0
    roi: RegionOfInterest = field(default_factory=RegionOfInterest)


def pinhole(header: Header, width: int, height: int, focal: float) -> CameraInfo:
    """The CameraInfo of an ideal pinhole camera (square pixels of ``focal`` px, the
    principal point in the middle, no distortion), as a rendered camera is."""
    cx, cy = width / 2.0, height / 2.0
    k = [focal, 0.0, cx, 0.0, focal, cy, 0.0, 0.0, 1.0]
    r = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    p = [focal, 0.0, cx, 0.0, 0.0, focal, cy, 0.0, 0.0, 0.0, 1.0, 0.0]
    return CameraInfo(header, height, width, "plumb_bob", [0.0] * 5, k, r, p)


def _zeros9() -> list[float]:
    return [0.0] * 9


@dataclass
class Imu(IdlStruct, typename="sensor_msgs::msg::dds_::Imu_"):
    header: Header = field(default_factory=Header)
    orientation: Quaternion = field(default_factory=Quaternion)
    orientation_covariance: t.array[t.float64, 9] = field(default_factory=_zeros9)
    angular_velocity: Vector3 = field(default_factory=Vector3)
    angular_velocity_covariance: t.array[t.float64, 9] = field(default_factory=_zeros9)
    linear_acceleration: Vector3 = field(default_factory=Vector3)
    linear_acceleration_covariance: t.array[t.float64, 9] = field(default_factory=_zeros9)


#: sensor_msgs/Range radiation types (the layout is Jazzy's, with ``variance``)
ULTRASOUND, INFRARED = 0, 1


@dataclass
class Range(IdlStruct, typename="sensor_msgs::msg::dds_::Range_"):
    header: Header = field(default_factory=Header)
    radiation_type: t.uint8 = ULTRASOUND
    field_of_view: t.float32 = 0.0
    min_range: t.float32 = 0.0
    max_range: t.float32 = 0.0
    range: t.float32 = 0.0
    variance: t.float32 = 0.0  # since ROS 2 Jazzy


# -- ROS 2 actions: goal status, and the services every action has ----------------------

#: action_msgs/GoalStatus codes
STATUS_UNKNOWN, STATUS_ACCEPTED, STATUS_EXECUTING, STATUS_CANCELING = 0, 1, 2, 3
STATUS_SUCCEEDED, STATUS_CANCELED, STATUS_ABORTED = 4, 5, 6
#: status code -> the word the bridge's body uses
STATUS_WORDS = {
    STATUS_SUCCEEDED: "succeeded",
    STATUS_CANCELED: "canceled",
    STATUS_ABORTED: "aborted",
    STATUS_UNKNOWN: "unknown",
}


@dataclass
class GoalStatus(IdlStruct, typename="action_msgs::msg::dds_::GoalStatus_"):
    goal_info: GoalInfo = field(default_factory=GoalInfo)
    status: t.int8 = 0


@dataclass
class GoalStatusArray(IdlStruct, typename="action_msgs::msg::dds_::GoalStatusArray_"):
    status_list: t.sequence[GoalStatus] = field(default_factory=list)


@dataclass
class CancelGoalResponse(IdlStruct, typename="action_msgs::srv::dds_::CancelGoal_Response_"):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    return_code: t.int8 = 0
    goals_canceling: t.sequence[GoalInfo] = field(default_factory=list)


# -- nav2_msgs/action/NavigateToPose (Jazzy) ----------------------------------------------


@dataclass
class NavigateToPoseGoal(IdlStruct, typename="nav2_msgs::action::dds_::NavigateToPose_Goal_"):
    pose: PoseStamped = field(default_factory=PoseStamped)
    behavior_tree: str = ""


@dataclass
class NavigateToPoseResult(IdlStruct, typename="nav2_msgs::action::dds_::NavigateToPose_Result_"):
    error_code: t.uint16 = 0
    error_msg: str = ""


@dataclass
class NavigateToPoseFeedback(
    IdlStruct, typename="nav2_msgs::action::dds_::NavigateToPose_Feedback_"
):
    current_pose: PoseStamped = field(default_factory=PoseStamped)
    navigation_time: Duration = field(default_factory=Duration)
    estimated_time_remaining: Duration = field(default_factory=Duration)
    number_of_recoveries: t.int16 = 0
    distance_remaining: t.float32 = 0.0


@dataclass
class NavigateToPoseSendGoalRequest(
    IdlStruct, typename="nav2_msgs::action::dds_::NavigateToPose_SendGoal_Request_"
):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    goal_id: UUID = field(default_factory=UUID)
    goal: NavigateToPoseGoal = field(default_factory=NavigateToPoseGoal)


@dataclass
class NavigateToPoseSendGoalResponse(
    IdlStruct, typename="nav2_msgs::action::dds_::NavigateToPose_SendGoal_Response_"
):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    accepted: bool = False
    stamp: Time = field(default_factory=Time)


@dataclass
class NavigateToPoseGetResultRequest(
    IdlStruct, typename="nav2_msgs::action::dds_::NavigateToPose_GetResult_Request_"
):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    goal_id: UUID = field(default_factory=UUID)


@dataclass
class NavigateToPoseGetResultResponse(
    IdlStruct, typename="nav2_msgs::action::dds_::NavigateToPose_GetResult_Response_"
):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    status: t.int8 = 0
    result: NavigateToPoseResult = field(default_factory=NavigateToPoseResult)


@dataclass
class NavigateToPoseFeedbackMessage(
    IdlStruct, typename="nav2_msgs::action::dds_::NavigateToPose_FeedbackMessage_"
):
    goal_id: UUID = field(default_factory=UUID)
    feedback: NavigateToPoseFeedback = field(default_factory=NavigateToPoseFeedback)


# -- robocog_msgs/action/Grasp (shipped as robocog/bridges/ros2/interfaces/Grasp.action) --


@dataclass
class GraspGoal(IdlStruct, typename="robocog_msgs::action::dds_::Grasp_Goal_"):
    command: str = ""
    target: str = ""


@dataclass
class GraspResult(IdlStruct, typename="robocog_msgs::action::dds_::Grasp_Result_"):
    success: bool = False
    message: str = ""
    holding: str = ""


@dataclass
class GraspFeedback(IdlStruct, typename="robocog_msgs::action::dds_::Grasp_Feedback_"):
    phase: str = ""


@dataclass
class GraspSendGoalRequest(
    IdlStruct, typename="robocog_msgs::action::dds_::Grasp_SendGoal_Request_"
):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    goal_id: UUID = field(default_factory=UUID)
    goal: GraspGoal = field(default_factory=GraspGoal)


@dataclass
class GraspSendGoalResponse(
    IdlStruct, typename="robocog_msgs::action::dds_::Grasp_SendGoal_Response_"
):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    accepted: bool = False
    stamp: Time = field(default_factory=Time)


@dataclass
class GraspGetResultRequest(
    IdlStruct, typename="robocog_msgs::action::dds_::Grasp_GetResult_Request_"
):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    goal_id: UUID = field(default_factory=UUID)


@dataclass
class GraspGetResultResponse(
    IdlStruct, typename="robocog_msgs::action::dds_::Grasp_GetResult_Response_"
):
    client_guid: t.uint64 = 0
    sequence_number: t.int64 = 0
    status: t.int8 = 0
    result: GraspResult = field(default_factory=GraspResult)


@dataclass
class GraspFeedbackMessage(
    IdlStruct, typename="robocog_msgs::action::dds_::Grasp_FeedbackMessage_"
):
    goal_id: UUID = field(default_factory=UUID)
    feedback: GraspFeedback = field(default_factory=GraspFeedback)


@dataclass(frozen=True)
class ActionTypes:
    """The wire types of one ROS 2 action: its three services and its feedback."""

    send_goal_request: type
    send_goal_response: type
    get_result_request: type
    get_result_response: type
    feedback_message: type


NAVIGATE_TO_POSE = ActionTypes(
    NavigateToPoseSendGoalRequest,
    NavigateToPoseSendGoalResponse,
    NavigateToPoseGetResultRequest,
    NavigateToPoseGetResultResponse,
    NavigateToPoseFeedbackMessage,
)
GRASP = ActionTypes(
    GraspSendGoalRequest,
    GraspSendGoalResponse,
    GraspGetResultRequest,
    GraspGetResultResponse,
    GraspFeedbackMessage,
)


def seconds_of(stamp: Time) -> float:
    """Seconds of a ROS time."""
    return stamp.sec + stamp.nanosec * 1e-9
