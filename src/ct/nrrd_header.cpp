#include "core/text.h"
#include "ct/nrrd_header.h"

#include "core/bounded_line.h"
#include "core/error.h"
#include "ct/declared_data.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <vector>

namespace grainlab::ct {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxHeaderLine = 64 * 1024;  // a header line: a field and a few numbers or a file name
constexpr std::size_t kMaxFieldLine = 900;         // a field's line ("name: value"): what teem's messages take
constexpr std::uint64_t kMaxAsciiValue = 1000;     // an ASCII value's characters: teem's buffer holds 1024

// deflate (gzip) turns one byte into at most 1032 (its longest match, 258
// bytes, costs at least 2 bits): a bound on what compressed data can hold.
constexpr std::uint64_t kDeflateMaxRatio = 1032;

// "m" "mm" "" -> {m, mm, ""}; unquoted words are taken as they are.
std::vector<std::string> quoted_list(const std::string& value) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < value.size()) {
    if (std::isspace(static_cast<unsigned char>(value[i]))) {
      ++i;
    } else if (value[i] == '"') {
      const auto end = value.find('"', i + 1);
      out.push_back(value.substr(i + 1, (end == std::string::npos ? value.size() : end) - i - 1));
      i = end == std::string::npos ? value.size() : end + 1;
    } else {
      const auto end = value.find_first_of(" \t", i);
      out.push_back(value.substr(i, (end == std::string::npos ? value.size() : end) - i));
      i = end == std::string::npos ? value.size() : end;
    }
  }
  return out;
}

// Bytes per value of an NRRD type name (teem's spellings), 0 when unknown or "block".
int type_bytes(const std::string& type) {
  std::string t = lower(type);
  for (const char* prefix : {"signed ", "unsigned "}) {
    if (t.rfind(prefix, 0) == 0) t = t.substr(std::string(prefix).size());
  }
  if (t.size() > 2 && t.compare(t.size() - 2, 2, "_t") == 0) t.resize(t.size() - 2);
  if (!t.empty() && t[0] == 'u' && t != "uchar" && t != "ushort" && t != "uint" && t != "ulonglong") {
    t = t.substr(1);  // uint8 -> int8
  }
  static const std::map<std::string, int> bytes = {
      {"char", 1},      {"uchar", 1},    {"int8", 1},      {"short", 2},     {"short int", 2}, {"ushort", 2},
      {"int16", 2},     {"int", 4},      {"uint", 4},      {"int32", 4},     {"long long", 8}, {"long long int", 8},
      {"longlong", 8},  {"ulonglong", 8}, {"int64", 8},    {"float", 4},     {"double", 8}};
  const auto it = bytes.find(t);
  return it == bytes.end() ? 0 : it->second;
}

std::string field(const NrrdHeader& h, const std::string& name) {
  const auto it = h.fields.find(name);
  return it == h.fields.end() ? "" : it->second;
}

