// std::getline with a bound on the line's length, for the text headers of
// binary files (NRRD, MetaImage): a file that is not what its extension says
// (a raw scan of gigabytes named .nrrd, with no newline in it) would
// otherwise be read whole into one string before its first line is judged.
#pragma once

#include "core/error.h"

#include <cstddef>
#include <istream>
#include <string>
#include <string_view>

namespace grainlab {

// Reads a line of at most `max_chars` characters (without its '\n') into
// `line`; false at the end of the input, as std::getline. Throws InputError
// naming `source` and the limit when a line is longer: `what` says what the
// file should have been ("an NRRD header").
inline bool bounded_getline(std::istream& in, std::string& line, std::size_t max_chars, std::string_view source,
                            std::string_view what) {
  line.clear();
  for (int c; (c = in.get()) != std::char_traits<char>::eof();) {
    if (c == '\n') return true;
    if (line.size() == max_chars)
      input_error("'{}': a line of more than {} characters where {} has short text lines: it is not {}, or it is "
                  "damaged; check the file and its extension",
                  excerpt(source, 200), max_chars, what, what);
    line.push_back(static_cast<char>(c));
  }
  return !line.empty();
}

}  // namespace grainlab
