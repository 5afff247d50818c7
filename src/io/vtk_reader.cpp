// A minimal XML reader for grainlab's own .vtp and .pvd files (see vtk_reader.h).
//
// The scanner walks the tags in order and keeps a stack of open elements. An
// inline DataArray's text is taken whole up to its closing tag and decoded:
// the byte count as a UInt32 or UInt64 (the VTKFile's header_type), then the
// values, little-endian; base64 of the two together (as grainlab and VTK
// write), or of each apart (as some other writers do). An appended DataArray
// is read at its offset in the raw <AppendedData> bytes: VTK's zlib blocks
// (compressor="vtkZLibDataCompressor", io/zlib_blocks.h) or a byte count and
// the values.
#include "io/vtk_reader.h"

#include "core/error.h"
#include "io/base64.h"
#include "io/zlib_blocks.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace grainlab {

namespace {

using Attributes = std::map<std::string, std::string, std::less<>>;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) input_error("cannot open '{}': check that the file exists and is readable", path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }
bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
         c == '-' || c == '.';
}

// One tag: <name attrs>, <name attrs/> or </name>.
struct Tag {
  std::string name;
  Attributes attributes;
  bool closing = false;       // </name>
  bool self_closing = false;  // <name/>
};

// Walks the tags of an XML text, skipping the declaration and comments.
class XmlScanner {
 public:
  XmlScanner(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  // The next tag, or false at the end of the text. Text between tags is skipped.
  bool next(Tag& tag) {
    for (;;) {
      const std::size_t lt = text_.find('<', pos_);
      if (lt == std::string_view::npos) return false;
      pos_ = lt;
      if (starts_with("<?")) {
        skip_past("?>");
      } else if (starts_with("<!--")) {
        skip_past("-->");
      } else {
        break;
      }
    }
    ++pos_;
    tag = Tag{};
    if (pos_ < text_.size() && text_[pos_] == '/') {
      tag.closing = true;
      ++pos_;
    }
    tag.name = read_name("an element name");
    for (;;) {
      skip_spaces();
      if (pos_ >= text_.size()) fail("the file ends inside the <{}> tag", tag.name);
      if (text_[pos_] == '>') {
        ++pos_;
        return true;
      }
      if (!tag.closing && starts_with("/>")) {
        pos_ += 2;
        tag.self_closing = true;
        return true;
      }
      if (tag.closing) fail("unexpected '{}' in the closing tag </{}>", text_[pos_], tag.name);
      std::string key = read_name("an attribute name");
      skip_spaces();
      expect('=', key);
      skip_spaces();
      if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\''))
        fail("attribute '{}' of <{}> has no quoted value", key, tag.name);
      const char quote = text_[pos_++];
      const std::size_t end = text_.find(quote, pos_);
      if (end == std::string_view::npos) fail("attribute '{}' of <{}> is not closed", key, tag.name);
      std::string value = unescape(text_.substr(pos_, end - pos_));
      pos_ = end + 1;
      if (!tag.attributes.emplace(std::move(key), std::move(value)).second)
        fail("<{}> repeats an attribute", tag.name);
    }
  }

  // The text up to the closing tag </name>, which is consumed.
  std::string_view content_until_close(std::string_view name) {
    const std::string close = "</" + std::string(name) + ">";
    const std::size_t end = text_.find(close, pos_);
    if (end == std::string_view::npos) fail("<{}> is never closed", name);
    const std::string_view content = text_.substr(pos_, end - pos_);
    pos_ = end + close.size();
    return content;
  }

  // Throws InputError naming the source and the line of the current position.
  template <typename... Args>
  [[noreturn]] void fail(fmt::format_string<Args...> f, Args&&... args) const {
    const std::size_t line = 1 + std::count(text_.begin(), text_.begin() + std::min(pos_, text_.size()), '\n');
    input_error("{}, line {}: {}. The file is not a VTK file written by grainlab, or it is damaged", source_, line,
                fmt::format(f, std::forward<Args>(args)...));
  }

 private:
  bool starts_with(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }
  void skip_past(std::string_view s) {
    const std::size_t end = text_.find(s, pos_);
    if (end == std::string_view::npos) fail("'{}' is never closed", text_.substr(pos_, 4));
    pos_ = end + s.size();
  }
  void skip_spaces() {
    while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
  }
  void expect(char c, const std::string& after) {
    if (pos_ >= text_.size() || text_[pos_] != c) fail("expected '{}' after '{}'", c, after);
    ++pos_;
  }
  std::string read_name(const char* what) {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
    if (pos_ == start) fail("expected {}", what);
    return std::string(text_.substr(start, pos_ - start));
  }
  std::string unescape(std::string_view s) const {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i] != '&') {
        out += s[i];
        continue;
      }
      static constexpr std::pair<std::string_view, char> kEntities[] = {
          {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
      bool found = false;
      for (const auto& [entity, c] : kEntities) {
        if (s.substr(i, entity.size()) == entity) {
          out += c;
          i += entity.size() - 1;
          found = true;
          break;
        }
      }
      if (!found) fail("unknown entity in '{}'", s);
    }
    return out;
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
};

