#include "core/text.h"
#include "ct/metaimage_header.h"

#include "core/bounded_line.h"
#include "ct/compressed_data.h"
#include "ct/declared_data.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab::ct {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxValue = 1024;  // a value: a few numbers, a name or a file name
constexpr std::size_t kMaxKey = 200;     // a field's name (MetaIO's buffer holds 254 characters)
constexpr std::size_t kMaxText = 254;    // a value that is not numbers (MetaIO's buffers hold 254 characters)

constexpr std::array<std::string_view, 37> kFields{
    "Comment",         "AcquisitionDate",    "ObjectType",      "ObjectSubType",
    "NDims",           "Name",               "ID",              "ParentID",
    "ParentName",      "FileFormatVersion",  "CompressedData",  "CompressedDataSize",
    "BinaryData",      "BinaryDataByteOrderMSB", "ElementByteOrderMSB", "Color",
    "Position",        "Origin",             "Offset",          "TransformMatrix",
    "Rotation",        "Orientation",        "CenterOfRotation", "AnatomicalOrientation",
    "ElementSpacing",  "DimSize",            "HeaderSize",      "HeaderSizePerSlice",
    "Modality",        "SequenceID",         "ElementMin",      "ElementMax",
    "ElementNumberOfChannels", "ElementSize", "ElementType",    "ElementDataFile",
    "TransformType"};

int element_bytes(const std::string& type) {
  static const std::map<std::string, int> bytes = {
      {"MET_CHAR", 1},  {"MET_UCHAR", 1}, {"MET_SHORT", 2},     {"MET_USHORT", 2},     {"MET_INT", 4},
      {"MET_UINT", 4},  {"MET_LONG", 4},  {"MET_ULONG", 4},     {"MET_LONG_LONG", 8},  {"MET_ULONG_LONG", 8},
      {"MET_FLOAT", 4}, {"MET_DOUBLE", 8}};
  const auto it = bytes.find(type);
  return it == bytes.end() ? 0 : it->second;
}

struct Field {
  std::string value;
  int line = 0;
};

class Header {
 public:
  explicit Header(const fs::path& path) : path_(path) {}

  // Reads the fields up to ElementDataFile; returns the header's bytes.
  std::uint64_t read() {
    std::ifstream in(path_, std::ios::binary);
    std::uint64_t bytes = 0;
    int n = 0;
    constexpr std::size_t kMaxHeaderLine = 64 * 1024;
    for (std::string line; bounded_getline(in, line, kMaxHeaderLine, path_.string(), "a MetaImage header");) {
      bytes += line.size() + 1;
      ++n;
      if (trim(line).empty()) continue;
      const auto eq = line.find('=');
      if (eq == std::string::npos) fail(n, fmt::format("'{}' is not a 'Key = Value' field", excerpt(trim(line))),
                                        "remove the line or write it as a field");
      const std::string key = trim(line.substr(0, eq));
      const std::string value = trim(line.substr(eq + 1));
      check_key(key, n);
      check_text(key, value, n);
      if (fields_.count(key)) {
        fail(n, fmt::format("field '{}' given a second time (first on line {})", key, fields_[key].line),
             "keep one of them");
      }
      fields_[key] = {value, n};
      if (key == "ElementDataFile") return bytes;  // the last field: the data follows
    }
    fail(n, "no 'ElementDataFile' field, which ends a MetaImage header (the data follows it)",
         "end the header with 'ElementDataFile = LOCAL' (data in this file) or the data file's name");
  }

  bool has(const char* key) const { return fields_.count(key) != 0; }
  const std::string& value(const char* key) const {
    static const std::string none;
    const auto it = fields_.find(key);
    return it == fields_.end() ? none : it->second.value;
  }
  int line(const char* key) const { return has(key) ? fields_.at(key).line : 0; }

  [[noreturn]] void fail(int line, const std::string& what, const std::string& fix) const {
    input_error("'{}' (MetaImage header, line {}): {}; {}", path_.string(), line, what, fix);
  }

  // The field's value as `count` numbers (whole ones > 0, numbers > 0, or any finite numbers).
  enum class Kind { Positive, PositiveWhole, Finite };
  std::vector<double> numbers(const char* key, std::size_t count, Kind kind) const {
    std::istringstream in(value(key));
    std::vector<double> out;
    for (std::string word; in >> word;) {
      char* end = nullptr;
      const double v = std::strtod(word.c_str(), &end);
      const bool whole = v == std::floor(v) && word.find_first_not_of("0123456789+") == std::string::npos;
      const bool ok = *end == '\0' && std::isfinite(v) && (kind == Kind::Finite || v > 0) &&
                      (kind != Kind::PositiveWhole || (whole && v <= 2147483647.0));
      if (!ok) {
        fail(line(key), fmt::format("'{} = {}': '{}' is not {}", key, excerpt(value(key)), excerpt(word, 40),
                                    kind == Kind::Finite         ? "a number"
                                    : kind == Kind::Positive     ? "a number > 0"
                                                                 : "a whole number > 0"),
             fmt::format("give {} such numbers", count));
      }
      out.push_back(v);
    }
    if (out.size() != count) {
      fail(line(key), fmt::format("'{} = {}' holds {} numbers, but NDims = {} calls for {}", key,
                                  excerpt(value(key)), out.size(), value("NDims"), count),
           "give one per axis (a matrix: NDims x NDims), or fix NDims");
    }
    return out;
  }

