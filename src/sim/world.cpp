#include "sim/world.hpp"

#include <algorithm>

namespace shelfdock::sim {

void World::AddShelf(int id, const geometry::ShelfModel& model,
                     const geometry::Pose2& T_world_shelf) {
  ShelfInstance shelf;
  shelf.id = id;
  shelf.model = model;
  shelf.T_world_shelf = T_world_shelf;
  AddShelf(shelf);
}

void World::AddShelf(const ShelfInstance& shelf) {
  shelves_.push_back(shelf);
  Rebuild();
}

void World::AddWall(const Wall& wall) {
  walls_.push_back(wall);
  Rebuild();
}

void World::AddWall(const std::vector<Eigen::Vector2d>& points, bool closed) {
  Wall wall;
  wall.points = points;
  wall.closed = closed;
  AddWall(wall);
}

void World::AddBox(const Box& box) {
  boxes_.push_back(box);
  Rebuild();
}

void World::AddRoundPost(const Eigen::Vector2d& centre, double radius_m) {
  RoundPost post;
  post.centre = centre;
  post.radius_m = radius_m;
  AddRoundPost(post);
}

void World::AddRoundPost(const RoundPost& post) {
  round_posts_.push_back(post);
  Rebuild();
}

void World::AddSquarePost(const geometry::Pose2& T_world_post, double side_m) {
  Box box;
  box.T_world_box = T_world_post;
  box.length_m = side_m;
  box.width_m = side_m;
  AddBox(box);
}

void World::AddPerson(const Person& person) { people_.push_back(person); }

void World::AddRobot(const MovingRobot& robot) { robots_.push_back(robot); }

ShelfInstance* World::FindShelf(int id) {
  auto it = std::find_if(shelves_.begin(), shelves_.end(),
                         [id](const ShelfInstance& s) { return s.id == id; });
  return it == shelves_.end() ? nullptr : &*it;
}

bool World::SetShelfPose(int id, const geometry::Pose2& T_world_shelf) {
  ShelfInstance* shelf = FindShelf(id);
  if (shelf == nullptr) return false;
  shelf->T_world_shelf = T_world_shelf;
  Rebuild();
  return true;
}

bool World::SetLegsAsBuilt(
    std::vector<std::pair<int, std::vector<geometry::Pose2>>> legs_by_shelf) {
  for (const auto& [id, legs] : legs_by_shelf) {
    if (FindShelf(id) == nullptr) return false;
  }
  for (auto& [id, legs] : legs_by_shelf) FindShelf(id)->legs_as_built = std::move(legs);
  Rebuild();
  return true;
}

bool World::RemoveShelf(int id) {
  const auto n = shelves_.size();
  std::erase_if(shelves_, [id](const ShelfInstance& s) { return s.id == id; });
  if (shelves_.size() == n) return false;
  Rebuild();
  return true;
}

std::optional<ShelfInstance> World::Shelf(int id) const {
  for (const ShelfInstance& s : shelves_) {
    if (s.id == id) return s;
  }
  return std::nullopt;
}

std::vector<LegFootprint> World::LegFootprints() const {
  std::vector<LegFootprint> legs;
  for (const ShelfInstance& s : shelves_) {
    const auto l = ShelfLegFootprints(s);
    legs.insert(legs.end(), l.begin(), l.end());
  }
  return legs;
}

std::vector<LegFootprint> World::LegFootprints(int shelf_id) const {
  const auto shelf = Shelf(shelf_id);
  return shelf ? ShelfLegFootprints(*shelf) : std::vector<LegFootprint>{};
}

std::vector<Primitive> World::ObstaclesAt(double t_s) const {
  std::vector<Primitive> all = grid_.primitives();
  AppendMovingObstacles(t_s, &all);
  return all;
}

void World::AppendMovingObstacles(double t_s, std::vector<Primitive>* out) const {
  for (std::size_t i = 0; i < people_.size(); ++i) {
    AppendPerson(people_[i], t_s, static_cast<int>(i), out);
  }
  for (std::size_t i = 0; i < robots_.size(); ++i) {
    AppendBox(robots_[i].BoxAt(t_s), ObjectKind::kRobot, static_cast<int>(i), out);
  }
}

void World::Rebuild() {
  std::vector<Primitive> prims;
  for (const ShelfInstance& s : shelves_) AppendShelfLegs(s, &prims);
  for (std::size_t i = 0; i < walls_.size(); ++i) {
    AppendWall(walls_[i], static_cast<int>(i), &prims);
  }
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    AppendBox(boxes_[i], ObjectKind::kBox, static_cast<int>(i), &prims);
  }
  for (std::size_t i = 0; i < round_posts_.size(); ++i) {
    AppendRoundPost(round_posts_[i], static_cast<int>(i), &prims);
  }
  grid_ = ObstacleGrid(std::move(prims));
}

}  // namespace shelfdock::sim
