#pragma once
// For tests of the readers' errors: the message of the io::InputError that `read` throws.

#include <string>

#include <gtest/gtest.h>

#include "io/input_error.hpp"

namespace shelfdock::testing {

/// Runs `read` and returns the InputError's message; fails the test when nothing is thrown.
template <typename F>
std::string InputErrorOf(F read) {
  try {
    read();
  } catch (const io::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

}  // namespace shelfdock::testing
