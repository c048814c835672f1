#include "sim/line_of_sight.hpp"

#include <algorithm>

#include "sim/lidar.hpp"

namespace shelfdock::sim {

int LegSight::LegsInSight(int min_beams) const {
  return static_cast<int>(
      std::count_if(beams.begin(), beams.end(), [min_beams](int n) { return n >= min_beams; }));
}

LegSight ComputeLegSight(const World& world, const geometry::Pose2& T_world_lidar,
                         const LidarConfig& lidar, int shelf_id) {
  // The labelled scan of an ideal LiDAR names the primitive each beam's centre ray hits first;
  // its seed is irrelevant since nothing random is left switched on.
  Lidar ideal(IdealLidarConfig(lidar), 0);
  const LabelledScan labelled = ideal.ScanLabelled(
      world, [&T_world_lidar](double) { return T_world_lidar; }, 0.0);
  LegSight sight;
  for (const BeamTruth& beam : labelled.truth) {
    if (beam.kind == ObjectKind::kShelfLeg && beam.object_id == shelf_id && beam.part >= 0 &&
        beam.part < static_cast<int>(sight.beams.size())) {
      ++sight.beams[static_cast<std::size_t>(beam.part)];
    }
  }
  return sight;
}

}  // namespace shelfdock::sim