// A vector field ("space directions", "space origin", "measurement frame")
// is "(x,y,z)" vectors of numbers, or "none" for an axis. A malformed vector
// made teem overflow a buffer on its stack (found by fuzzing: a number of
// hundreds of characters), so each is checked: at most 16 vectors of 16
// numbers, each number whole to strtod, finite and at most 40 characters.
void check_vector_field(const fs::path& path, int line_number, const std::string& name, const std::string& value) {
  const auto refuse = [&](const std::string& what) {
    input_error("'{}': NRRD header line {} ('{}: {}'): {}; write vectors as (x,y,z) with plain numbers, e.g. "
                "(0.025,0,0), or none for a non-spatial axis; the file is damaged, write it again",
                path.string(), line_number, name, excerpt(value, 60), what);
  };
  std::size_t i = 0, vectors = 0;
  while (i < value.size()) {
    if (value[i] == ' ' || value[i] == '\t') {
      ++i;
      continue;
    }
    if (++vectors > 16) refuse("more than 16 vectors");
    if (value.compare(i, 4, "none") == 0) {
      i += 4;
      continue;
    }
    if (value[i] != '(') refuse(fmt::format("'{}' where a vector '(' or 'none' starts", excerpt(value.substr(i), 20)));
    const auto close = value.find(')', i);
    if (close == std::string::npos) refuse("a vector without its ')'");
    const std::string inside = value.substr(i + 1, close - i - 1);
    std::size_t start = 0, numbers = 0;
    while (true) {
      const auto comma = inside.find(',', start);
      const std::string number = trim(inside.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      char* end = nullptr;
      const double v = std::strtod(number.c_str(), &end);
      if (number.empty() || number.size() > 40 || *end != '\0' || !std::isfinite(v))
        refuse(fmt::format("'{}' is not a number", excerpt(number, 40)));
      if (++numbers > 16) refuse("a vector of more than 16 numbers");
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    i = close + 1;
  }
}

}  // namespace

double metres_per_unit(const std::string& unit) {
  const std::string u = lower(trim(unit));
  if (u.empty() || u == "???" || u == "none") return 0;
  static const std::map<std::string, double> units = {
      {"m", 1},          {"meter", 1},          {"meters", 1},          {"metre", 1},          {"metres", 1},
      {"cm", 1e-2},      {"centimeter", 1e-2},  {"centimeters", 1e-2},  {"centimetre", 1e-2},  {"centimetres", 1e-2},
      {"mm", 1e-3},      {"millimeter", 1e-3},  {"millimeters", 1e-3},  {"millimetre", 1e-3},  {"millimetres", 1e-3},
      {"um", 1e-6},      {"\xc2\xb5m", 1e-6},   {"\xce\xbcm", 1e-6},    {"micron", 1e-6},      {"microns", 1e-6},
      {"micrometer", 1e-6}, {"micrometers", 1e-6}, {"micrometre", 1e-6}, {"micrometres", 1e-6},
      {"nm", 1e-9},      {"nanometer", 1e-9},   {"nanometers", 1e-9},   {"nanometre", 1e-9},   {"nanometres", 1e-9}};
  const auto it = units.find(u);
  return it == units.end() ? -1 : it->second;
}

NrrdHeader read_nrrd_header(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!in || !bounded_getline(in, line, kMaxHeaderLine, path.string(), "an NRRD header") ||
      line.rfind("NRRD000", 0) != 0) {
    input_error("'{}' is not an NRRD file: it does not start with the NRRD magic line (\"NRRD0004\"); check the "
                "file, or its extension",
                path.string());
  }
  NrrdHeader h;
  h.header_bytes = line.size() + 1;
  for (int line_number = 2; bounded_getline(in, line, kMaxHeaderLine, path.string(), "an NRRD header");
       ++line_number) {
    h.header_bytes += line.size() + 1;
    if (trim(line).empty()) break;  // the blank line before attached data
    const auto colon = line.find(": ");
    // Comments, and key/value pairs ("key:=value"; teem takes a line that
    // starts "name: " for a field even when ":=" follows).
    if (line[0] == '#' || line.find(":=") < colon) continue;
    // Every other line is a field, "name: value". A line of neither made
    // ITK's NRRD reader (teem) overflow a buffer and abort (found by fuzzing).
    if (colon == std::string::npos)
      input_error("'{}': NRRD header line {} ('{}') is neither a field ('name: value'), a comment ('#') nor a "
                  "key/value pair ('key:=value'); the file is damaged, write it again",
                  path.string(), line_number, excerpt(line, 60));
    // teem quotes a field it cannot parse whole in a message buffer of fixed
    // size on its stack: a 4 kB line overflowed it (found by fuzzing), lines
    // of 900 characters of every field it cannot parse do not.
    if (line.size() > kMaxFieldLine)
      input_error("'{}': NRRD header line {} ('{}') has {} characters, more than the {} a field of an NRRD header "
                  "takes (ITK's NRRD reader overflows on longer ones); the file is damaged, write it again",
                  path.string(), line_number, excerpt(line, 60), line.size(), kMaxFieldLine);
    std::string name;
    for (char c : lower(line.substr(0, colon))) {
      if (c != ' ') name += c;
    }
    h.fields[name] = trim(line.substr(colon + 2));
    if (name == "spacedirections" || name == "spaceorigin" || name == "measurementframe")
      check_vector_field(path, line_number, line.substr(0, colon), h.fields[name]);
  }
  return h;
}

