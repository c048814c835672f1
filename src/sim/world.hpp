#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "sim/obstacle_grid.hpp"
#include "sim/world_objects.hpp"

namespace shelfdock::sim {

/// The simulated warehouse: shelves, walls, boxes, posts (static, indexed in a uniform grid for
/// fast ray casting) and people and other robots (moving, evaluated at the time of each beam).
/// Every Add/Set call rebuilds the static grid, so build the world first, then scan it.
class World {
 public:
  void AddShelf(int id, const geometry::ShelfModel& model, const geometry::Pose2& T_world_shelf);
  void AddShelf(const ShelfInstance& shelf);
  void AddWall(const Wall& wall);
  /// A polyline wall from points (open) or a polygon (closed).
  void AddWall(const std::vector<Eigen::Vector2d>& points, bool closed = false);
  void AddBox(const Box& box);
  void AddRoundPost(const Eigen::Vector2d& centre, double radius_m);
  void AddRoundPost(const RoundPost& post);
  /// A square post is a box of side `side_m`.
  void AddSquarePost(const geometry::Pose2& T_world_post, double side_m);
  void AddPerson(const Person& person);
  void AddRobot(const MovingRobot& robot);

  /// Moves a shelf (e.g. carried by the robot after the lift). Returns false for unknown ids.
  bool SetShelfPose(int id, const geometry::Pose2& T_world_shelf);
  /// Gives shelves' legs their as-built places (ShelfInstance::legs_as_built), shelf id and legs
  /// each, and builds the ray-casting grid once. Returns false, changing nothing, when an id is
  /// unknown.
  bool SetLegsAsBuilt(std::vector<std::pair<int, std::vector<geometry::Pose2>>> legs_by_shelf);
  /// Removes a shelf (e.g. lifted off the floor). Returns false for unknown ids.
  bool RemoveShelf(int id);

  const std::vector<ShelfInstance>& shelves() const { return shelves_; }
  std::optional<ShelfInstance> Shelf(int id) const;
  const std::vector<Wall>& walls() const { return walls_; }
  const std::vector<Box>& boxes() const { return boxes_; }
  const std::vector<RoundPost>& round_posts() const { return round_posts_; }
  const std::vector<Person>& people() const { return people_; }
  const std::vector<MovingRobot>& robots() const { return robots_; }

  /// True leg geometry of every shelf (or one shelf) in the world frame.
  std::vector<LegFootprint> LegFootprints() const;
  std::vector<LegFootprint> LegFootprints(int shelf_id) const;

  /// Everything solid at time t, as ray-castable primitives (static first, then moving).
  std::vector<Primitive> ObstaclesAt(double t_s) const;
  /// Only the moving ones (people's legs, robots) at time t, appended to `out`.
  void AppendMovingObstacles(double t_s, std::vector<Primitive>* out) const;
  bool HasMovingObstacles() const { return !people_.empty() || !robots_.empty(); }

  const ObstacleGrid& static_grid() const { return grid_; }

 private:
  void Rebuild();
  /// The shelf with `id`, or nullptr.
  ShelfInstance* FindShelf(int id);

  std::vector<ShelfInstance> shelves_;
  std::vector<Wall> walls_;
  std::vector<Box> boxes_;
  std::vector<RoundPost> round_posts_;
  std::vector<Person> people_;
  std::vector<MovingRobot> robots_;
  ObstacleGrid grid_;
};

}  // namespace shelfdock::sim