const std::string* find(const Tag& tag, std::string_view key) {
  const auto it = tag.attributes.find(key);
  return it == tag.attributes.end() ? nullptr : &it->second;
}

// An attribute that must be present.
const std::string& need(const XmlScanner& xml, const Tag& tag, std::string_view key) {
  const std::string* v = find(tag, key);
  if (!v) xml.fail("<{}> has no '{}' attribute", tag.name, key);
  return *v;
}

template <typename T>
T parse_number(const XmlScanner& xml, const Tag& tag, std::string_view key, const std::string& s) {
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size())
    xml.fail("attribute '{}' of <{}> is '{}', not a number", key, tag.name, s);
  return v;
}

// The bytes of one inline binary DataArray (its header checked and removed).
std::vector<std::uint8_t> inline_bytes(const XmlScanner& xml, std::string_view content, std::size_t header_size,
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
std::vector<std::uint8_t> appended_bytes(const XmlScanner& xml, std::string_view appended, std::size_t offset,
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

std::size_t type_size(std::string_view type) {
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
      if (tag.closing) {
        if (stack_.empty() || stack_.back() != tag.name)
          xml_.fail("</{}> does not close the open element <{}>", tag.name, stack_.empty() ? "" : stack_.back());
        stack_.pop_back();
        continue;
      }
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

}  // namespace

PolyData parse_vtp(std::string_view text, const std::string& source_name) {
  // Appended data: XML up to <AppendedData>, then its raw bytes from after an
  // '_' to the closing tag. The XML part is read as if </VTKFile> followed it.
  const std::size_t at = text.find("<AppendedData");
  if (at == std::string_view::npos) return VtpParser(text, {}, source_name).parse();
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
  return VtpParser(xml, text.substr(underscore + 1, close - underscore - 1), source_name).parse();
}

PolyData read_vtp(const std::filesystem::path& path) { return parse_vtp(read_text(path), path.string()); }

std::vector<PvdEntry> parse_pvd(std::string_view text, const std::string& source_name) {
  XmlScanner xml(text, source_name);
  std::vector<PvdEntry> entries;
  std::vector<std::string> stack;
  bool seen_root = false, seen_collection = false;
  Tag tag;
  while (xml.next(tag)) {
    if (tag.closing) {
      if (stack.empty() || stack.back() != tag.name)
        xml.fail("</{}> does not close the open element <{}>", tag.name, stack.empty() ? "" : stack.back());
      stack.pop_back();
      continue;
    }
    if (tag.name == "VTKFile") {
      if (!stack.empty()) xml.fail("<VTKFile> inside another element");
      if (need(xml, tag, "type") != "Collection") xml.fail("VTKFile type is '{}', not Collection", need(xml, tag, "type"));
      seen_root = true;
    } else if (tag.name == "Collection") {
      if (stack.size() != 1 || stack.back() != "VTKFile") xml.fail("<Collection> outside <VTKFile>");
      seen_collection = true;
    } else if (tag.name == "DataSet") {
      if (stack.empty() || stack.back() != "Collection") xml.fail("<DataSet> outside <Collection>");
      PvdEntry e;
      e.time = parse_number<double>(xml, tag, "timestep", need(xml, tag, "timestep"));
      e.file = need(xml, tag, "file");
      entries.push_back(std::move(e));
    }
    if (!tag.self_closing) stack.push_back(tag.name);
  }
  if (!seen_root) xml.fail("no <VTKFile> element");
  if (!seen_collection) xml.fail("no <Collection> element");
  if (!stack.empty()) xml.fail("<{}> is never closed", stack.back());
  return entries;
}

std::vector<PvdEntry> read_pvd(const std::filesystem::path& path) { return parse_pvd(read_text(path), path.string()); }

}  // namespace grainlab
