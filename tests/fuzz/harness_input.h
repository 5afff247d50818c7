// What every fuzz harness shares. A harness (fuzz_NAME.cpp) defines
// LLVMFuzzerTestOneInput: it hands the bytes to one of grainlab's readers of
// outside files, the way a user's file reaches it (most readers take a path,
// so the bytes are written to a file first), and lets through only the
// refusal a reader is allowed: InputError, whose message says what, where and
// how to fix. Anything else (a crash, a sanitizer report, std::bad_alloc or
// another exception, a hang, an allocation over libFuzzer's -malloc_limit_mb)
// is a finding: it gets a fix and its input goes into tests/fuzz/corpus/NAME.
#pragma once

#include "core/error.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace grainlab::fuzz {

// A file of this process (in /dev/shm when there is one, else the system's
// temporary folder) named `name`, holding `bytes`; rewritten at every call.
std::filesystem::path input_file(std::span<const std::uint8_t> bytes, std::string_view name);

// Prints a refusal's message when GRAINLAB_FUZZ_VERBOSE is set (to see how
// far the seeds get), else nothing.
void report_refusal(const InputError& e);

// Runs `read`; an InputError (a clean refusal) is swallowed, anything else
// escapes to libFuzzer (or the corpus driver) as the finding it is.
template <typename Read>
int refused_or_read(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    report_refusal(e);
  }
  return 0;
}

}  // namespace grainlab::fuzz
