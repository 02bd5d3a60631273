"""ROS 2 message types as Cyclone DDS IDL structs under their ROS 2 wire names.

This is an independent second implementation of the node's wire types (the
node's own are Rust structs in src/messages/types.rs): the integration tests
only pass if both agree byte for byte. Type `pkg/msg/T` travels as
`pkg::msg::dds_::T_`, service `pkg/srv/S` as `pkg::srv::dds_::S_Request_` /
`S_Response_`.
"""

from dataclasses import dataclass, field

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import float32, float64, int32, int64, sequence, uint8, uint32, uint64


# ---- builtin_interfaces / std_msgs -------------------------------------------

@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32 = 0
    nanosec: uint32 = 0

    def to_sec(self) -> float:
        return self.sec + self.nanosec * 1e-9

    def to_nanos(self) -> int:
        return self.sec * 1_000_000_000 + self.nanosec

    @staticmethod
    def from_nanos(n: int) -> "Time":
        return Time(sec=n // 1_000_000_000, nanosec=n % 1_000_000_000)


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time = field(default_factory=Time)
    frame_id: str = ""


@dataclass
class Float64(IdlStruct, typename="std_msgs::msg::dds_::Float64_"):
    data: float64 = 0.0


# ---- geometry_msgs -------------------------------------------------------------

@dataclass
class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0


@dataclass
class Quaternion(IdlStruct, typename="geometry_msgs::msg::dds_::Quaternion_"):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0
    w: float64 = 1.0


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
class Wrench(IdlStruct, typename="geometry_msgs::msg::dds_::Wrench_"):
    force: Vector3 = field(default_factory=Vector3)
    torque: Vector3 = field(default_factory=Vector3)


@dataclass
class WrenchStamped(IdlStruct, typename="geometry_msgs::msg::dds_::WrenchStamped_"):
    header: Header = field(default_factory=Header)
    wrench: Wrench = field(default_factory=Wrench)


# A deliberately wrong WrenchStamped: same wire name, only a header. The node
# receives a truncated sample it cannot decode ("undecodable").
@dataclass
class TruncatedWrenchStamped(IdlStruct, typename="geometry_msgs::msg::dds_::WrenchStamped_"):
    header: Header = field(default_factory=Header)


# ---- tf2_msgs, sensor_msgs, rosgraph_msgs, diagnostic_msgs ----------------------

@dataclass
class TFMessage(IdlStruct, typename="tf2_msgs::msg::dds_::TFMessage_"):
    transforms: sequence[TransformStamped] = field(default_factory=list)


@dataclass
class JointState(IdlStruct, typename="sensor_msgs::msg::dds_::JointState_"):
    header: Header = field(default_factory=Header)
    name: sequence[str] = field(default_factory=list)
    position: sequence[float64] = field(default_factory=list)
    velocity: sequence[float64] = field(default_factory=list)
    effort: sequence[float64] = field(default_factory=list)


@dataclass
class Clock(IdlStruct, typename="rosgraph_msgs::msg::dds_::Clock_"):
    clock: Time = field(default_factory=Time)


@dataclass
class KeyValue(IdlStruct, typename="diagnostic_msgs::msg::dds_::KeyValue_"):
    key: str = ""
    value: str = ""


@dataclass
class DiagnosticStatus(IdlStruct, typename="diagnostic_msgs::msg::dds_::DiagnosticStatus_"):
    level: uint8 = 0
    name: str = ""
    message: str = ""
    hardware_id: str = ""
    values: sequence[KeyValue] = field(default_factory=list)


@dataclass
class DiagnosticArray(IdlStruct, typename="diagnostic_msgs::msg::dds_::DiagnosticArray_"):
    header: Header = field(default_factory=Header)
    status: sequence[DiagnosticStatus] = field(default_factory=list)


@dataclass
class Log(IdlStruct, typename="rcl_interfaces::msg::dds_::Log_"):
    stamp: Time = field(default_factory=Time)
    level: uint8 = 0
    name: str = ""
    msg: str = ""
    file: str = ""
    function: str = ""
    line: uint32 = 0


# ---- annular_plate (msg/, srv/) ---------------------------------------------------

@dataclass
class ModalAmplitudes(IdlStruct, typename="annular_plate::msg::dds_::ModalAmplitudes_"):
    header: Header = field(default_factory=Header)
    step: uint64 = 0
    sim_time: float64 = 0.0
    input_stamp: Time = field(default_factory=Time)
    k: sequence[uint32] = field(default_factory=list)
    l: sequence[uint32] = field(default_factory=list)
    shape: sequence[uint8] = field(default_factory=list)
    frequency_hz: sequence[float64] = field(default_factory=list)
    q_lagrange: sequence[float64] = field(default_factory=list)
    q_dot_lagrange: sequence[float64] = field(default_factory=list)
    q_ale: sequence[float64] = field(default_factory=list)
    q_dot_ale: sequence[float64] = field(default_factory=list)


@dataclass
class CriticalSpeeds(IdlStruct, typename="annular_plate::msg::dds_::CriticalSpeeds_"):
    centrifugal_stiffening: bool = False
    k: sequence[uint32] = field(default_factory=list)
    l: sequence[uint32] = field(default_factory=list)
    rad_s: sequence[float64] = field(default_factory=list)


@dataclass
class NodeWrench(IdlStruct, typename="annular_plate::msg::dds_::NodeWrench_"):
    kind: uint8 = 0
    index: uint32 = 0
    wrench: Wrench = field(default_factory=Wrench)


NODE_WRENCH_ALE = 0
NODE_WRENCH_LAGRANGE = 1


@dataclass
class NodeWrenchArray(IdlStruct, typename="annular_plate::msg::dds_::NodeWrenchArray_"):
    header: Header = field(default_factory=Header)
    wrenches: sequence[NodeWrench] = field(default_factory=list)


@dataclass
class PadClampForces(IdlStruct, typename="annular_plate::msg::dds_::PadClampForces_"):
    header: Header = field(default_factory=Header)
    pad: sequence[uint32] = field(default_factory=list)
    clamp_force: sequence[float64] = field(default_factory=list)


@dataclass
class PadStates(IdlStruct, typename="annular_plate::msg::dds_::PadStates_"):
    header: Header = field(default_factory=Header)
    step: uint64 = 0
    sim_time: float64 = 0.0
    clamp_force: sequence[float64] = field(default_factory=list)
    normal_force: sequence[float64] = field(default_factory=list)
    friction_force: sequence[float64] = field(default_factory=list)
    friction_torque: sequence[float64] = field(default_factory=list)
    contact_pad: sequence[uint32] = field(default_factory=list)
    contact_ale_node: sequence[uint32] = field(default_factory=list)
    contact_normal_top: sequence[float64] = field(default_factory=list)
    contact_normal_bottom: sequence[float64] = field(default_factory=list)
    contact_friction: sequence[float64] = field(default_factory=list)
    pad_compression_top: sequence[float64] = field(default_factory=list)
    pad_compression_bottom: sequence[float64] = field(default_factory=list)
    contact_patch_top_radial: sequence[float64] = field(default_factory=list)
    contact_patch_top_tangential: sequence[float64] = field(default_factory=list)
    contact_patch_bottom_radial: sequence[float64] = field(default_factory=list)
    contact_patch_bottom_tangential: sequence[float64] = field(default_factory=list)
    contact_slip_top: sequence[float64] = field(default_factory=list)
    contact_slip_bottom: sequence[float64] = field(default_factory=list)


@dataclass
class ToolState(IdlStruct, typename="annular_plate::msg::dds_::ToolState_"):
    header: Header = field(default_factory=Header)
    step: uint64 = 0
    sim_time: float64 = 0.0
    feed_rate: float64 = 0.0
    tip_z: float64 = 0.0
    chip_thickness: float64 = 0.0
    feed_force: float64 = 0.0


# ---- services -------------------------------------------------------------------
# With the default "enhanced" service mapping (rmw_fastrtps) the request is
# the bare request struct; the reply correlates through an inline QoS the
# Python binding does not expose, so the peer pairs replies by order (one
# outstanding call at a time). With ros.service_mapping: cyclone, both carry
# the rmw_cyclonedds header first (`CycloneHeader` below).

# ---- visualization_msgs (Humble / Jazzy) -------------------------------------------

@dataclass
class Duration(IdlStruct, typename="builtin_interfaces::msg::dds_::Duration_"):
    sec: int32 = 0
    nanosec: uint32 = 0


@dataclass
class ColorRGBA(IdlStruct, typename="std_msgs::msg::dds_::ColorRGBA_"):
    r: float32 = 0.0
    g: float32 = 0.0
    b: float32 = 0.0
    a: float32 = 0.0


@dataclass
class Point(IdlStruct, typename="geometry_msgs::msg::dds_::Point_"):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0


@dataclass
class Pose(IdlStruct, typename="geometry_msgs::msg::dds_::Pose_"):
    position: Point = field(default_factory=Point)
    orientation: Quaternion = field(default_factory=Quaternion)


@dataclass
class CompressedImage(IdlStruct, typename="sensor_msgs::msg::dds_::CompressedImage_"):
    header: Header = field(default_factory=Header)
    format: str = ""
    data: sequence[uint8] = field(default_factory=list)


@dataclass
class UVCoordinate(IdlStruct, typename="visualization_msgs::msg::dds_::UVCoordinate_"):
    u: float32 = 0.0
    v: float32 = 0.0


@dataclass
class MeshFile(IdlStruct, typename="visualization_msgs::msg::dds_::MeshFile_"):
    filename: str = ""
    data: sequence[uint8] = field(default_factory=list)


@dataclass
class Marker(IdlStruct, typename="visualization_msgs::msg::dds_::Marker_"):
    header: Header = field(default_factory=Header)
    ns: str = ""
    id: int32 = 0
    type: int32 = 0
    action: int32 = 0
    pose: Pose = field(default_factory=Pose)
    scale: Vector3 = field(default_factory=Vector3)
    color: ColorRGBA = field(default_factory=ColorRGBA)
    lifetime: Duration = field(default_factory=Duration)
    frame_locked: bool = False
    points: sequence[Point] = field(default_factory=list)
    colors: sequence[ColorRGBA] = field(default_factory=list)
    texture_resource: str = ""
    texture: CompressedImage = field(default_factory=CompressedImage)
    uv_coordinates: sequence[UVCoordinate] = field(default_factory=list)
    text: str = ""
    mesh_resource: str = ""
    mesh_file: MeshFile = field(default_factory=MeshFile)
    mesh_use_embedded_materials: bool = False


@dataclass
class MarkerArray(IdlStruct, typename="visualization_msgs::msg::dds_::MarkerArray_"):
    markers: sequence[Marker] = field(default_factory=list)


@dataclass
class TriggerRequest(IdlStruct, typename="std_srvs::srv::dds_::Trigger_Request_"):
    structure_needs_at_least_one_member: uint8 = 0


@dataclass
class TriggerResponse(IdlStruct, typename="std_srvs::srv::dds_::Trigger_Response_"):
    success: bool = False
    message: str = ""


@dataclass
class SetBoolRequest(IdlStruct, typename="std_srvs::srv::dds_::SetBool_Request_"):
    data: bool = False


@dataclass
class SetBoolResponse(IdlStruct, typename="std_srvs::srv::dds_::SetBool_Response_"):
    success: bool = False
    message: str = ""


@dataclass
class StepRequest(IdlStruct, typename="annular_plate::srv::dds_::Step_Request_"):
    steps: uint32 = 0


@dataclass
class StepResponse(IdlStruct, typename="annular_plate::srv::dds_::Step_Response_"):
    success: bool = False
    message: str = ""
    step: uint64 = 0
    sim_time: float64 = 0.0


# The same Step service as rmw_cyclonedds_cpp frames it: a request header
# (client id, sequence number) before the payload, echoed in the reply.
@dataclass
class CycloneStepRequest(IdlStruct, typename="annular_plate::srv::dds_::Step_Request_"):
    client: uint64 = 0
    seq: int64 = 0
    steps: uint32 = 0


@dataclass
class CycloneStepResponse(IdlStruct, typename="annular_plate::srv::dds_::Step_Response_"):
    client: uint64 = 0
    seq: int64 = 0
    success: bool = False
    message: str = ""
    step: uint64 = 0
    sim_time: float64 = 0.0


# rcl_interfaces (parameter services)

@dataclass
class ParameterValue(IdlStruct, typename="rcl_interfaces::msg::dds_::ParameterValue_"):
    type: uint8 = 0
    bool_value: bool = False
    integer_value: int64 = 0
    double_value: float64 = 0.0
    string_value: str = ""
    byte_array_value: sequence[uint8] = field(default_factory=list)
    bool_array_value: sequence[bool] = field(default_factory=list)
    integer_array_value: sequence[int64] = field(default_factory=list)
    double_array_value: sequence[float64] = field(default_factory=list)
    string_array_value: sequence[str] = field(default_factory=list)


@dataclass
class Parameter(IdlStruct, typename="rcl_interfaces::msg::dds_::Parameter_"):
    name: str = ""
    value: ParameterValue = field(default_factory=ParameterValue)


@dataclass
class SetParametersResult(IdlStruct, typename="rcl_interfaces::msg::dds_::SetParametersResult_"):
    successful: bool = False
    reason: str = ""


@dataclass
class ListParametersResult(IdlStruct, typename="rcl_interfaces::msg::dds_::ListParametersResult_"):
    names: sequence[str] = field(default_factory=list)
    prefixes: sequence[str] = field(default_factory=list)


@dataclass
class ListParametersRequest(IdlStruct, typename="rcl_interfaces::srv::dds_::ListParameters_Request_"):
    prefixes: sequence[str] = field(default_factory=list)
    depth: uint64 = 0


@dataclass
class ListParametersResponse(IdlStruct, typename="rcl_interfaces::srv::dds_::ListParameters_Response_"):
    result: ListParametersResult = field(default_factory=ListParametersResult)


@dataclass
class GetParametersRequest(IdlStruct, typename="rcl_interfaces::srv::dds_::GetParameters_Request_"):
    names: sequence[str] = field(default_factory=list)


@dataclass
class GetParametersResponse(IdlStruct, typename="rcl_interfaces::srv::dds_::GetParameters_Response_"):
    values: sequence[ParameterValue] = field(default_factory=list)


@dataclass
class GetParameterTypesRequest(IdlStruct, typename="rcl_interfaces::srv::dds_::GetParameterTypes_Request_"):
    names: sequence[str] = field(default_factory=list)


@dataclass
class GetParameterTypesResponse(IdlStruct, typename="rcl_interfaces::srv::dds_::GetParameterTypes_Response_"):
    types: sequence[uint8] = field(default_factory=list)


@dataclass
class FloatingPointRange(IdlStruct, typename="rcl_interfaces::msg::dds_::FloatingPointRange_"):
    from_value: float64 = 0.0
    to_value: float64 = 0.0
    step: float64 = 0.0


@dataclass
class IntegerRange(IdlStruct, typename="rcl_interfaces::msg::dds_::IntegerRange_"):
    from_value: int64 = 0
    to_value: int64 = 0
    step: uint64 = 0


@dataclass
class ParameterDescriptor(IdlStruct, typename="rcl_interfaces::msg::dds_::ParameterDescriptor_"):
    name: str = ""
    type: uint8 = 0
    description: str = ""
    additional_constraints: str = ""
    read_only: bool = False
    dynamic_typing: bool = False
    floating_point_range: sequence[FloatingPointRange] = field(default_factory=list)
    integer_range: sequence[IntegerRange] = field(default_factory=list)


@dataclass
class DescribeParametersRequest(IdlStruct, typename="rcl_interfaces::srv::dds_::DescribeParameters_Request_"):
    names: sequence[str] = field(default_factory=list)


@dataclass
class DescribeParametersResponse(IdlStruct, typename="rcl_interfaces::srv::dds_::DescribeParameters_Response_"):
    descriptors: sequence[ParameterDescriptor] = field(default_factory=list)


@dataclass
class SetParametersRequest(IdlStruct, typename="rcl_interfaces::srv::dds_::SetParameters_Request_"):
    parameters: sequence[Parameter] = field(default_factory=list)


@dataclass
class SetParametersResponse(IdlStruct, typename="rcl_interfaces::srv::dds_::SetParameters_Response_"):
    results: sequence[SetParametersResult] = field(default_factory=list)


# Parameter types (rcl_interfaces/msg/ParameterType)
PARAMETER_NOT_SET = 0
PARAMETER_BOOL = 1
PARAMETER_INTEGER = 2
PARAMETER_DOUBLE = 3
PARAMETER_STRING = 4
PARAMETER_DOUBLE_ARRAY = 8


# ---- simulation_interfaces (1.0/2.0, Humble to Rolling) ---------------------

@dataclass
class SimResult(IdlStruct, typename="simulation_interfaces::msg::dds_::Result_"):
    result: uint8 = 0
    error_message: str = ""


@dataclass
class SimulationState(IdlStruct, typename="simulation_interfaces::msg::dds_::SimulationState_"):
    state: uint8 = 0


@dataclass
class ResetSimulationRequest(IdlStruct, typename="simulation_interfaces::srv::dds_::ResetSimulation_Request_"):
    scope: uint8 = 0


@dataclass
class ResetSimulationResponse(IdlStruct, typename="simulation_interfaces::srv::dds_::ResetSimulation_Response_"):
    result: SimResult = field(default_factory=SimResult)


@dataclass
class StepSimulationRequest(IdlStruct, typename="simulation_interfaces::srv::dds_::StepSimulation_Request_"):
    steps: uint64 = 1


@dataclass
class StepSimulationResponse(IdlStruct, typename="simulation_interfaces::srv::dds_::StepSimulation_Response_"):
    result: SimResult = field(default_factory=SimResult)


@dataclass
class GetSimulationStateRequest(IdlStruct, typename="simulation_interfaces::srv::dds_::GetSimulationState_Request_"):
    structure_needs_at_least_one_member: uint8 = 0


@dataclass
class GetSimulationStateResponse(IdlStruct, typename="simulation_interfaces::srv::dds_::GetSimulationState_Response_"):
    state: SimulationState = field(default_factory=SimulationState)
    result: SimResult = field(default_factory=SimResult)


@dataclass
class SetSimulationStateRequest(IdlStruct, typename="simulation_interfaces::srv::dds_::SetSimulationState_Request_"):
    state: SimulationState = field(default_factory=SimulationState)


@dataclass
class SetSimulationStateResponse(IdlStruct, typename="simulation_interfaces::srv::dds_::SetSimulationState_Response_"):
    result: SimResult = field(default_factory=SimResult)
