// Small text helpers shared by the readers of config, header and table files.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// `s` without the leading and trailing characters of `blanks`.
inline std::string trim(std::string_view s, std::string_view blanks = " \t\r") {
  const auto a = s.find_first_not_of(blanks);
  if (a == std::string_view::npos) return {};
  return std::string(s.substr(a, s.find_last_not_of(blanks) - a + 1));
}

// `s` in lower case (ASCII).
inline std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Levenshtein distance (insertions, deletions, substitutions), for "did you
// mean" suggestions; case counts (compare lower(a) with lower(b) to ignore it).
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace grainlab
