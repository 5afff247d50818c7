// grainlab's own strict walk over a TIFF file's structure, before ITK's TIFF
// reader (libtiff and ITK's tag copying) sees it. ITK trusts what libtiff
// hands it: a DateTime tag shorter than the 20 characters the TIFF standard
// fixes made ITK copy 20 bytes out of a 15-byte buffer. The walk reads only
// the header and the directories (IFDs), never the pixels, and requires:
//   header     "II*\0" or "MM\0*" (classic), "II+\0" / "MM\0+" (BigTIFF,
//              8-byte offsets); the first IFD inside the file
//   IFD chain  each IFD and its entries inside the file, none visited twice
//              (a loop), at most 1,000,000 pages, each tag once
//   entries    a known TIFF data type; a value that does not fit in the entry
//              lies inside the file (offset + count x type size, without
//              overflow); DateTime at least 20 characters with
//              its NUL
//   each page  ImageWidth, ImageLength 1 to 1,048,576; BitsPerSample 1 to 64;
//              SamplesPerPixel 1 to 16; PlanarConfiguration 1 or 2; strips
//              (RowsPerStrip >= 1) or tiles (TileWidth, TileLength >= 1),
//              with as many offsets and byte counts as the image needs, each
//              block inside the file, and uncompressed blocks long enough
//              for their pixels
// Format: TIFF 6.0 (Adobe, 1992), BigTIFF (libtiff.org).
#pragma once

#include <filesystem>

namespace grainlab::ct {

// Throws InputError naming the file, the page and the tag, and how to fix it,
// at the first part of the structure that breaks the rules above.
void check_tiff_structure(const std::filesystem::path& path);

}  // namespace grainlab::ct
