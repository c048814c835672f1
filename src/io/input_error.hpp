#pragma once

#include <stdexcept>
#include <string>

namespace shelfdock::io {

/// Bad input from the outside world: a missing file, a malformed document, a field with the
/// wrong type or an impossible value. The message names the file and the field; the CLI turns
/// it into exit code 2.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& field, const std::string& what)
      : std::runtime_error(file + ": " + (field.empty() ? "" : field + ": ") + what),
        file_(file),
        field_(field) {}

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  std::string field_;
};

}  // namespace shelfdock::io
