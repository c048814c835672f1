// sensor_msgs/msg/LaserScan (ROS 2) <-> shelfdock's scan JSON (src/io/scan_json.hpp): the one
// place that knows both layouts. Field names are the same; ROS 2 stamps are {sec, nanosec}, ours
// are seconds; a range that is not a measurement is null in JSON.
import { parse } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";

export const SCHEMA_NAME = "sensor_msgs/msg/LaserScan";

// The ros2msg schema text rosbag2 stores for LaserScan: the message, then each dependency after a
// line of '=' and "MSG: <type>" (the layout `ros2 bag record` writes into MCAP).
export const SCHEMA_TEXT = [
  "std_msgs/Header header",
  "float32 angle_min",
  "float32 angle_max",
  "float32 angle_increment",
  "float32 time_increment",
  "float32 scan_time",
  "float32 range_min",
  "float32 range_max",
  "float32[] ranges",
  "float32[] intensities",
  "================================================================================",
  "MSG: std_msgs/Header",
  "builtin_interfaces/Time stamp",
  "string frame_id",
  "================================================================================",
  "MSG: builtin_interfaces/Time",
  "int32 sec",
  "uint32 nanosec",
  "",
].join("\n");

/// A CDR reader for the schema a recording carries (its own text, not ours: a recording made by
/// another ROS distribution still decodes as long as the fields exist).
export function makeReader(schemaText) {
  return new MessageReader(parse(schemaText, { ros2: true }));
}

export function makeWriter() {
  return new MessageWriter(parse(SCHEMA_TEXT, { ros2: true }));
}

/// ROS 2 message -> scan JSON. REP 117: a range outside [range_min, range_max) or not finite is
/// no measurement (null), as `shelfdock bag` does for ROS 1 bags.
export function messageToScan(msg) {
  const ranges = Array.from(msg.ranges, (r) =>
    Number.isFinite(r) && r >= msg.range_min && r < msg.range_max ? r : null,
  );
  const scan = {
    angle_min: msg.angle_min,
    angle_max: msg.angle_max,
    angle_increment: msg.angle_increment,
    range_min: msg.range_min,
    range_max: msg.range_max,
    ranges,
    time_increment: msg.time_increment,
    scan_time: msg.scan_time,
    stamp: msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9,
    frame_id: msg.header.frame_id,
  };
  if (msg.intensities.length === ranges.length) scan.intensities = Array.from(msg.intensities);
  return scan;
}

/// Stamp in seconds -> {sec, nanosec} (nanosec in [0, 1e9)).
export function stampToRos(stamp_s) {
  let sec = Math.floor(stamp_s);
  let nanosec = Math.round((stamp_s - sec) * 1e9);
  if (nanosec >= 1e9) {
    sec += 1;
    nanosec -= 1e9;
  }
  return { sec, nanosec };
}

/// Scan JSON -> ROS 2 message; null ranges become NaN (the float32 "no return").
export function scanToMessage(scan) {
  const ranges = Float32Array.from(scan.ranges, (r) => (r === null ? NaN : r));
  return {
    header: { stamp: stampToRos(scan.stamp ?? 0), frame_id: scan.frame_id ?? "lidar" },
    angle_min: scan.angle_min,
    angle_max: scan.angle_max,
    angle_increment: scan.angle_increment,
    time_increment: scan.time_increment ?? 0,
    scan_time: scan.scan_time ?? 0,
    range_min: scan.range_min,
    range_max: scan.range_max,
    ranges,
    intensities: Float32Array.from(scan.intensities ?? []),
  };
}
