#pragma once

#include <cstdint>
#include <vector>

namespace shelfdock::sim {

/// The printed cells of one AprilTag 36h11 code, white quiet zone included (10 x 10 cells for
/// 36h11), row-major from the top-left as the code is seen from the front: true = white.
struct MarkerPattern {
  int total_cells = 0;   ///< cells per side, quiet zone included
  int border_cells = 0;  ///< cells per side of the outer black border (what code_size measures)
  std::vector<bool> white;

  bool IsWhite(int col, int row) const {
    return white[static_cast<std::size_t>(row) * static_cast<std::size_t>(total_cells) +
                 static_cast<std::size_t>(col)];
  }
};

/// Number of codes in the 36h11 family (valid ids are 0 .. count - 1).
int MarkerFamilySize();

/// The cells of code `tag_id` (0 <= tag_id < MarkerFamilySize()).
MarkerPattern MarkerPatternFor(int tag_id);

}  // namespace shelfdock::sim
