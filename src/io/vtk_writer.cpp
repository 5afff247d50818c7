// VTK XML PolyData and .pvd writing (see vtk_writer.h for the encoding).
#include "io/vtk_writer.h"

#include "core/atomic_file.h"
#include "io/base64.h"
#include "io/zlib_blocks.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <span>
#include <stdexcept>

namespace grainlab {

// The binary arrays are the values' bytes in memory, declared LittleEndian.
static_assert(std::endian::native == std::endian::little, "the VTK writer assumes a little-endian host");

std::size_t VtkArray::value_count() const {
  return std::visit([](const auto& v) { return v.size(); }, values);
}

const char* VtkArray::type_name() const {
  switch (values.index()) {
    case 0: return "Float64";
    case 1: return "Float32";
    default: return "Int32";
  }
}

void VtkCells::add(std::initializer_list<std::int64_t> ids) {
  connectivity.insert(connectivity.end(), ids.begin(), ids.end());
  offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
}

namespace {

void check_cells(const VtkCells& c, const char* kind, std::size_t n_points) {
  std::int64_t prev = 0;
  for (std::size_t i = 0; i < c.offsets.size(); ++i) {
    if (c.offsets[i] < prev)
      throw std::invalid_argument(fmt::format("PolyData {}: offset {} ({}) is below the previous one ({})", kind,
                                              i, c.offsets[i], prev));
    prev = c.offsets[i];
  }
  if (static_cast<std::size_t>(prev) != c.connectivity.size())
    throw std::invalid_argument(fmt::format("PolyData {}: the last offset is {} but the connectivity has {} entries",
                                            kind, prev, c.connectivity.size()));
  for (std::size_t i = 0; i < c.connectivity.size(); ++i)
    if (c.connectivity[i] < 0 || static_cast<std::size_t>(c.connectivity[i]) >= n_points)
      throw std::invalid_argument(fmt::format("PolyData {}: connectivity entry {} is point {}, but there are {} points",
                                              kind, i, c.connectivity[i], n_points));
}

void check_arrays(const std::vector<VtkArray>& arrays, const char* where, std::size_t tuples) {
  std::set<std::string> names;
  for (const VtkArray& a : arrays) {
    if (a.name.empty()) throw std::invalid_argument(fmt::format("PolyData {}: an array has no name", where));
    if (!names.insert(a.name).second)
      throw std::invalid_argument(fmt::format("PolyData {}: two arrays are named '{}'", where, a.name));
    if (a.components < 1)
      throw std::invalid_argument(fmt::format("PolyData {} array '{}': {} components", where, a.name, a.components));
    if (a.value_count() != tuples * static_cast<std::size_t>(a.components))
      throw std::invalid_argument(fmt::format("PolyData {} array '{}': {} values, expected {} tuples of {}", where,
                                              a.name, a.value_count(), tuples, a.components));
  }
}

// The text with XML's five special characters escaped, for attribute values.
std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

template <typename T>
std::span<const std::uint8_t> bytes_of(const std::vector<T>& v) {
  return {reinterpret_cast<const std::uint8_t*>(v.data()), v.size() * sizeof(T)};
}

// The base64 payload of one DataArray: the UInt64 byte count and then the
// values, as one base64 stream. The 8 header bytes and the first value byte
// make 3 whole groups, so the rest is encoded straight from the values.
void append_payload(std::string& out, std::span<const std::uint8_t> bytes) {
  const std::uint64_t n = bytes.size();
  std::uint8_t head[sizeof n + 1];
  std::memcpy(head, &n, sizeof n);
  const std::size_t first = bytes.empty() ? 0 : 1;
  if (first) head[sizeof n] = bytes[0];
  base64_append(out, std::span<const std::uint8_t>(head, sizeof n + first));
  base64_append(out, bytes.subspan(first));
}

// Writes DataArray elements with their data inline, or as references into
// the appended section it collects (then written by finish()).
class ArrayWriter {
 public:
  explicit ArrayWriter(VtpEncoding encoding) : encoding_(encoding) {}

  // A DataArray of `type` whose values are `bytes`; components 0 leaves the attribute out.
  void write(std::string& out, const char* indent, const char* type, std::string_view name, int components,
             std::span<const std::uint8_t> bytes) {
    out += fmt::format("{}<DataArray type=\"{}\" Name=\"{}\"", indent, type, xml_escape(name));
    if (components > 0) out += fmt::format(" NumberOfComponents=\"{}\"", components);
    if (encoding_ == VtpEncoding::Inline) {
      out += " format=\"binary\">";
      append_payload(out, bytes);
      out += "</DataArray>\n";
    } else {
      out += fmt::format(" format=\"appended\" offset=\"{}\"/>\n", appended_.size());
      append_zlib_blocks(appended_, bytes);
    }
  }

  void write(std::string& out, const char* indent, const VtkArray& a) {
    std::visit([&](const auto& v) { write(out, indent, a.type_name(), a.name, a.components, bytes_of(v)); }, a.values);
  }

