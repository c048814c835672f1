#pragma once

#include <string>

#include "geometry/gray_image.hpp"

namespace shelfdock::io {

/// Reads an 8-bit grey image from a binary PGM (P5, maxval <= 255, '#' comments allowed), the
/// format both camera dumps and rendered test images use. Throws InputError naming the file.
geometry::GrayImage ReadPgm(const std::string& path);

/// Writes a binary PGM (P5, maxval 255). Throws InputError naming the file when it cannot.
void WritePgm(const std::string& path, const geometry::GrayImage& image);

}  // namespace shelfdock::io
