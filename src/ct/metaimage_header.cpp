#include "ct/metaimage_header.h"

#include "core/bounded_line.h"
#include "ct/declared_data.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

namespace grainlab::ct {

namespace fs = std::filesystem;

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

int element_bytes(const std::string& type) {
  static const std::map<std::string, int> bytes = {
      {"MET_CHAR", 1},  {"MET_UCHAR", 1}, {"MET_SHORT", 2},     {"MET_USHORT", 2},     {"MET_INT", 4},
      {"MET_UINT", 4},  {"MET_LONG", 4},  {"MET_ULONG", 4},     {"MET_LONG_LONG", 8},  {"MET_ULONG_LONG", 8},
      {"MET_FLOAT", 4}, {"MET_DOUBLE", 8}};
  const auto it = bytes.find(type);
  return it == bytes.end() ? 0 : it->second;
}

}  // namespace

void check_metaimage_data_size(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::map<std::string, std::string> fields;
  std::uint64_t header_bytes = 0;
  constexpr std::size_t kMaxHeaderLine = 64 * 1024;  // a header line: a key and a few numbers or a file name
  for (std::string line; bounded_getline(in, line, kMaxHeaderLine, path.string(), "a MetaImage header");) {
    header_bytes += line.size() + 1;
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = trim(line.substr(0, eq));
    fields[key] = trim(line.substr(eq + 1));
    if (key == "ElementDataFile") break;  // the last field: the data follows
  }
  auto field = [&](const char* key) { return fields.count(key) ? fields[key] : std::string(); };
  const std::string data_file = field("ElementDataFile");
  const int bytes = element_bytes(field("ElementType"));
  if (data_file.empty() || bytes == 0 || field("CompressedData") == "True" || field("BinaryData") == "False") return;
  if (data_file.rfind("LIST", 0) == 0 || data_file.find_first_of("% ") != std::string::npos) return;  // several files
  std::uint64_t need = declared_bytes(field("DimSize"), bytes);
  if (need == 0) return;  // ITK names the problem
  const std::string channels = field("ElementNumberOfChannels");
  if (!channels.empty()) need *= static_cast<std::uint64_t>(std::max(1LL, std::atoll(channels.c_str())));
  DeclaredData d{path, "MetaImage",
                 fmt::format("'DimSize = {}' of 'ElementType = {}'{}", field("DimSize"), field("ElementType"),
                             channels.empty() ? "" : fmt::format(" x {} channels", channels)),
                 need, path, header_bytes, false, "'DimSize' and 'ElementType'"};
  if (data_file != "LOCAL") {
    d.data = fs::path(data_file).is_absolute() ? fs::path(data_file) : path.parent_path() / data_file;
    const std::int64_t skip = field("HeaderSize").empty() ? 0 : std::atoll(field("HeaderSize").c_str());
    d.offset = skip > 0 ? static_cast<std::uint64_t>(skip) : 0;
    d.at_end = skip == -1;
  }
  check_declared_data(d);
}

}  // namespace grainlab::ct
