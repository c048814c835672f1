// The ICP speed-target lines and JSON of `eval peers`, on rows with known times.
#include "io/peers_report.hpp"

#include <gtest/gtest.h>

namespace shelfdock::io {
namespace {

eval::PeerRow Row(const std::string& set, eval::PeerMethod method, double time_p50_s) {
  eval::PeerRow r;
  r.set = set;
  r.method = method;
  r.time_s.p50 = time_p50_s;
  return r;
}

TEST(PeersReport, IcpSpeedTargetMetOrMissedBySetAndSaidWhenNotBuilt) {
  // 40 us against 2 ms: 50x, met; 40 us against 0.2 ms: 5x, missed by 4x.
  const std::vector<eval::PeerRow> rows = {
      Row("a", eval::PeerMethod::kShelfdock, 40e-6), Row("a", eval::PeerMethod::kIcp, 2e-3),
      Row("b", eval::PeerMethod::kShelfdock, 40e-6), Row("b", eval::PeerMethod::kIcp, 0.2e-3)};
  const std::vector<std::string> lines = IcpTargetLines(rows);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("a: shelfdock 50.0x faster"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("met)"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("b: shelfdock 5.0x faster"), std::string::npos) << lines[1];
  EXPECT_NE(lines[1].find("**missed** by 4.00x"), std::string::npos) << lines[1];

  const nlohmann::json j = PeersJson(rows, {});
  ASSERT_TRUE(j["icp"]["built"].get<bool>());
  ASSERT_EQ(j["icp"]["sets"].size(), 2u);
  EXPECT_NEAR(j["icp"]["sets"][0]["time_ratio"].get<double>(), 50.0, 1e-9);
  EXPECT_TRUE(j["icp"]["sets"][0]["met"].get<bool>());
  EXPECT_NEAR(j["icp"]["sets"][1]["time_ratio"].get<double>(), 5.0, 1e-9);
  EXPECT_FALSE(j["icp"]["sets"][1]["met"].get<bool>());

  // Without ICP rows (a build without PCL): one line saying so, and built false.
  const std::vector<eval::PeerRow> no_icp = {rows[0], rows[2]};
  EXPECT_EQ(IcpTargetLines(no_icp), std::vector<std::string>{kIcpNotBuilt});
  EXPECT_FALSE(PeersJson(no_icp, {})["icp"]["built"].get<bool>());
}

}  // namespace
}  // namespace shelfdock::io
