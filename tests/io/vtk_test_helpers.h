// Helpers for the VTK io tests: bitwise array comparison, a file's text
// (file_text.h), and xmllint when the machine has it.
#pragma once

#include "file_text.h"
#include "io/vtk_writer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace grainlab::test {

// Same name, components, type and the same bytes (so -0.0 differs from 0.0 and NaN payloads count).
inline ::testing::AssertionResult same_bits(const VtkArray& a, const VtkArray& b) {
  if (a.name != b.name || a.components != b.components || a.values.index() != b.values.index())
    return ::testing::AssertionFailure() << "array '" << a.name << "' (" << a.type_name() << " x" << a.components
                                         << ") vs '" << b.name << "' (" << b.type_name() << " x" << b.components << ")";
  return std::visit(
      [&](const auto& va) {
        const auto& vb = std::get<std::decay_t<decltype(va)>>(b.values);
        if (va.size() != vb.size())
          return ::testing::AssertionFailure() << "'" << a.name << "': " << va.size() << " vs " << vb.size() << " values";
        if (!va.empty() && std::memcmp(va.data(), vb.data(), va.size() * sizeof(va[0])) != 0)
          return ::testing::AssertionFailure() << "'" << a.name << "': values differ";
        return ::testing::AssertionSuccess();
      },
      a.values);
}

// True if xmllint can be run here.
inline bool have_xmllint() { return std::system("xmllint --version > /dev/null 2>&1") == 0; }

// Exit status of `xmllint --noout file` (0: well-formed XML).
inline int xmllint_status(const std::filesystem::path& p) {
  return std::system(("xmllint --noout '" + p.string() + "' > /dev/null 2>&1").c_str());
}

}  // namespace grainlab::test
