// Errors that reach users. Every message says what is wrong, where, and how to fix it.
#pragma once

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <string_view>

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

// A file could not be written (disk full, a file-size limit, permissions):
// a fault of the system, not of the input. The message names the file.
class WriteError : public RunError {
 public:
  using RunError::RunError;
};

// A run asked to stop (a stop signal) while it prepared, before it could
// checkpoint as a run: what could be kept was kept (the message says what).
class Stopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `text` for a message: whole when short, else its first `max` characters
// and how long it was, so that a hostile value never floods the terminal.
inline std::string excerpt(std::string_view text, std::size_t max = 60) {
  if (text.size() <= max) return std::string(text);
  return fmt::format("{}... ({} characters)", text.substr(0, max), text.size());
}

// Throws InputError with a formatted message.
template <typename... Args>
[[noreturn]] void input_error(fmt::format_string<Args...> f, Args&&... args) {
  throw InputError(fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace grainlab
