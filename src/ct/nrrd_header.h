// What grainlab reads from an NRRD header itself, because ITK does not pass it
// on or does not check it:
//  - the length unit of the spacing and origin: "space units" (with "space
//    directions" / "space origin") or the per-axis "units" (with "spacings").
//    Absent or empty, the unit is the millimetre (ITK's and 3D Slicer's
//    convention);
//  - whether the data holds exactly the voxels the header describes. With raw
//    encoding, the data is sizes[0] x sizes[1] x sizes[2] x (bytes of `type`)
//    bytes after the header (or in the detached "data file", after "byte
//    skip" bytes). ITK reads that many bytes and ignores any more, so a header
//    whose sizes are too small would be segmented as a different image.
// Format: teem.sourceforge.net/nrrd/format.html. Field names are matched
// without case and spaces ("data file" = "datafile").
#pragma once

#include "core/types.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace grainlab::ct {

struct NrrdHeader {
  std::map<std::string, std::string> fields;  // normalised name ("spaceunits") -> value, trimmed
  std::uint64_t header_bytes = 0;             // bytes up to and including the blank line ending the header
};

// Reads the text header of an .nrrd or .nhdr file (lines of at most 64 KiB:
// a longer one is refused before it is read whole). Throws InputError naming
// the file when it does not start with the "NRRD000x" magic.
NrrdHeader read_nrrd_header(const std::filesystem::path& path);

// Metres per unit of the header's spacing and origin, per axis, and where
// they came from, e.g. "'space directions' in \"m\" ('space units')" or
// "'spacings' read as mm (no 'units' field)".
struct NrrdUnits {
  Vec3 metres_per_unit = Vec3::Constant(1e-3);
  bool named = false;  // the header names the unit (a spacing of 1 is then a real 1)
  std::string source;
};

// Throws InputError naming the file, the field and the unit when a unit is not
// a length grainlab knows, with --voxel-size as the way round it.
NrrdUnits nrrd_units(const NrrdHeader& header, const std::filesystem::path& path);

// Metres per unit named by `unit` ("m", "mm", "um", "µm", "microns", ...): 0
// when empty or "???" (no unit given), -1 when not a known length unit.
double metres_per_unit(const std::string& unit);

// For raw encoding, throws InputError when the data bytes differ from what
// "sizes" and "type" describe (both figures, and what to fix). For gzip, ascii
// and hex, when the data is too short to hold them even at the encoding's
// densest (gzip: 1032 bytes per byte), so that ITK never allocates an image a
// small file only claims; bzip2 and zrl are left to ITK's reader.
void check_nrrd_data_size(const NrrdHeader& header, const std::filesystem::path& path);

}  // namespace grainlab::ct
