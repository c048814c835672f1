#include "docking/outcome.hpp"

namespace shelfdock::docking {

std::string_view ToString(OutcomeCode code) {
  switch (code) {
    case OutcomeCode::kPending:
      return "pending";
    case OutcomeCode::kSuccess:
      return "success";
    case OutcomeCode::kShelfNotFound:
      return "shelf_not_found";
    case OutcomeCode::kDetectionLost:
      return "detection_lost";
    case OutcomeCode::kWouldCollide:
      return "would_collide";
    case OutcomeCode::kNoPath:
      return "no_path";
    case OutcomeCode::kTrackingFailed:
      return "tracking_failed";
    case OutcomeCode::kWrongShelf:
      return "wrong_shelf";
    case OutcomeCode::kCodeNotFound:
      return "code_not_found";
    case OutcomeCode::kTimeout:
      return "timeout";
    case OutcomeCode::kTooManyReplans:
      return "too_many_replans";
  }
  return "unknown";
}

}  // namespace shelfdock::docking
