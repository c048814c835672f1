// The only file of the simulator that touches libapriltag: the code's cells are read from the
// same tag36h11 family table the detector decodes against, so rendering and decoding cannot
// disagree, and the simulator carries no second copy of the 587 codes.
#include "sim/marker_pattern.hpp"

#include <cassert>
#include <memory>

#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>

namespace shelfdock::sim {
namespace {

const apriltag_family_t& Family() {
  static const std::unique_ptr<apriltag_family_t, void (*)(apriltag_family_t*)> family(
      tag36h11_create(), &tag36h11_destroy);
  return *family;
}

}  // namespace

int MarkerFamilySize() { return static_cast<int>(Family().ncodes); }

MarkerPattern MarkerPatternFor(int tag_id) {
  const apriltag_family_t& family = Family();
  assert(tag_id >= 0 && tag_id < static_cast<int>(family.ncodes));
  assert(!family.reversed_border);  // 36h11: black border inside a white quiet zone

  MarkerPattern pattern;
  pattern.total_cells = family.total_width;
  pattern.border_cells = family.width_at_border;
  const int n = pattern.total_cells;
  pattern.white.assign(static_cast<std::size_t>(n * n), true);

  // Everything inside the black border starts black; the data bits set to 1 are white. The bit
  // positions count from the border's top-left cell (as libapriltag's apriltag_to_image does).
  const int border_start = (n - pattern.border_cells) / 2;
  auto cell = [&](int col, int row) -> std::vector<bool>::reference {
    return pattern.white[static_cast<std::size_t>(row * n + col)];
  };
  for (int row = border_start; row < border_start + pattern.border_cells; ++row) {
    for (int col = border_start; col < border_start + pattern.border_cells; ++col) {
      cell(col, row) = false;
    }
  }
  const uint64_t code = family.codes[tag_id];
  for (uint32_t i = 0; i < family.nbits; ++i) {
    const bool bit = ((code >> (family.nbits - i - 1)) & 1ULL) != 0;
    if (bit) {
      cell(border_start + static_cast<int>(family.bit_x[i]),
           border_start + static_cast<int>(family.bit_y[i])) = true;
    }
  }
  return pattern;
}

}  // namespace shelfdock::sim
