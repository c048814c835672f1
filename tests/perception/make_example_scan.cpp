// Test helper: writes the shipped example scan (config/example_scan.json, also the CLI test
// fixture tests/data/example_scan.json): the WLR-716 simulator's view of a t1-rect-1075x883
// shelf at (2.0, 0.2) m, yaw 0.1 rad in the lidar frame, in a 12 m x 10 m room.
// Usage: perception_make_example_scan OUT.json
#include <fstream>
#include <iostream>

#include "io/scan_json.hpp"
#include "test_scenes.hpp"

int main(int argc, char** argv) {
  using namespace shelfdock;
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " OUT.json\n";
    return 2;
  }
  sim::World world;
  perception::testing::AddRoom(world);
  world.AddShelf(1, perception::testing::PaperModels()[1], geometry::Pose2(2.0, 0.2, 0.1));
  const geometry::LaserScan scan = perception::testing::SimScan(world, geometry::Pose2(), 2024);
  std::ofstream out(argv[1]);
  out << io::ScanToJson(scan).dump() << "\n";
  return out ? 0 : 1;
}
