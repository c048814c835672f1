#pragma once

#include <vector>

#include <Eigen/Core>

#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"
#include "perception/mixed_returns.hpp"
#include "perception/preprocess.hpp"
#include "perception/silhouette_edges.hpp"

namespace shelfdock::perception {

/// What a leg's outline across the beams says about its bearing (the fits' silhouette term): the
/// bearing of its centre (between the outer beams) or, when one edge is seen and the other side
/// may go on, of that edge; with its std.
struct SilhouetteTerm {
  double mid_rad = 0.0;    ///< [rad] bearing of the outline's centre, between the outer beams
  double sigma_rad = 0.0;  ///< [rad] std of the bearing the term holds; 0: no term (one return,
                           ///< no edge seen)
  int edge_side = 0;       ///< one edge holds: -1 the smaller bearing, +1 the larger; 0 the centre
  double edge_rad = 0.0;   ///< [rad] that edge's bearing relative to mid_rad
};

/// One fitted leg (paper 3.3).
struct LegFitResult {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< [m] fitted leg centre, lidar frame
  double axis_yaw = 0.0;       ///< [rad] leg section's x axis (G_h side) used by the fit
  bool axis_from_pca = false;  ///< the axis came from the points' PCA, not the hint
  double rms_m = 0.0;          ///< [m] RMS point-to-surface distance at the solution
  bool converged = false;
  SilhouetteTerm silhouette;  ///< what its outline said of its bearing (MakeSilhouetteTerm)
  MixedEdges mixed;           ///< its outer returns weighed as possible blends (FindMixedEdges)
};

/// Main direction (Eq. 3-4: centroid and scatter matrix, largest eigenvector) and the ratio of
/// the eigenvalues (>= 1; large for points along one face).
struct PcaDirection {
  double yaw = 0.0;         ///< [rad]
  double anisotropy = 1.0;  ///< [-] largest / smallest eigenvalue
};
/// Principal axis of the points (PCA) and how elongated they are.
PcaDirection PrincipalDirection(const std::vector<ScanPoint>& points);

/// The silhouette term of a leg's returns (beam order) and its outline's edges (FitLeg explains
/// when one edge holds instead of the centre).
SilhouetteTerm MakeSilhouetteTerm(const std::vector<ScanPoint>& points,
                                  const SilhouetteEdges& edges, const LegFitConfig& config);

/// The range noise the weighing of possible blends (FindMixedEdges, MixedReturnSqrtWeight)
/// assumes: the scan's `range_noise_m` (0: the configured LegFitConfig::range_sigma_m), at least
/// LegFitConfig::mixed_min_noise_m.
double MixedEdgeNoise(double range_noise_m, const LegFitConfig& config);

/// Paper 3.3: the leg centre from its points by nonlinear least squares (Ceres). Round legs use
/// the residual |p - c| - r; rectangular legs the distance of each point to the nearest face of
/// the G_h x G_w section that faces the sensor (at the origin). The section's axes come from
/// the PCA when the points show a clear face, else from `axis_yaw_hint` (the shelf edge: legs
/// are mounted square to the frame). Unlike the bare centroid, the fit is not pulled toward the
/// sensor by the leg's half depth. Across the beams the leg's outline (silhouette) places it:
/// centred between its outer beams when the scan shows both edges or neither, against the one
/// edge `edges` shows when the other side may go on (a dropout, an occluder). An outer return
/// that may be a blend of the leg and the surface beyond its edge (FindMixedEdges) keeps its range
/// only as far as a plain return of the range noise `range_noise_m` explains it (MixedEdgeNoise).
LegFitResult FitLeg(const std::vector<ScanPoint>& points, const geometry::LegModel& leg,
                    double axis_yaw_hint, const LegFitConfig& config,
                    const SilhouetteEdges& edges = {}, double range_noise_m = 0.0);

}  // namespace shelfdock::perception
