#pragma once
// Command-line values every subcommand parses the same way, with one error style:
// "error: (command line): --flag: what was expected".

#include <cstddef>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "geometry/pose2.hpp"

namespace shelfdock::app {

/// Stands for the command line where a file name would be in an io::InputError.
inline constexpr const char* kCommandLine = "(command line)";

/// Parses "a,b,..." into exactly `n` finite numbers; io::InputError names `flag` and `form`
/// (e.g. "X,Y,YAW (m, m, rad)") and quotes the text otherwise.
std::vector<double> ParseNumbers(const std::string& text, std::size_t n, const std::string& flag,
                                 const std::string& form);

/// Check for seeds and counts held in unsigned types, which would wrap "-1" around to 2^64 - 1:
/// "--seed: must be a whole number >= 0, got '-1'".
CLI::Validator NonNegativeInteger();

/// Parses a pose "X,Y,YAW" (metres, metres, radians).
geometry::Pose2 ParsePose(const std::string& text, const std::string& flag);

}  // namespace shelfdock::app