  // Cell connectivity or offsets: Int64 inline; Int32 compressed when every value fits.
  void write_cells(std::string& out, const char* name, const std::vector<std::int64_t>& v) {
    const bool narrow = encoding_ == VtpEncoding::Compressed &&
                        std::all_of(v.begin(), v.end(), [](std::int64_t x) {
                          return x >= 0 && x <= std::numeric_limits<std::int32_t>::max();
                        });
    if (!narrow) return write(out, "        ", "Int64", name, 0, bytes_of(v));
    const std::vector<std::int32_t> v32(v.begin(), v.end());
    write(out, "        ", "Int32", name, 0, bytes_of(v32));
  }

  // The appended section, if any, before </VTKFile>.
  void finish(std::string& out) const {
    if (encoding_ == VtpEncoding::Inline) return;
    out += "  <AppendedData encoding=\"raw\">\n   _";
    out += appended_;
    out += "\n  </AppendedData>\n";
  }

 private:
  VtpEncoding encoding_;
  std::string appended_;
};

void append_cells(std::string& out, ArrayWriter& w, const char* element, const VtkCells& c) {
  if (c.size() == 0) return;
  out += fmt::format("      <{}>\n", element);
  w.write_cells(out, "connectivity", c.connectivity);
  w.write_cells(out, "offsets", c.offsets);
  out += fmt::format("      </{}>\n", element);
}

void append_data(std::string& out, ArrayWriter& w, const char* element, const std::vector<VtkArray>& arrays) {
  if (arrays.empty()) return;
  out += fmt::format("      <{}>\n", element);
  for (const VtkArray& a : arrays) w.write(out, "        ", a);
  out += fmt::format("      </{}>\n", element);
}

}  // namespace

void check_polydata(const PolyData& pd) {
  if (pd.points.components != 3 || pd.points.values.index() == 2)
    throw std::invalid_argument("PolyData points must be Float64 or Float32 with 3 components");
  if (pd.points.value_count() % 3 != 0)
    throw std::invalid_argument(fmt::format("PolyData points: {} values is not a multiple of 3",
                                            pd.points.value_count()));
  const std::size_t n = pd.point_count();
  check_cells(pd.verts, "verts", n);
  check_cells(pd.lines, "lines", n);
  check_cells(pd.polys, "polys", n);
  check_arrays(pd.point_data, "point data", n);
  check_arrays(pd.cell_data, "cell data", pd.cell_count());
}

std::string vtp_text(const PolyData& pd, VtpEncoding encoding) {
  check_polydata(pd);
  std::string out;
  if (encoding == VtpEncoding::Inline) {
    std::size_t bytes = pd.points.value_count() * 8 + 8 * (pd.verts.connectivity.size() +
                                                           pd.lines.connectivity.size() +
                                                           pd.polys.connectivity.size() + pd.cell_count());
    for (const auto* list : {&pd.point_data, &pd.cell_data})
      for (const VtkArray& a : *list) bytes += a.value_count() * 8;
    out.reserve(bytes / 3 * 4 + 4096);
  }
  ArrayWriter w(encoding);

  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  out += encoding == VtpEncoding::Compressed ? " compressor=\"vtkZLibDataCompressor\">\n" : ">\n";
  out += "  <PolyData>\n";
  out += fmt::format(
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" NumberOfStrips=\"0\" "
      "NumberOfPolys=\"{}\">\n",
      pd.point_count(), pd.verts.size(), pd.lines.size(), pd.polys.size());
  append_data(out, w, "PointData", pd.point_data);
  append_data(out, w, "CellData", pd.cell_data);
  out += "      <Points>\n";
  w.write(out, "        ", pd.points);
  out += "      </Points>\n";
  append_cells(out, w, "Verts", pd.verts);
  append_cells(out, w, "Lines", pd.lines);
  append_cells(out, w, "Polys", pd.polys);
  out += "    </Piece>\n";
  out += "  </PolyData>\n";
  w.finish(out);
  out += "</VTKFile>\n";
  return out;
}

void write_vtp(const std::filesystem::path& path, const PolyData& pd, VtpEncoding encoding) {
  write_file_atomically(path, vtp_text(pd, encoding));
}

std::string pvd_text(const std::vector<PvdEntry>& entries) {
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  // Times in the shortest decimal that reads back to the same double.
  for (const PvdEntry& e : entries)
    out += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.time,
                       xml_escape(e.file));
  out += "  </Collection>\n";
  out += "</VTKFile>\n";
  return out;
}

void PvdCollection::add(double time, std::string file) {
  if (!std::isfinite(time))
    throw std::invalid_argument(fmt::format("{}: snapshot time {} is not finite", path_.string(), time));
  if (file.empty()) throw std::invalid_argument(fmt::format("{}: snapshot file name is empty", path_.string()));
  const std::vector<PvdEntry> before = entries_;
  const auto same = std::find_if(entries_.begin(), entries_.end(), [&](const PvdEntry& e) { return e.file == file; });
  if (same != entries_.end()) {
    same->time = time;
  } else {
    entries_.push_back({time, std::move(file)});
  }
  try {
    write_file_atomically(path_, pvd_text(entries_));
  } catch (...) {
    entries_ = before;  // as the file on disk still is
    throw;
  }
}

}  // namespace grainlab
