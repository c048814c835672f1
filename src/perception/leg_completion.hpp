#pragma once

#include <vector>

#include <Eigen/Core>

#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"
#include "perception/leg_search.hpp"
#include "perception/preprocess.hpp"
#include "perception/scan_point.hpp"

namespace shelfdock::perception {

/// Leg sets completed from two candidates: the legs cut from the scan at the other corners
/// (to be appended to PreprocessOutput::candidates, in this order) and the sets using them.
struct CompletedLegSets {
  std::vector<Cluster> legs;  ///< new candidates; index k is candidate base + k
  std::vector<LegSet> sets;   ///< 3 or 4 legs, in cyclic order as SearchLegSets gives them
};

/// Two candidates a model's side or diagonal apart fix the shelf up to which side of them it
/// stands on; the preset tells which. Where that shelf has its other legs, the scan's returns
/// within half the leg's extent plus corner_margin_m of the corner are cut out as a leg, from
/// `scan_points` (every valid return, before the trailing filter: a lone return beside a dropout
/// and an occluder is taken for a mixed point there). Used when the search of paper 3.2 found
/// nothing near the preset because a leg in sight never became a candidate: seen by one return
/// beside an occluder, or merged with a person's leg. A cut is no leg when its returns already
/// were a candidate, when the object goes on past it or it lies on a surface with its beam
/// neighbours, or when it is a single return beside a nearer one (a mixed point may look so);
/// on a surface, the part of it that stands out from the line fitted to the surface beside it
/// (`config.surface_min_offset_m`, `surface_offset_sigmas`) is the leg still, placed by its
/// bearing: a leg a few centimetres in front of a wall. With no return at a corner, returns on
/// its bearing that stand out so from the wall are the leg's blend with it.
/// Only shelves within the map's own error of the preset (`gate.map_error_m`,
/// `gate.map_error_yaw_rad`) are completed; the sets then go through the same fit, model screening
/// and evidence as any other (the detector holds a completed 3-leg set to the no-preset err_sum
/// bound). `centres` are the candidates' search centres (detector.cpp); `preprocess` gives the
/// depth step, the surface rule's parameters and the widest leg cluster.
CompletedLegSets CompleteLegSets(const std::vector<ScanPoint>& scan_points,
                                 const PreprocessOutput& pre,
                                 const std::vector<Eigen::Vector2d>& centres,
                                 const std::vector<geometry::ShelfModel>& models,
                                 const geometry::Pose2& T_lidar_preset,
                                 const LegCompletionConfig& config, const PresetGateConfig& gate,
                                 const LegSearchConfig& search, const PreprocessConfig& preprocess);

}  // namespace shelfdock::perception
