// Test helper: reads back the .vtp files that io/vtk_writer.h writes, so the
// tests can check what a run wrote (only tests read .vtp files; the engine
// reads .pvd collections only, io/pvd_reader.h). Header-only: test_io and
// test_apps both include it.
//
// The tags come from io/xml_scanner.h, with a stack of open elements. An
// inline DataArray's text is taken whole up to its closing tag and decoded:
// the byte count as a UInt32 or UInt64 (the VTKFile's header_type), then the
// values, little-endian; base64 of the two together (as grainlab and VTK
// write), or of each apart (as some other writers do). An appended DataArray
// is read at its offset in the raw <AppendedData> bytes: VTK's zlib blocks
// (compressor="vtkZLibDataCompressor", io/zlib_blocks.h) or a byte count and
// the values. Not a general VTK reader: no ascii data, no base64 appended
// data, no compressed inline data, no triangle strips.
#pragma once

#include "core/error.h"
#include "io/base64.h"
#include "io/vtk_decoding.h"
#include "io/vtk_writer.h"
#include "io/xml_scanner.h"
#include "io/zlib_blocks.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace grainlab {

namespace vtp_detail {

using xml::find;
using xml::is_space;
using xml::need;
using xml::parse_number;
using xml::Tag;
using XmlScanner = xml::Scanner;

// The bytes of one inline binary DataArray (its header checked and removed).
inline std::vector<std::uint8_t> inline_bytes(const XmlScanner& xml, std::string_view content, std::size_t header_size,
                                       const std::string& name) {
  std::string compact;
  compact.reserve(content.size());
  for (const char c : content)
    if (!is_space(c)) compact += c;
  // grainlab writes header and values as one stream; other writers pad the
  // header apart, which shows as '=' within its characters: read both.
  const std::size_t header_chars = base64_length(header_size);
  if (compact.size() < header_chars) xml.fail("DataArray '{}' is too short to hold its byte count", name);
  const std::string_view head(compact.data(), header_chars);
  std::vector<std::uint8_t> header, bytes;
  try {
    if (head.find('=') != std::string_view::npos) {
      header = base64_decode(head);
      bytes = base64_decode(std::string_view(compact).substr(header_chars));
    } else {
      bytes = base64_decode(compact);
      header.assign(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(header_size));
      bytes.erase(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(header_size));
    }
  } catch (const std::invalid_argument& e) {
    xml.fail("DataArray '{}': {}", name, e.what());
  }
  if (header.size() != header_size) xml.fail("DataArray '{}' is too short to hold its byte count", name);
  std::uint64_t count = 0;
  if (header_size == 4) {
    std::uint32_t c32 = 0;
    std::memcpy(&c32, header.data(), 4);
    count = c32;
  } else {
    std::memcpy(&count, header.data(), 8);
  }
  if (count != bytes.size())
    xml.fail("DataArray '{}' says it holds {} bytes but holds {}", name, count, bytes.size());
  return bytes;
}

// The bytes of one DataArray stored at `offset` of the raw appended section:
// zlib blocks (compressed files) or a byte count and the values.
inline std::vector<std::uint8_t> appended_bytes(const XmlScanner& xml, std::string_view appended, std::size_t offset,
                                         bool compressed, std::size_t header_size, const std::string& name) {
  if (offset > appended.size())
    xml.fail("DataArray '{}' starts at byte {} of the appended data, which holds {}: the file is cut short", name,
             offset, appended.size());
  const std::string_view data = appended.substr(offset);
  if (compressed) {
    try {
      std::size_t used = 0;
      return read_zlib_blocks(data, used);
    } catch (const std::invalid_argument& e) {
      xml.fail("DataArray '{}': {}", name, e.what());
    }
  }
  if (data.size() < header_size) xml.fail("DataArray '{}' is too short to hold its byte count", name);
  std::uint64_t count = 0;
  std::memcpy(&count, data.data(), header_size);  // little-endian: a UInt32 count fills the low bytes
  if (count > data.size() - header_size)
    xml.fail("DataArray '{}' says it holds {} bytes but the appended data ends after {}", name, count,
             data.size() - header_size);
  const auto* p = reinterpret_cast<const std::uint8_t*>(data.data()) + header_size;
  return {p, p + count};
}

// The values of a DataArray's bytes as T (the file's values are value_size bytes each).
template <typename T>
std::vector<T> values_of(const XmlScanner& xml, const std::vector<std::uint8_t>& bytes, std::size_t value_size,
                         const std::string& name) {
  if (bytes.size() % value_size != 0)
    xml.fail("DataArray '{}': {} bytes is not a whole number of {}-byte values", name, bytes.size(), value_size);
  std::vector<T> out(bytes.size() / value_size);
  if (sizeof(T) == value_size) {
    if (!out.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
  } else if constexpr (std::is_same_v<T, std::int64_t>) {
    // Int32 cell arrays widened to Int64.
    for (std::size_t i = 0; i < out.size(); ++i) {
      std::int32_t v;
      std::memcpy(&v, bytes.data() + i * sizeof v, sizeof v);
      out[i] = v;
    }
  } else {
    xml.fail("DataArray '{}': {}-byte values cannot be read as {}-byte ones", name, value_size, sizeof(T));
  }
  return out;
}

inline std::size_t type_size(std::string_view type) {
  if (type == "Float64" || type == "Int64") return 8;
  if (type == "Float32" || type == "Int32") return 4;
  return 0;
}

// Reads grainlab's PolyData out of the tags.
class VtpParser {
 public:
  // `text`: the XML; `appended`: the raw bytes after the '_' of its <AppendedData>, if any.
  VtpParser(std::string_view text, std::string_view appended, const std::string& source)
      : xml_(text, source), appended_(appended) {}

  PolyData parse() {
    Tag tag;
    bool seen_root = false, seen_piece = false, seen_points = false;
    while (xml_.next(tag)) {
      if (xml_.closes(tag, stack_)) continue;
      if (tag.name == "VTKFile") {
        if (!stack_.empty()) xml_.fail("<VTKFile> inside another element");
        seen_root = true;
        root(tag);
      } else if (tag.name == "Piece") {
        if (seen_piece) xml_.fail("more than one <Piece> (only single-piece files are read)");
        seen_piece = true;
        piece(tag);
      } else if (tag.name == "DataArray") {
        const std::string parent = stack_.empty() ? "" : stack_.back();
        data_array(tag, parent, tag.self_closing ? std::string_view() : xml_.content_until_close("DataArray"));
        if (parent == "Points") seen_points = true;
        continue;  // its closing tag, if any, is consumed
      }
      if (!tag.self_closing) stack_.push_back(tag.name);
    }
    if (!seen_root) xml_.fail("no <VTKFile> element");
    if (!stack_.empty()) xml_.fail("<{}> is never closed", stack_.back());
    if (!seen_piece) xml_.fail("no <Piece> element");
    if (!seen_points) xml_.fail("no <Points> DataArray");
    try {
      check_polydata(pd_);
    } catch (const std::invalid_argument& e) {
      xml_.fail("{}", e.what());
    }
    if (pd_.point_count() != n_points_ || pd_.verts.size() != n_verts_ || pd_.lines.size() != n_lines_ ||
        pd_.polys.size() != n_polys_)
      xml_.fail("the <Piece> counts ({} points, {} verts, {} lines, {} polys) do not match the arrays "
                "({}, {}, {}, {})",
                n_points_, n_verts_, n_lines_, n_polys_, pd_.point_count(), pd_.verts.size(), pd_.lines.size(),
                pd_.polys.size());
    return std::move(pd_);
  }

 private:
  void root(const Tag& tag) {
    if (need(xml_, tag, "type") != "PolyData") xml_.fail("VTKFile type is '{}', not PolyData", need(xml_, tag, "type"));
    if (const std::string* order = find(tag, "byte_order"); order && *order != "LittleEndian")
      xml_.fail("byte order '{}' is not supported (only LittleEndian)", *order);
    if (const std::string* c = find(tag, "compressor"); c && !c->empty()) {
      if (*c != "vtkZLibDataCompressor") xml_.fail("compressor '{}' is not supported (only vtkZLibDataCompressor)", *c);
      compressed_ = true;
    }
    const std::string* header = find(tag, "header_type");
    if (!header || *header == "UInt32") {
      header_size_ = 4;
    } else if (*header == "UInt64") {
      header_size_ = 8;
    } else {
      xml_.fail("header_type '{}' is not UInt32 or UInt64", *header);
    }
  }

  void piece(const Tag& tag) {
    const auto count = [&](std::string_view key) -> std::size_t {
      const std::string* v = find(tag, key);
      return v ? parse_number<std::size_t>(xml_, tag, key, *v) : 0;
    };
    n_points_ = count("NumberOfPoints");
    n_verts_ = count("NumberOfVerts");
    n_lines_ = count("NumberOfLines");
    n_polys_ = count("NumberOfPolys");
    if (count("NumberOfStrips") != 0) xml_.fail("triangle strips are not supported");
  }

  void data_array(const Tag& tag, const std::string& parent, std::string_view content) {
    const std::string& name = need(xml_, tag, "Name");
    const std::string& type = need(xml_, tag, "type");
    const std::string& format = need(xml_, tag, "format");
    std::vector<std::uint8_t> bytes;
    if (format == "appended") {
      const std::size_t offset = parse_number<std::size_t>(xml_, tag, "offset", need(xml_, tag, "offset"));
      bytes = appended_bytes(xml_, appended_, offset, compressed_, header_size_, name);
    } else if (format == "binary") {
      if (compressed_) xml_.fail("DataArray '{}': compressed inline data is not supported (only appended)", name);
      bytes = inline_bytes(xml_, content, header_size_, name);
    } else {
      xml_.fail("DataArray '{}' has format '{}': only binary (inline) or appended data is read", name, format);
    }
    const std::size_t size = type_size(type);
    if (size == 0) xml_.fail("DataArray '{}' has type '{}' (Float64, Float32, Int32 or Int64 expected)", name, type);
    int components = 1;
    if (const std::string* c = find(tag, "NumberOfComponents"))
      components = parse_number<int>(xml_, tag, "NumberOfComponents", *c);
    if (components < 1) xml_.fail("DataArray '{}' has {} components", name, components);

    if (parent == "Verts" || parent == "Lines" || parent == "Polys") {
      VtkCells& cells = parent == "Verts" ? pd_.verts : parent == "Lines" ? pd_.lines : pd_.polys;
      if (type != "Int64" && type != "Int32") xml_.fail("{} array '{}' has type {}, not an integer", parent, name, type);
      std::vector<std::int64_t> v = values_of<std::int64_t>(xml_, bytes, size, name);
      if (name == "connectivity") {
        cells.connectivity = std::move(v);
      } else if (name == "offsets") {
        cells.offsets = std::move(v);
      } else {
        xml_.fail("{} holds an unknown array '{}'", parent, name);
      }
      return;
    }
    if (parent == "Strips") xml_.fail("triangle strips are not supported");

    VtkArray a;
    a.name = name;
    a.components = components;
    if (type == "Float64") {
      a.values = values_of<double>(xml_, bytes, size, name);
    } else if (type == "Float32") {
      a.values = values_of<float>(xml_, bytes, size, name);
    } else if (type == "Int32") {
      a.values = values_of<std::int32_t>(xml_, bytes, size, name);
    } else {
      xml_.fail("DataArray '{}' has type Int64, which grainlab's point and cell data do not use", name);
    }
    if (a.value_count() % static_cast<std::size_t>(components) != 0)
      xml_.fail("DataArray '{}': {} values is not a whole number of {}-component tuples", name, a.value_count(),
                components);
    if (parent == "Points") {
      pd_.points = std::move(a);
    } else if (parent == "PointData") {
      pd_.point_data.push_back(std::move(a));
    } else if (parent == "CellData") {
      pd_.cell_data.push_back(std::move(a));
    } else {
      xml_.fail("DataArray '{}' inside <{}>, which grainlab does not write", name, parent);
    }
  }

  XmlScanner xml_;
  std::string_view appended_;
  bool compressed_ = false;
  std::vector<std::string> stack_;
  PolyData pd_;
  std::size_t header_size_ = 4;
  std::size_t n_points_ = 0, n_verts_ = 0, n_lines_ = 0, n_polys_ = 0;
};

}  // namespace vtp_detail

// Parses .vtp text; source_name is used in messages.
inline PolyData parse_vtp(std::string_view text, const std::string& source_name) {
  // Appended data: XML up to <AppendedData>, then its raw bytes from after an
  // '_' to the closing tag. The XML part is read as if </VTKFile> followed it.
  const std::size_t at = text.find("<AppendedData");
  if (at == std::string_view::npos) return vtp_detail::VtpParser(text, {}, source_name).parse();
  const std::string xml = std::string(text.substr(0, at)) + "</VTKFile>\n";
  const std::size_t open_end = text.find('>', at);
  const std::string_view open = text.substr(at, open_end == std::string_view::npos ? 0 : open_end - at);
  const std::size_t underscore = open_end == std::string_view::npos ? open_end : text.find('_', open_end);
  const std::size_t close = text.rfind("</AppendedData>");
  if (underscore == std::string_view::npos || close == std::string_view::npos || close < underscore)
    input_error("{}: the <AppendedData> section is cut short (no '_' or no closing tag). The file is damaged, "
                "perhaps by a run that was killed while another program copied it",
                source_name);
  if (open.find("encoding=\"raw\"") == std::string_view::npos)
    input_error("{}: only raw <AppendedData> is read (the file's is base64 or unstated)", source_name);
  return vtp_detail::VtpParser(xml, text.substr(underscore + 1, close - underscore - 1), source_name).parse();
}

// The PolyData of a .vtp file; throws InputError naming the file and what is
// wrong for a missing, malformed or unsupported file.
inline PolyData read_vtp(const std::filesystem::path& path) {
  return parse_vtp(xml::read_text(path), path.string());
}

}  // namespace grainlab
