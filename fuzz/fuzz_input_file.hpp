#pragma once
// Fuzz targets feed the readers exactly as the CLI does: through a file. Each process writes its
// inputs to one file in its own temporary directory (removed at exit), in memory (/dev/shm) where
// there is one: a disk-backed file costs more than most readers take to run.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace shelfdock::fuzz {

class FuzzInputFile {
 public:
  explicit FuzzInputFile(const std::string& name) {
    std::error_code ec;
    const std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec)
                                           ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path();
    std::string dir_template = (base / "shelfdock_fuzz_XXXXXX").string();
    if (mkdtemp(dir_template.data()) == nullptr) std::abort();
    dir_ = dir_template;
    path_ = (dir_ / name).string();
  }
  ~FuzzInputFile() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  FuzzInputFile(const FuzzInputFile&) = delete;
  FuzzInputFile& operator=(const FuzzInputFile&) = delete;

  /// Replaces the file's content with `data` and returns its path.
  const std::string& Write(const uint8_t* data, std::size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) std::abort();
    return path_;
  }

 private:
  std::filesystem::path dir_;
  std::string path_;
};

}  // namespace shelfdock::fuzz

/// Defines the libFuzzer entry point: writes the input to a file named `file_name` and runs
/// `body(path)`. io::InputError is the expected answer to bad input; any other exception escaping
/// a reader is a finding (main would report it as an internal failure, exit 1), so it aborts.
#define SHELFDOCK_FUZZ_FILE_TARGET(file_name, body)                              \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) { \
    static shelfdock::fuzz::FuzzInputFile file(file_name);                       \
    const std::string& path = file.Write(data, size);                            \
    try {                                                                        \
      body(path);                                                                \
    } catch (const shelfdock::io::InputError&) {                                 \
    }                                                                            \
    return 0;                                                                    \
  }
