// Scan files: one JSON object, an array of them, or JSON Lines (io::ReadScans).
#include "fuzz_input_file.hpp"
#include "io/input_error.hpp"
#include "io/scan_json.hpp"

namespace {
void Run(const std::string& path) { (void)shelfdock::io::ReadScans(path); }
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("scan.json", Run)
