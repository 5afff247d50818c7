// The data length a raw-encoded image header declares, checked against the
// file. NRRD and MetaImage readers (ITK's) read the bytes the header's sizes
// and type call for and ignore any more, so a header whose sizes are too
// small is read as a different image, and one whose sizes are too large reads
// past the data (MetaImage: silently). grainlab checks the length first.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace grainlab::ct {

struct DeclaredData {
  std::filesystem::path image;   // the file the user named
  std::string format;            // "NRRD", "MetaImage"
  std::string described;         // the header's words, e.g. "'sizes: 40 40 20' of 'type: unsigned short'"
  std::uint64_t bytes = 0;       // what they call for
  std::filesystem::path data;    // the file holding the data (`image` itself when attached)
  std::uint64_t offset = 0;      // where the data starts in `data`
  bool at_end = false;           // the data is the last `bytes` of `data`: only a short file can be told
  std::string fix;               // which header fields to fix, e.g. "'sizes' and 'type'"
};

// Bytes of `value_bytes` per value times the whitespace-separated sizes ("40
// 40 20"); 0 when there is none or one is not a positive whole number (the
// format's reader then names the problem).
std::uint64_t declared_bytes(const std::string& sizes, int value_bytes);

// Throws InputError naming the file, both lengths and the fix when the data
// after `offset` is shorter than `bytes`, or (unless at_end) longer.
void check_declared_data(const DeclaredData& d);

}  // namespace grainlab::ct
