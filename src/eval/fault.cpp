#include "eval/fault.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <random>

namespace shelfdock::eval {
namespace {

constexpr std::array kKinds{
    FaultKind::kNone,           FaultKind::kLidarBlackout,
    FaultKind::kSpuriousPoints, FaultKind::kLateScans,
    FaultKind::kDoubleScans,    FaultKind::kPersonCrossing,
    FaultKind::kPersonStanding, FaultKind::kRobotPassing,
    FaultKind::kOdometrySlip,   FaultKind::kLocalisationJump,
    FaultKind::kShelfDisplaced, FaultKind::kWrongShelfCode,
    FaultKind::kNoShelf,        FaultKind::kCameraBlind,
    FaultKind::kCameraPartial,
};

using docking::OutcomeCode;
// A shelf that is not where the map says is never recognised (its detections fall outside the
// preset gate); if it stands in the way, its legs block the path.
constexpr std::array kNotFound{OutcomeCode::kShelfNotFound, OutcomeCode::kWouldCollide};
constexpr std::array kAbsent{OutcomeCode::kShelfNotFound};
constexpr std::array kWrong{OutcomeCode::kWrongShelf};
constexpr std::array kBlind{OutcomeCode::kCodeNotFound};
// A person who stays in the path: the Docker waits, then reports the block.
constexpr std::array kBlocked{OutcomeCode::kWouldCollide, OutcomeCode::kNoPath};

}  // namespace

std::span<const FaultKind> AllFaultKinds() { return kKinds; }

std::string_view ToString(FaultKind kind) {
  switch (kind) {
    case FaultKind::kNone:
      return "none";
    case FaultKind::kLidarBlackout:
      return "lidar_blackout";
    case FaultKind::kSpuriousPoints:
      return "spurious_points";
    case FaultKind::kLateScans:
      return "late_scans";
    case FaultKind::kDoubleScans:
      return "double_scans";
    case FaultKind::kPersonCrossing:
      return "person_crossing";
    case FaultKind::kPersonStanding:
      return "person_standing";
    case FaultKind::kRobotPassing:
      return "robot_passing";
    case FaultKind::kOdometrySlip:
      return "odometry_slip";
    case FaultKind::kLocalisationJump:
      return "localisation_jump";
    case FaultKind::kShelfDisplaced:
      return "shelf_displaced";
    case FaultKind::kWrongShelfCode:
      return "wrong_shelf_code";
    case FaultKind::kNoShelf:
      return "no_shelf";
    case FaultKind::kCameraBlind:
      return "camera_blind";
    case FaultKind::kCameraPartial:
      return "camera_partial";
  }
  return "unknown";
}

FaultSpec DrawFault(std::uint64_t seed, const FaultDrawConfig& c) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 0x5EED);
  auto uniform = [&rng](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  FaultSpec f;
  // Stratified: the kinds take turns (any run of 15 consecutive seeds has each once), so a short
  // sweep covers them all; the parameters are drawn.
  f.kind = kKinds[seed % kKinds.size()];
  f.start_s = uniform(0.0, c.fault_window_s);
  switch (f.kind) {
    case FaultKind::kLidarBlackout:
      f.duration_s = uniform(0.05, c.max_blackout_s);
      break;
    case FaultKind::kSpuriousPoints:
      f.duration_s = uniform(0.1, 1.0);
      f.amount = std::floor(uniform(5.0, c.max_spurious_beams + 1.0));
      break;
    case FaultKind::kLateScans:
      f.duration_s = uniform(0.5, 3.0);
      f.amount = uniform(0.02, c.max_late_s);
      break;
    case FaultKind::kDoubleScans:
      f.duration_s = uniform(0.5, 3.0);
      break;
    case FaultKind::kPersonCrossing:
    case FaultKind::kRobotPassing:
      f.across_m = uniform(0.5, c.docking_length_m - 1.2);
      f.speed_mps = f.kind == FaultKind::kPersonCrossing ? uniform(0.5, 1.5) : uniform(0.3, 1.0);
      f.amount = uniform(0.0, 1.0);  // phase along the mover's path at t = 0
      break;
    case FaultKind::kPersonStanding:
      f.across_m = uniform(0.5, c.docking_length_m - 1.2);
      f.offset = geometry::Pose2(0.0, uniform(-0.15, 0.15), 0.0);
      break;
    case FaultKind::kOdometrySlip:
      f.duration_s = uniform(0.05, c.max_slip_s);
      f.amount = uniform(0.1, c.max_slip_ratio);
      break;
    case FaultKind::kLocalisationJump: {
      // Timed from the start of the run: the approach runs on localisation.
      f.start_s = uniform(0.0, 4.0);
      const double r = uniform(0.05, c.max_jump_m);
      const double a = uniform(-std::numbers::pi, std::numbers::pi);
      f.offset = geometry::Pose2(r * std::cos(a), r * std::sin(a), 0.0);
      break;
    }
    case FaultKind::kShelfDisplaced: {
      const double r = uniform(c.min_displacement_m, c.max_displacement_m);
      const double a = uniform(-std::numbers::pi, std::numbers::pi);
      f.offset = geometry::Pose2(r * std::cos(a), r * std::sin(a), uniform(-0.3, 0.3));
      break;
    }
    case FaultKind::kCameraPartial:
      f.amount = uniform(0.2, c.max_partial_share);
      break;
    case FaultKind::kNone:
    case FaultKind::kWrongShelfCode:
    case FaultKind::kNoShelf:
    case FaultKind::kCameraBlind:
      break;
  }
  return f;
}

bool DockingPossible(const FaultSpec& fault) { return ExpectedFailures(fault.kind).empty(); }

bool SuccessAcceptable(FaultKind kind) { return kind == FaultKind::kPersonStanding; }

std::span<const docking::OutcomeCode> ExpectedFailures(FaultKind kind) {
  switch (kind) {
    case FaultKind::kShelfDisplaced:
      return kNotFound;
    case FaultKind::kNoShelf:
      return kAbsent;
    case FaultKind::kWrongShelfCode:
      return kWrong;
    case FaultKind::kCameraBlind:
      return kBlind;
    case FaultKind::kPersonStanding:
      return kBlocked;
    default:
      return {};
  }
}

}  // namespace shelfdock::eval