NrrdUnits nrrd_units(const NrrdHeader& h, const fs::path& path) {
  // "space units" goes with "space directions"; per-axis "units" with "spacings".
  const bool space = h.fields.count("spacedirections") > 0;
  const std::string units_field = space ? "space units" : "units";
  const std::string spacing_field = space ? "space directions" : "spacings";
  const std::string value = field(h, space ? "spaceunits" : "units");
  NrrdUnits u;
  const std::vector<std::string> names = quoted_list(value);
  std::array<double, 3> factor{0, 0, 0};
  for (std::size_t a = 0; a < std::min<std::size_t>(3, names.size()); ++a) {
    factor[a] = metres_per_unit(names[a]);
    if (factor[a] < 0) {
      input_error("'{}': NRRD '{}' \"{}\" is not a length unit grainlab knows (m, cm, mm, um, \xc2\xb5m, microns, "
                  "nm): fix the header, or give the voxel size with --voxel-size in metres (e.g. --voxel-size 25e-6)",
                  path.string(), units_field, names[a]);
    }
  }
  const bool given = factor[0] > 0 || factor[1] > 0 || factor[2] > 0;
  if (!given) {
    u.source = fmt::format("header field '{}' read as mm (the file has no '{}')", spacing_field, units_field);
    return u;
  }
  if (!(factor[0] > 0 && factor[1] > 0 && factor[2] > 0)) {
    input_error("'{}': NRRD '{}: {}' gives a unit for some axes and not others: give all three, or the voxel size "
                "with --voxel-size in metres",
                path.string(), units_field, value);
  }
  u.metres_per_unit = Vec3(factor[0], factor[1], factor[2]);
  u.named = true;
  u.source = fmt::format("header field '{}' in the file's '{}: {}'", spacing_field, units_field, value);
  return u;
}

// An encoded (not raw) NRRD's data against the least room it needs: gzip
// data holds at most kDeflateMaxRatio bytes per byte, ASCII at least one
// character and a separator per value, hex two characters per byte; so a
// header that claims more than its file can hold is refused before ITK
// allocates the image it describes. bzip2 and zrl have no such cheap bound
// (`ct segment` still checks the image against the machine's memory).
void check_encoded_data_size(const NrrdHeader& h, const fs::path& path, const std::string& encoding) {
  const int bytes = type_bytes(field(h, "type"));
  const std::uint64_t need = bytes ? declared_bytes(field(h, "sizes"), bytes) : 0;
  if (need == 0 || !field(h, "datafile").empty()) return;  // ITK names the problem; detached: left to ITK
  std::error_code ec;
  const std::uint64_t file = fs::file_size(path, ec);
  if (ec) return;
  const std::uint64_t have = file > h.header_bytes ? file - h.header_bytes : 0;
  const std::uint64_t values = need / static_cast<std::uint64_t>(bytes);
  std::uint64_t least = 0;  // bytes of encoded data the header's image needs at least
  std::string why;
  if (encoding == "gzip" || encoding == "gz") {
    least = need / kDeflateMaxRatio;
    why = fmt::format("gzip packs at most {} bytes into one", kDeflateMaxRatio);
  } else if (encoding == "ascii" || encoding == "text" || encoding == "txt") {
    least = 2 * values - 1;
    why = "each value takes a digit and a separator";
  } else if (encoding == "hex") {
    least = 2 * need;
    why = "each byte takes two hex digits";
  } else {
    return;
  }
  if (have >= least) return;
  input_error("'{}' (NRRD, {} encoding) cannot hold the image its header describes: 'sizes: {}' of 'type: {}' ({} "
              "bytes) need at least {} bytes of encoded data ({}), but the file holds {} after its header; copy the "
              "file again, or fix 'sizes' and 'type' in the header",
              path.string(), encoding, excerpt(field(h, "sizes")), excerpt(field(h, "type")), need, least, why, have);
}