 private:
  void check_key(const std::string& key, int n) const {
    const bool printable = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
      return c > ' ' && c < 127;
    });
    if (!printable) fail(n, fmt::format("'{}' is not a field name", excerpt(key)), "fix or remove the line");
    // MetaIO copies a field's name into a buffer of 255 bytes without a
    // bound: a longer one overflowed it (found by fuzzing).
    if (key.size() > kMaxKey) {
      fail(n, fmt::format("a field name of {} characters ('{}'), more than the {} a MetaImage field name takes",
                          key.size(), excerpt(key, 40), kMaxKey),
           "shorten it or remove the line");
    }
    if (std::find(kFields.begin(), kFields.end(), key) != kFields.end()) return;
    for (const std::string_view known : kFields) {
      if (edit_distance(lower(key), lower(known)) <= 2 && key.size() > 3) {
        fail(n, fmt::format("'{}' is not a MetaImage field (a misspelt '{}'?)", key, known),
             "correct its spelling (MetaImage field names are case-sensitive)");
      }
    }
  }

  void check_text(const std::string& key, const std::string& value, int n) const {
    // MetaIO copies a text value (ObjectType, Name, Comment, ...) into a
    // buffer of 255 bytes without a bound: a longer one overflowed it (found
    // by fuzzing); numbers it parses, so lists of numbers may be longer.
    const bool numbers = value.find_first_not_of("0123456789+-.eE \t") == std::string::npos;
    if (!numbers && value.size() > kMaxText) {
      fail(n, fmt::format("the value of '{}' is a text of {} characters, more than the {} a MetaImage text field "
                          "holds",
                          key, value.size(), kMaxText),
           key == "ElementDataFile" ? "give the data file's path relative to the header's folder (move the data file "
                                      "beside the header and name the file alone)"
                                    : "shorten it");
    }
    if (value.size() > kMaxValue) {
      fail(n, fmt::format("the value of '{}' has {} characters, more than the {} a MetaImage field holds", key,
                          value.size(), kMaxValue),
           "shorten it");
    }
    for (const char c : value) {
      const auto u = static_cast<unsigned char>(c);
      if ((u < ' ' && c != '\t') || u == 127) {
        fail(n, fmt::format("the value of '{}' holds the control character 0x{:02x}", key, u),
             "the header is damaged, or this is not a MetaImage file: export the scan again");
      }
    }
  }

  fs::path path_;
  std::map<std::string, Field> fields_;
};

bool is_bool(const std::string& v) {
  const std::string l = lower(v);
  return l == "true" || l == "false" || l == "t" || l == "f" || l == "1" || l == "0";
}

bool is_true(const std::string& v) {
  const std::string l = lower(v);
  return l == "true" || l == "t" || l == "1";
}

std::int64_t whole(const Header& h, const char* key, std::int64_t lowest, std::int64_t highest) {
  const std::string& v = h.value(key);
  char* end = nullptr;
  const long long n = std::strtoll(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || n < lowest || n > highest) {
    h.fail(h.line(key), fmt::format("'{} = {}' is not a whole number from {} to {}", key, excerpt(v), lowest, highest),
           "fix the value");
  }
  return n;
}

