// Camera images (binary PGM, io::ReadPgm).
#include "fuzz_input_file.hpp"
#include "io/input_error.hpp"
#include "io/pgm.hpp"

namespace {
void Run(const std::string& path) { (void)shelfdock::io::ReadPgm(path); }
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("image.pgm", Run)
