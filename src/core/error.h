// Errors that reach users. Every message says what is wrong, where, and how to fix it.
#pragma once

#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace grainlab {

// Bad user input (a mesh, a config value, a time step): the run cannot start.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A run that went wrong while running (instability, a grain escaping).
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A run asked to stop (a stop signal) while it prepared, before it could
// checkpoint as a run: what could be kept was kept (the message says what).
class Stopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws InputError with a formatted message.
template <typename... Args>
[[noreturn]] void input_error(fmt::format_string<Args...> f, Args&&... args) {
  throw InputError(fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace grainlab