// The header's fields, checked for what they are and against one another.
void check_fields(const Header& h) {
  if (!h.has("NDims")) h.fail(h.line("ElementDataFile"), "no 'NDims' field", "add 'NDims = 3' before it");
  const auto dims = static_cast<std::size_t>(whole(h, "NDims", 1, 10));
  using Kind = Header::Kind;
  if (!h.has("DimSize")) h.fail(h.line("ElementDataFile"), "no 'DimSize' field", "add the image's size per axis");
  long double voxels = 1;  // the image's voxels, bounded so that its byte count cannot overflow
  for (const double n : h.numbers("DimSize", dims, Kind::PositiveWhole)) voxels *= n;
  if (voxels > 0x1p50L) {
    h.fail(h.line("DimSize"), fmt::format("'DimSize = {}' makes {:.3g} voxels, more than any scan", h.value("DimSize"),
                                          static_cast<double>(voxels)),
           "fix DimSize");
  }
  for (const char* key : {"ElementSpacing", "ElementSize"}) {
    if (h.has(key)) h.numbers(key, dims, Kind::Positive);
  }
  for (const char* key : {"Offset", "Origin", "Position", "CenterOfRotation"}) {
    if (h.has(key)) h.numbers(key, dims, Kind::Finite);
  }
  for (const char* key : {"TransformMatrix", "Rotation", "Orientation"}) {
    if (h.has(key)) h.numbers(key, dims * dims, Kind::Finite);
  }
  if (!h.has("ElementType")) h.fail(h.line("ElementDataFile"), "no 'ElementType' field", "add it (e.g. MET_USHORT)");
  if (element_bytes(h.value("ElementType")) == 0) {
    h.fail(h.line("ElementType"), fmt::format("'ElementType = {}' is not a MetaImage element type",
                                              excerpt(h.value("ElementType"))),
           "use one of MET_UCHAR, MET_CHAR, MET_USHORT, MET_SHORT, MET_UINT, MET_INT, MET_ULONG, MET_LONG, "
           "MET_ULONG_LONG, MET_LONG_LONG, MET_FLOAT, MET_DOUBLE");
  }
  for (const char* key : {"BinaryData", "CompressedData", "BinaryDataByteOrderMSB", "ElementByteOrderMSB"}) {
    if (h.has(key) && !is_bool(h.value(key))) {
      h.fail(h.line(key), fmt::format("'{} = {}' is neither True nor False", key, excerpt(h.value(key))),
             "write True or False");
    }
  }
  if (h.has("ElementNumberOfChannels")) whole(h, "ElementNumberOfChannels", 1, 64);
  if (h.has("CompressedDataSize")) whole(h, "CompressedDataSize", 0, INT64_MAX);
  if (h.has("HeaderSize")) whole(h, "HeaderSize", -1, INT64_MAX);
}

// ElementDataFile = LIST [D]: the slice files' names follow the header, one
// a line, one per D-dimensional slice: the product of DimSize past its first
// D axes (D = NDims - 1 when not given or not 1 to NDims). MetaIO took an
// empty line for a name and read through a wild pointer (found by fuzzing:
// exit 139), and it reads "LIST..." (any word starting so) the same way: the
// field must be LIST and each line the name of a file.
void check_slice_list(const Header& h, const fs::path& path, std::uint64_t header_bytes) {
  const int at = h.line("ElementDataFile");
  std::istringstream words(h.value("ElementDataFile"));
  std::string list, dim_word, extra;
  words >> list >> dim_word >> extra;
  const auto ndims = static_cast<std::size_t>(std::atoll(h.value("NDims").c_str()));
  const std::size_t dim = dim_word.empty() ? ndims - 1 : static_cast<std::size_t>(std::atoll(dim_word.c_str()));
  if (list != "LIST" || !extra.empty() ||
      (!dim_word.empty() && dim_word.find_first_not_of("0123456789") != std::string::npos)) {
    h.fail(at, fmt::format("'ElementDataFile = {}' starts with LIST, which MetaIO reads as a list of slice files, "
                           "but is not 'LIST' or 'LIST D' (D: the slices' dimension)",
                           excerpt(h.value("ElementDataFile"))),
           "write 'ElementDataFile = LIST' followed by the slice files' names, one a line, or rename the data file");
  }
  const std::vector<double> sizes = h.numbers("DimSize", ndims, Header::Kind::PositiveWhole);
  double files = 1;
  for (std::size_t d = (dim >= 1 && dim <= ndims) ? dim : ndims - 1; d < ndims; ++d) files *= sizes[d];
  if (files > 1e6) h.fail(at, fmt::format("a list of {:.3g} slice files", files), "join the slices into one file");
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(header_bytes));
  std::string name;
  for (int k = 1; k <= static_cast<int>(files); ++k) {
    const bool got = static_cast<bool>(bounded_getline(in, name, kMaxText, path.string(), "a MetaImage slice list"));
    name = trim(name);
    const bool printable = std::all_of(name.begin(), name.end(), [](char c) {
      return static_cast<unsigned char>(c) >= ' ' && c != 127;
    });
    std::error_code ec;
    const fs::path file = fs::path(name).is_absolute() ? fs::path(name) : path.parent_path() / name;
    if (!got || name.empty() || !printable || !fs::is_regular_file(file, ec)) {
      h.fail(at + k, fmt::format("slice file {} of the {} that 'ElementDataFile = LIST' and DimSize call for {}", k,
                                 static_cast<std::uint64_t>(files),
                                 !got            ? "is missing (the file ends)"
                                 : name.empty()  ? "is an empty line"
                                 : !printable    ? "holds a control character"
                                                 : fmt::format("'{}' does not exist or is not a regular file",
                                                               excerpt(file.string(), 200))),
             "list one slice file a line after the header, each next to the header or by its full path");
    }
  }
}

