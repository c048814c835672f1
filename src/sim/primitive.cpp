#include "sim/primitive.hpp"

#include <cmath>

namespace shelfdock::sim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

double Cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}
}  // namespace

Primitive Primitive::Circle(const Eigen::Vector2d& centre, double radius_m) {
  Primitive p;
  p.shape = Shape::kCircle;
  p.a = centre;
  p.radius_m = radius_m;
  return p;
}

Primitive Primitive::Segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  Primitive p;
  p.shape = Shape::kSegment;
  p.a = a;
  p.b = b;
  return p;
}

void Primitive::Bounds(Eigen::Vector2d* min, Eigen::Vector2d* max) const {
  if (shape == Shape::kCircle) {
    *min = a.array() - radius_m;
    *max = a.array() + radius_m;
  } else {
    *min = a.cwiseMin(b);
    *max = a.cwiseMax(b);
  }
}

double IntersectRay(const Ray2& ray, const Primitive& primitive) {
  if (primitive.shape == Primitive::Shape::kCircle) {
    // |o + t d - c|^2 = r^2 with |d| = 1:  t^2 + 2 t (d.m) + |m|^2 - r^2 = 0, m = o - c.
    const Eigen::Vector2d m = ray.origin - primitive.a;
    const double b = m.dot(ray.dir);
    const double c = m.squaredNorm() - primitive.radius_m * primitive.radius_m;
    const double disc = b * b - c;
    if (disc < 0.0) return kInf;
    const double root = std::sqrt(disc);
    const double t_near = -b - root;
    if (t_near >= 0.0) return t_near;
    const double t_far = -b + root;  // origin inside the circle
    return t_far >= 0.0 ? t_far : kInf;
  }
  // o + t d = a + s (b - a), s in [0, 1]: Cramer's rule on the 2x2 system.
  const Eigen::Vector2d e = primitive.b - primitive.a;
  const double denom = Cross(ray.dir, e);
  if (std::abs(denom) < 1e-15) return kInf;  // parallel: a grazing ray sees no surface
  const Eigen::Vector2d w = primitive.a - ray.origin;
  const double t = Cross(w, e) / denom;
  const double s = Cross(w, ray.dir) / denom;
  if (t < 0.0 || s < 0.0 || s > 1.0) return kInf;
  return t;
}

Eigen::Vector2d SurfaceNormal(const Primitive& primitive, const Eigen::Vector2d& point,
                              const Eigen::Vector2d& from) {
  if (primitive.shape == Primitive::Shape::kCircle) {
    const Eigen::Vector2d n = point - primitive.a;
    const double len = n.norm();
    return len > 0.0 ? Eigen::Vector2d(n / len) : Eigen::Vector2d::UnitX();
  }
  const Eigen::Vector2d e = primitive.b - primitive.a;
  Eigen::Vector2d n(-e.y(), e.x());
  const double len = n.norm();
  if (len == 0.0) return Eigen::Vector2d::UnitX();
  n /= len;
  return n.dot(from - point) >= 0.0 ? n : Eigen::Vector2d(-n);
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const Material& m) {
  geometry::ConfigChecker k;  // shiny: either value
  k.Check(m.reflectivity >= 0.0 && m.reflectivity <= 1.0, "reflectivity", "in [0, 1]");
  return k.Result();
}

}  // namespace shelfdock::sim
