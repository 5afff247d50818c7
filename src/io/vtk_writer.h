// VTK XML PolyData (.vtp) files and ParaView .pvd collections, written by hand
// (no VTK library): a whole run opens in ParaView as one time series.
//
// Two encodings of the DataArrays (VtpEncoding):
// - Compressed (the default, what runs write): every array zlib-compressed in
//   VTK's blocks (compressor="vtkZLibDataCompressor", io/zlib_blocks.h) and
//   stored raw in one <AppendedData encoding="raw"> section after an '_', each
//   DataArray naming its byte offset there (format="appended", header_type
//   UInt64). Cell arrays are Int32 when every index fits. This is how VTK's
//   own writers store data by default; the file is XML up to the appended
//   section and binary after it. Snapshot arrays repeat each grain's values on
//   its points and each shape's triangles on every grain, which zlib packs
//   tightly: a snapshot is about 7x smaller per grain face than inline base64
//   with Float32 values (tests/io/snapshot_vtk_test.cpp measures it).
// - Inline: each DataArray inline binary, format="binary": one base64 stream
//   of a UInt64 byte count followed by the little-endian values; Int64 cells;
//   no compression. Header and values are encoded together, not as two padded
//   blocks: VTK's reader seeks into the decoded stream at byte offsets (it
//   reads PolyData cell data per cell kind), which lands on the wrong
//   characters if the header was padded apart (checked against VTK 9.1's
//   vtkXMLPolyDataReader). Well-formed XML throughout, four thirds of the bytes.
//
// Cells follow VTK's PolyData layout: for each cell kind (verts, lines, polys)
// a connectivity list of point indices and the offsets of each cell's end in
// it (no leading 0). Cell data holds one tuple per cell, verts first, then
// lines, then polys.
//
// Every file goes through write_file_atomically: a killed run leaves no torn file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <variant>
#include <vector>

namespace grainlab {

// A named array of tuples of `components` numbers, stored tuple after tuple.
struct VtkArray {
  using Values = std::variant<std::vector<double>, std::vector<float>, std::vector<std::int32_t>>;
  std::string name;
  int components = 1;
  Values values;

  std::size_t value_count() const;
  std::size_t tuple_count() const { return components > 0 ? value_count() / components : 0; }
  // "Float64", "Float32" or "Int32".
  const char* type_name() const;
  friend bool operator==(const VtkArray&, const VtkArray&) = default;
};

// Cells of one kind. Cell i uses connectivity[offsets[i-1], offsets[i]) with offsets[-1] = 0.
struct VtkCells {
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;

  std::size_t size() const { return offsets.size(); }
  // Appends one cell made of the given point indices.
  void add(std::initializer_list<std::int64_t> ids);
  friend bool operator==(const VtkCells&, const VtkCells&) = default;
};

// One PolyData piece: points, cells and the arrays on them.
struct PolyData {
  VtkArray points{"Points", 3, std::vector<double>{}};  // m; Float64 or Float32, 3 components
  VtkCells verts, lines, polys;
  std::vector<VtkArray> point_data;  // one tuple per point
  std::vector<VtkArray> cell_data;   // one tuple per cell: verts, then lines, then polys

  std::size_t point_count() const { return points.tuple_count(); }
  std::size_t cell_count() const { return verts.size() + lines.size() + polys.size(); }
  friend bool operator==(const PolyData&, const PolyData&) = default;
};

// Throws std::invalid_argument saying what is inconsistent: points not 3
// floating components, offsets not increasing or not ending at the
// connectivity size, a point index out of range, an array with the wrong
// number of tuples, an empty or repeated array name.
void check_polydata(const PolyData& pd);

// How a .vtp file stores its arrays (see the top of this file).
enum class VtpEncoding { Compressed, Inline };

// The .vtp file contents of `pd` (checked first).
std::string vtp_text(const PolyData& pd, VtpEncoding encoding = VtpEncoding::Compressed);

// Writes `pd` to `path` atomically (std::invalid_argument if inconsistent, RunError if the write fails).
void write_vtp(const std::filesystem::path& path, const PolyData& pd,
               VtpEncoding encoding = VtpEncoding::Compressed);

// One time step of a .pvd collection: the time (s) and the data file, relative to the .pvd's folder.
struct PvdEntry {
  double time = 0;
  std::string file;
  friend bool operator==(const PvdEntry&, const PvdEntry&) = default;
};

// The .pvd file contents listing `entries`.
std::string pvd_text(const std::vector<PvdEntry>& entries);

// A ParaView collection that is rewritten (atomically) every time an entry is
// added, so it is a valid file listing every snapshot so far during a run.
class PvdCollection {
 public:
  explicit PvdCollection(std::filesystem::path path) : path_(std::move(path)) {}

  // Adds a snapshot at `time` (s, finite) whose file is `file` relative to the
  // .pvd's folder, then rewrites the .pvd. A file already listed keeps its
  // place and takes the new time (a snapshot written again).
  void add(double time, std::string file);

  const std::filesystem::path& path() const { return path_; }
  const std::vector<PvdEntry>& entries() const { return entries_; }

 private:
  std::filesystem::path path_;
  std::vector<PvdEntry> entries_;
};

}  // namespace grainlab