// ElementDataFile = PATTERN MIN MAX STEP [D]: MetaIO formats each slice's name
// with PATTERN as a printf format, so PATTERN must hold one whole-number
// conversion (%d, %03d) and nothing else a printf reads ("%s" would read
// through a wild pointer).
void check_slice_pattern(const Header& h) {
  const int at = h.line("ElementDataFile");
  std::istringstream words(h.value("ElementDataFile"));
  std::string pattern;
  words >> pattern;
  std::vector<std::string> numbers;
  for (std::string w; words >> w;) numbers.push_back(w);
  const auto percent = pattern.find('%');
  std::size_t i = percent + 1;
  while (i < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[i]))) ++i;
  const bool one_d = i < pattern.size() && pattern[i] == 'd' && pattern.find('%', i) == std::string::npos;
  const bool whole = std::all_of(numbers.begin(), numbers.end(), [](const std::string& w) {
    return !w.empty() && w.size() < 10 && w.find_first_not_of("0123456789-+", 0) == std::string::npos;
  });
  if (!one_d || !whole || numbers.size() < 3 || numbers.size() > 4) {
    h.fail(at, fmt::format("'ElementDataFile = {}' is not a slice pattern 'NAME%03d.raw MIN MAX STEP' (one %d "
                           "conversion and three or four whole numbers)",
                           excerpt(h.value("ElementDataFile"))),
           "write the pattern so, LOCAL, or the data file's name (without '%')");
  }
}

}  // namespace

void check_metaimage_header(const fs::path& path, bool compressed_data) {
  Header h(path);
  const std::uint64_t header_bytes = h.read();
  check_fields(h);
  const std::string& data_file = h.value("ElementDataFile");
  if (data_file.rfind("LIST", 0) == 0) return check_slice_list(h, path, header_bytes);
  if (data_file.find('%') != std::string::npos) return check_slice_pattern(h);  // the slices: MetaIO's
  fs::path data = path;
  if (data_file != "LOCAL") {
    data = fs::path(data_file).is_absolute() ? fs::path(data_file) : path.parent_path() / data_file;
    std::error_code ec;
    if (!fs::is_regular_file(data, ec)) {
      h.fail(h.line("ElementDataFile"),
             fmt::format("its data file '{}' does not exist or is not a regular file", excerpt(data.string(), 200)),
             "copy the data file next to the header, or write 'ElementDataFile = LOCAL' when the data follows the "
             "header in this file");
    }
  }
  const bool compressed = is_true(h.value("CompressedData"));
  const bool binary = !h.has("BinaryData") || is_true(h.value("BinaryData"));
  const int bytes = element_bytes(h.value("ElementType"));
  std::uint64_t need = declared_bytes(h.value("DimSize"), bytes);
  const std::string& channels = h.value("ElementNumberOfChannels");
  if (!channels.empty()) need *= static_cast<std::uint64_t>(std::atoll(channels.c_str()));
  if (compressed) {
    if (!compressed_data) return;
    // MetaIO inflated until the image was full, for ever when the stream
    // broke or ended first (compressed_data.h).
    const std::uint64_t size = h.has("CompressedDataSize") ? std::atoll(h.value("CompressedDataSize").c_str()) : 0;
    const InflatedPrefix got = inflate_prefix(data, data_file == "LOCAL" ? header_bytes : 0, size, need);
    if (got.produced < need) {
      h.fail(h.line("ElementDataFile"),
             fmt::format("its compressed data {} after {} of the {} bytes that 'DimSize = {}' of 'ElementType = {}' "
                         "call for",
                         got.error.empty() ? "ends" : "is broken (zlib: " + excerpt(got.error, 80) + ")", got.produced,
                         need, h.value("DimSize"), h.value("ElementType")),
             "copy the file again, or fix DimSize and ElementType");
    }
    return;
  }
  if (!binary) return;  // MetaIO reads ASCII data by its own lengths
  DeclaredData d{path, "MetaImage",
                 fmt::format("'DimSize = {}' of 'ElementType = {}'{}", h.value("DimSize"), h.value("ElementType"),
                             channels.empty() ? "" : fmt::format(" x {} channels", channels)),
                 need, data, header_bytes, false, "'DimSize' and 'ElementType'"};
  if (data_file != "LOCAL") {
    const std::int64_t skip = h.has("HeaderSize") ? std::atoll(h.value("HeaderSize").c_str()) : 0;
    d.offset = skip > 0 ? static_cast<std::uint64_t>(skip) : 0;
    d.at_end = skip == -1;
  }
  check_declared_data(d);
}

}  // namespace grainlab::ct
