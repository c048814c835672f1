// FineAdjust: from a few-mm / few-mrad offset the moves end on the goal, never turn more than
// the lever angle away from it, and never reverse farther than the lever needs.
#include "docking/fine_adjust.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {

using geometry::Pose2;

struct AdjustOutcome {
  Pose2 T_goal_base;
  double time_s = 0.0;
  double max_turn_rad = 0.0;    ///< largest |yaw| away from the goal heading on the way
  double max_distance_m = 0.0;  ///< largest distance from the goal on the way
};

/// Integrates the commands on an ideal unicycle (FineAdjust never mixes v and w) at 50 Hz.
AdjustOutcome Simulate(const Pose2& T_goal_base0, const VerifyConfig& config) {
  const Pose2 T_odom_goal(1.0, 2.0, 0.4);
  Pose2 T_odom_base = T_odom_goal * T_goal_base0;
  FineAdjust adjust(config);
  adjust.Start(T_odom_base, T_odom_goal);
  AdjustOutcome out;
  constexpr double kDt = 0.02;
  bool done = false;
  for (int i = 0; i < 1000 && !done; ++i) {
    const VelocityCommand cmd = adjust.Update(T_odom_base, kDt, &done);
    EXPECT_TRUE(cmd.v_mps == 0.0 || cmd.w_radps == 0.0);
    T_odom_base = T_odom_base * Pose2(cmd.v_mps * kDt, 0.0, cmd.w_radps * kDt);
    const Pose2 e = T_odom_goal.inverse() * T_odom_base;
    out.max_turn_rad = std::max(out.max_turn_rad, std::abs(e.yaw));
    out.max_distance_m = std::max(out.max_distance_m, std::hypot(e.x, e.y));
    out.time_s += kDt;
  }
  EXPECT_TRUE(done);
  out.T_goal_base = T_odom_goal.inverse() * T_odom_base;
  return out;
}

TEST(FineAdjust, CorrectsSmallOffsetsToASubMillimetreResidual) {
  const VerifyConfig config;
  for (double ex : {-0.004, 0.0, 0.003}) {
    for (double ey : {-0.003, 0.0, 0.0025}) {
      for (double eyaw : {-0.008, 0.0, 0.006}) {
        const AdjustOutcome o = Simulate(Pose2(ex, ey, eyaw), config);
        EXPECT_LT(std::abs(o.T_goal_base.x), 0.0005) << ex << " " << ey << " " << eyaw;
        EXPECT_LT(std::abs(o.T_goal_base.y), 0.0005) << ex << " " << ey << " " << eyaw;
        EXPECT_LT(std::abs(o.T_goal_base.yaw), 0.0005) << ex << " " << ey << " " << eyaw;
        // No wide swings: the turn stays near the lever angle plus the initial yaw, and the
        // robot stays within the lever's reach (|ey| / tan(angle) + |ex|) of the goal.
        EXPECT_LT(o.max_turn_rad, config.max_lever_angle_rad + std::abs(eyaw) + 0.01);
        const double reach = std::abs(ey) / std::tan(config.max_lever_angle_rad);
        EXPECT_LT(o.max_distance_m, reach + std::abs(ex) + 0.002);
      }
    }
  }
}

TEST(FineAdjust, AnAxialErrorIsOneShortMoveAndOneTurn) {
  const VerifyConfig config;
  const AdjustOutcome o = Simulate(Pose2(-0.004, 0.0, 0.005), config);
  EXPECT_LT(std::abs(o.T_goal_base.x), 0.0005);
  EXPECT_LT(std::abs(o.T_goal_base.yaw), 0.0005);
  // A 4 mm move at <= adjust_accel and a 5 mrad turn: well under a second even with the tail.
  const double t_move = 2.0 * std::sqrt(0.004 / config.adjust_accel_mps2);
  const double t_turn = 2.0 * std::sqrt(0.005 / config.adjust_yaw_accel_radps2);
  EXPECT_LT(o.time_s, t_move + t_turn + 0.3);
}

TEST(FineAdjust, NothingToDoEndsAtOnce) {
  FineAdjust adjust;
  const Pose2 T(3.0, -1.0, 2.0);
  adjust.Start(T, T);
  bool done = false;
  const VelocityCommand cmd = adjust.Update(T, 0.02, &done);
  EXPECT_TRUE(done);
  EXPECT_EQ(cmd.v_mps, 0.0);
  EXPECT_EQ(cmd.w_radps, 0.0);
}

}  // namespace
}  // namespace shelfdock::docking
