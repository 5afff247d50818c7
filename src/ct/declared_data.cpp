#include "ct/declared_data.h"

#include "core/error.h"

#include <sstream>

namespace grainlab::ct {

namespace fs = std::filesystem;

std::uint64_t declared_bytes(const std::string& sizes, int value_bytes) {
  std::istringstream in(sizes);
  std::uint64_t bytes = static_cast<std::uint64_t>(value_bytes);
  std::int64_t n = 0;
  int axes = 0;
  while (in >> n) {
    if (n <= 0) return 0;
    bytes *= static_cast<std::uint64_t>(n);
    ++axes;
  }
  return axes > 0 && in.eof() ? bytes : 0;
}

void check_declared_data(const DeclaredData& d) {
  std::error_code ec;
  if (!fs::is_regular_file(d.data, ec)) {
    input_error("'{}': its data file '{}' does not exist: copy it next to the header, or fix the header's data file "
                "field",
                d.image.string(), d.data.string());
  }
  const std::uint64_t file = fs::file_size(d.data, ec);
  if (ec) return;
  const std::uint64_t have = file > d.offset ? file - d.offset : 0;
  const std::string where = d.data == d.image ? "after its header" : fmt::format("in '{}'", d.data.string());
  const std::string described = fmt::format("{} ({} bytes)", d.described, d.bytes);
  if (have < d.bytes) {
    input_error("'{}' ({}) is truncated or its header is wrong: it describes {}, but the file holds only {} bytes "
                "of raw data {}; copy the file again, or fix {} in the header",
                d.image.string(), d.format, described, have, where, d.fix);
  }
  if (have > d.bytes && !d.at_end) {
    input_error("'{}' ({}) holds more data than its header describes: {}, but {} bytes of raw data {}; the image "
                "read would not be the scan: fix {} in the header so that they account for all the data",
                d.image.string(), d.format, described, have, where, d.fix);
  }
}

}  // namespace grainlab::ct
