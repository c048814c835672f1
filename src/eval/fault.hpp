#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "docking/outcome.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::eval {

/// The faults `shelfdock eval faults` injects into a simulated docking (issue 10, item 6). One
/// fault per run, so that each outcome is owed to one cause; kNone is the control.
enum class FaultKind {
  kNone,
  kLidarBlackout,     ///< no scans for up to 1 s while docking
  kSpuriousPoints,    ///< bursts of false returns (dust, reflections) in the scans
  kLateScans,         ///< scans delivered up to 0.3 s late (stamped when taken)
  kDoubleScans,       ///< each scan delivered twice
  kPersonCrossing,    ///< a person walks across the docking path
  kPersonStanding,    ///< a person stands in the docking path and stays
  kRobotPassing,      ///< another robot drives across the docking path
  kOdometrySlip,      ///< the wheels slip: odometry over-reports the motion for a moment
  kLocalisationJump,  ///< the localisation estimate jumps by up to 0.3 m
  kShelfDisplaced,    ///< the shelf stands beyond the search area around its map pose
  kWrongShelfCode,    ///< the shelf at the map pose carries another shelf's code
  kNoShelf,           ///< no shelf at all
  kCameraBlind,       ///< the upward camera never sees the code
  kCameraPartial,     ///< the code is partly covered in some camera frames
};

/// Every kind, in the order of the enum (the order of the report's rows).
std::span<const FaultKind> AllFaultKinds();

/// Stable snake_case name ("lidar_blackout", ...), used in the report.
std::string_view ToString(FaultKind kind);

/// One drawn fault and its parameters (only those of its kind are used). Times are from the
/// docking area's entry unless said otherwise.
struct FaultSpec {
  FaultKind kind = FaultKind::kNone;
  double start_s = 0.0;     ///< [s] when a timed fault begins (after the entry)
  double duration_s = 0.0;  ///< [s] how long it lasts
  double amount =
      0.0;  ///< the fault's size: delay [s], slip ratio, beams per scan, share of frames
  geometry::Pose2 offset;  ///< localisation jump (map frame) or shelf displacement [m, rad]
  double across_m = 0.0;   ///< [m] where a mover crosses the docking path, from the entry
  double speed_mps = 0.0;  ///< [m/s] a mover's speed
};

/// Ranges the faults are drawn from.
struct FaultDrawConfig {
  double max_blackout_s = 1.0;      ///< [s]
  double max_late_s = 0.3;          ///< [s]
  double max_slip_ratio = 0.5;      ///< extra motion odometry reports while slipping
  double max_slip_s = 0.3;          ///< [s] a slip lasts at most this long
  double max_jump_m = 0.3;          ///< [m] localisation jump
  double min_displacement_m = 1.2;  ///< [m] beyond the tracker's preset gate (0.9 m)
  double max_displacement_m = 2.0;  ///< [m]
  double max_partial_share = 0.7;   ///< largest share of camera frames partly covered
  int max_spurious_beams = 60;      ///< false returns per scan in a burst
  double fault_window_s = 8.0;      ///< [s] timed faults start within this after the entry
  double docking_length_m = 4.5;    ///< [m] entry to goal (movers cross inside it)
};

/// The fault of run `seed`: the kind AllFaultKinds()[seed % 15] (each kind once in any 15
/// consecutive seeds), its parameters uniform in their ranges. Deterministic for a seed.
FaultSpec DrawFault(std::uint64_t seed, const FaultDrawConfig& config = {});

/// Whether docking stays possible under the fault, the rule the report checks:
///   possible  -- every fault that is transient or within what the Docker is built to absorb:
///                none, LiDAR blackout <= 1 s, spurious-point bursts, late or doubled scans, a
///                person or robot crossing (they leave), odometry slip, a localisation jump
///                <= 0.3 m, a code partly covered in at most 70 % of the frames. Each such run
///                must end in success.
///   impossible -- the shelf is not where the map says (displaced beyond the search area, or
///                absent), it is the wrong shelf, the camera is blind, or a person stands in the
///                path for good. Each such run must end in one of ExpectedFailures().
bool DockingPossible(const FaultSpec& fault);

/// The typed failures that are a correct end of an impossible run (empty for possible ones).
std::span<const docking::OutcomeCode> ExpectedFailures(FaultKind kind);

/// Whether success is also a correct end of an impossible run: a person standing in the path
/// blocks the docking area the map suggests, but the Docker may find the shelf's other end free
/// and dock from there (the true leg clearance is checked on every run all the same).
bool SuccessAcceptable(FaultKind kind);

}  // namespace shelfdock::eval
