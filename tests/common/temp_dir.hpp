#pragma once
// A fresh directory of its own for each test process: two suites running at once (or the same
// suite in two build trees) never write the same file. Removed with everything in it at exit.

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace shelfdock::testing {

class TempDir {
 public:
  TempDir() {
    std::string name = (std::filesystem::temp_directory_path() / "shelfdock_test_XXXXXX").string();
    if (mkdtemp(name.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = name;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// `name` inside the directory.
  std::string File(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// The test process's own directory, made on first use.
inline const TempDir& ProcessTempDir() {
  static const TempDir dir;
  return dir;
}

}  // namespace shelfdock::testing
