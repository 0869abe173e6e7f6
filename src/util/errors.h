// Errors raised for bad input. Every message names the file, the element and the
// offending value, so the CLI can print it as one line and exit non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace rt {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Builds the one-line message "FILE: ELEMENT: WHAT" used by every loader error.
inline InputError input_error(const std::string& file, const std::string& element,
                              const std::string& what) {
  return InputError(file + ": " + element + ": " + what);
}

}  // namespace rt