// teem reads each value of ASCII data with fscanf("%s") into a buffer of 1025
// characters on its stack, without a bound: a longer run of characters
// without a space overflowed it (found by fuzzing; release: `*** stack
// smashing detected ***`, exit 134). A number takes some 30 characters, so a
// run over kMaxAsciiValue is refused before ITK sees the file.
void check_ascii_values(const NrrdHeader& h, const fs::path& path) {
  const std::string data_file = field(h, "datafile");
  if (data_file.rfind("LIST", 0) == 0 || data_file.find('%') != std::string::npos) return;  // several files
  const fs::path data = data_file.empty() ? path
                        : fs::path(data_file).is_absolute() ? fs::path(data_file)
                                                            : path.parent_path() / data_file;
  std::ifstream in(data, std::ios::binary);
  if (!in) return;  // ITK names a missing data file
  std::uint64_t at = data_file.empty() ? h.header_bytes : 0;
  in.seekg(static_cast<std::streamoff>(at));
  std::uint64_t run = 0;
  std::array<char, 65536> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    const auto got = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < got; ++i, ++at) {
      run = std::isspace(static_cast<unsigned char>(buffer[i])) ? 0 : run + 1;
      if (run > kMaxAsciiValue) {
        input_error("'{}' (NRRD, ascii encoding): its data holds {} characters without a space at byte {}, where "
                    "each value is a number of a few characters (ITK's NRRD reader overflows on a value of more "
                    "than 1024); the data is damaged or not ASCII: export the scan again",
                    data.string(), run, at + 1 - run);
      }
    }
  }
}

void check_nrrd_data_size(const NrrdHeader& h, const fs::path& path) {
  if (const std::string encoding = lower(field(h, "encoding")); encoding != "raw") {
    if (encoding == "ascii" || encoding == "text" || encoding == "txt") check_ascii_values(h, path);
    check_encoded_data_size(h, path, encoding);
    return;
  }
  const int bytes = type_bytes(field(h, "type"));
  if (bytes == 0) return;  // ITK names an unknown type
  const std::uint64_t need = declared_bytes(field(h, "sizes"), bytes);
  if (need == 0) return;  // ITK names the problem
  const std::int64_t byte_skip = field(h, "byteskip").empty() ? 0 : std::atoll(field(h, "byteskip").c_str());
  const std::int64_t line_skip = field(h, "lineskip").empty() ? 0 : std::atoll(field(h, "lineskip").c_str());
  if (line_skip != 0) return;  // data after counted lines: left to ITK
  DeclaredData d{path, "NRRD", fmt::format("'sizes: {}' of 'type: {}'", field(h, "sizes"), field(h, "type")), need,
                 path, h.header_bytes, byte_skip == -1, "'sizes' and 'type'"};
  const std::string data_file = field(h, "datafile");
  if (!data_file.empty()) {
    if (data_file.rfind("LIST", 0) == 0 || data_file.find('%') != std::string::npos) return;  // several files
    d.data = fs::path(data_file).is_absolute() ? fs::path(data_file) : path.parent_path() / data_file;
    d.offset = 0;
  }
  if (byte_skip > 0) d.offset += static_cast<std::uint64_t>(byte_skip);
  check_declared_data(d);
}

}  // namespace grainlab::ct
