// grainlab's own strict reading of a MetaImage (.mha, .mhd) header, before
// ITK's MetaIO sees the file. MetaIO trusts its input: a header of misspelt,
// repeated fields made it read past a buffer (a crash, exit 139). So every
// header line must be one `Key = Value` field, each key at most once, a key
// one or two letters off a MetaImage field ("NGims") is taken for a typo, and
// the fields grainlab's reading depends on must be there and agree:
//   NDims      1 to 10 (MetaIO's limit)
//   DimSize    NDims whole numbers > 0; ElementSpacing, ElementSize NDims
//              numbers > 0; Offset, Origin, Position, CenterOfRotation NDims
//              numbers; TransformMatrix, Rotation, Orientation NDims^2 numbers
//   ElementType a MET_ type; ElementNumberOfChannels 1 to 64
//   BinaryData, CompressedData, ...ByteOrderMSB  True or False
//   CompressedDataSize, HeaderSize  whole numbers (HeaderSize -1: the data
//              is the end of its file)
//   ElementDataFile  the last field (the data follows it): LOCAL (the data is
//              in this file), a data file next to the header that exists,
//              LIST [D] followed by the names of slice files that exist, one
//              a line (as many as DimSize's axes past the first D make), or
//              a pattern 'NAME%03d.raw MIN MAX STEP [D]' of one %d conversion
// Values are printable text of at most 1024 characters (254 unless they are
// numbers), field names of at most 200 (MetaIO copies text and names into
// buffers of 255 bytes unchecked). Then uncompressed
// binary data must hold exactly DimSize x channels x ElementType's bytes
// (declared_data.h). Fields of other names (ITK writes an image's own
// metadata as extra fields) are allowed when printable.
// Format: itk.org/Wiki/ITK/MetaIO/Documentation.
#pragma once

#include <filesystem>

namespace grainlab::ct {

// Throws InputError naming the file, the line and the field, and how to fix
// it, at the first field that breaks the rules above; then as
// check_declared_data when the data is shorter or longer than the header says.
// Compressed data is inflated to check that it holds the whole image, as much
// work as reading it: `compressed_data` false leaves that to the read of the
// voxels, so that a header is read (and a volume too large for the machine's
// memory refused) without inflating gigabytes.
void check_metaimage_header(const std::filesystem::path& path, bool compressed_data = true);

}  // namespace grainlab::ct
