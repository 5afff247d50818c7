// Reading a segmented scan (see scanned_grains.h).
#include "grains/scanned_grains.h"

#include "core/bounded_read.h"
#include "core/error.h"
#include "geometry/mesh_check.h"

#include <algorithm>
#include <sstream>

namespace grainlab {

namespace {

constexpr std::uintmax_t kMaxGrainTableBytes = 256 * kMiB;

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
    out.push_back(cell);
  }
  return out;
}

}  // namespace

ScannedGrains read_scanned_grains(const std::filesystem::path& dir, bool keep_border) {
  const std::filesystem::path csv = dir / "grains.csv";
  std::error_code ec;
  if (!std::filesystem::exists(csv, ec))
    input_error("{}: no such file; grains.scan must be a folder written by `grainlab ct segment IMAGE --out DIR` "
                "(one mesh per grain and grains.csv)",
                csv.string());
  // Read whole, its size bounded first (a device or a runaway file is refused
  // before memory is touched): some 150 bytes a grain, so 256 MiB holds over a
  // million grains.
  std::istringstream in(read_bounded_file(csv, kMaxGrainTableBytes, "grain table"));
  std::string line;
  if (!std::getline(in, line)) input_error("{}: empty file; segment the scan again with `grainlab ct segment`", csv.string());
  const std::vector<std::string> header = split_csv(line);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end())
      input_error("{}: no column '{}' in the header line; grains.csv from `grainlab ct segment` has id, file, "
                  "x_m, y_m, z_m, qw, qx, qy, qz, volume_m3, equivalent_diameter_m, border",
                  csv.string(), name);
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t file_col = column("file"), border_col = column("border");
  ScannedGrains out;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \r") == std::string::npos) continue;
    const std::vector<std::string> cells = split_csv(line);
    if (cells.size() != header.size())
      input_error("{}:{}: {} values for {} columns; the file is damaged: segment the scan again", csv.string(),
                  line_no, cells.size(), header.size());
    const std::string& b = cells[border_col];
    if (b != "0" && b != "1")
      input_error("{}:{}: border = '{}'; it must be 0 or 1", csv.string(), line_no, b);
    if (b == "1" && !keep_border) {
      ++out.border_dropped;
      continue;
    }
    const std::string& name = cells[file_col];
    if (std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < ' '; }))
      input_error("{}:{}: file = '{}' holds a control character, so it names no mesh; the file is damaged: "
                  "segment the scan again",
                  csv.string(), line_no, excerpt(name));
    const std::filesystem::path mesh_file = dir / name;
    std::error_code ec;  // a name too long for the system is "no such mesh", not an exception
    if (!std::filesystem::exists(mesh_file, ec))
      input_error("{}:{}: the mesh {} does not exist{}; the folder is incomplete: segment the scan again",
                  csv.string(), line_no, excerpt(mesh_file.string(), 300), ec ? " (" + ec.message() + ")" : "");
    out.meshes.push_back(load_mesh(mesh_file));
    out.names.push_back(mesh_file.stem().string());
  }
  if (out.meshes.empty())
    input_error("{}: no grain to place ({} touching the image border dropped; set grains.scan_border = \"keep\" "
                "to keep them)",
                csv.string(), out.border_dropped);
  return out;
}

}  // namespace grainlab
