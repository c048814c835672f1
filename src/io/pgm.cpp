#include "io/pgm.hpp"

#include <cctype>
#include <cmath>
#include <fstream>

#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

/// Next header integer, skipping whitespace and '#' comments (netpbm header grammar).
int ReadHeaderInt(std::istream& in, const std::string& path, const std::string& field) {
  while (true) {
    const int c = in.peek();
    if (c == '#') {
      std::string comment;
      std::getline(in, comment);
    } else if (c != EOF && std::isspace(c)) {
      in.get();
    } else {
      break;
    }
  }
  int value = 0;
  if (!(in >> value) || value <= 0) {
    throw InputError(path, field, "expected a positive integer in the PGM header");
  }
  return value;
}

}  // namespace

geometry::GrayImage ReadPgm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open file");
  char magic[2] = {0, 0};
  in.read(magic, 2);
  if (!in || magic[0] != 'P' || magic[1] != '5') {
    throw InputError(path, "header", "expected a binary PGM (magic number P5)");
  }
  const int width = ReadHeaderInt(in, path, "width");
  const int height = ReadHeaderInt(in, path, "height");
  const int maxval = ReadHeaderInt(in, path, "maxval");
  if (maxval > 255) throw InputError(path, "maxval", "expected 8-bit grey (maxval <= 255)");
  constexpr int kMaxSide = 1 << 15;
  if (width > kMaxSide || height > kMaxSide) {
    throw InputError(path, "size", "image sides must be at most 32768 pixels");
  }
  if (!std::isspace(in.get())) throw InputError(path, "header", "expected whitespace after maxval");

  geometry::GrayImage image(width, height);
  in.read(reinterpret_cast<char*>(image.pixels.data()),
          static_cast<std::streamsize>(image.pixels.size()));
  if (in.gcount() != static_cast<std::streamsize>(image.pixels.size())) {
    throw InputError(path, "pixels",
                     "truncated: expected " + std::to_string(image.pixels.size()) + " bytes");
  }
  if (maxval != 255) {
    // Rescale to the full 0..255 range so thresholds mean the same for every file.
    for (uint8_t& p : image.pixels) {
      p = static_cast<uint8_t>(std::lround(std::min(255.0, p * 255.0 / maxval)));
    }
  }
  return image;
}

void WritePgm(const std::string& path, const geometry::GrayImage& image) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(path, "", "cannot open file for writing");
  out << "P5\n" << image.width << " " << image.height << "\n255\n";
  out.write(reinterpret_cast<const char*>(image.pixels.data()),
            static_cast<std::streamsize>(image.pixels.size()));
  if (!out) throw InputError(path, "", "write failed");
}

}  // namespace shelfdock::io
