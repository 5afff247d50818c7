// PLY 1.0 (the Stanford polygon format) as grainlab reads it.
//
// A file is a text header, then the data:
//   ply
//   format ascii 1.0          (or binary_little_endian 1.0, binary_big_endian 1.0)
//   comment ...               (comment and obj_info lines are skipped)
//   element vertex 8          (an element: its name and how many records follow)
//   property float x          (a scalar property: TYPE NAME)
//   property list uchar int vertex_indices   (a list: COUNT_TYPE ITEM_TYPE NAME)
//   end_header
// then each element's records, in the header's order, each record its
// properties in order: a scalar one value, a list its count and that many
// items. Scalar types: char uchar short ushort int uint float double (1, 1,
// 2, 2, 4, 4, 4, 8 bytes) or their aliases int8 uint8 int16 uint16 int32
// uint32 float32 float64. ASCII data is numbers separated by blanks, a record
// a line (blank lines skipped, values after a record's last ignored); binary
// data is the values packed in the byte order the format names. Header lines
// may end in CRLF.
//
// grainlab takes the x, y and z of the element `vertex` (any scalar type,
// kept in double precision; its other properties skipped) and the list
// `vertex_indices` (or `vertex_index`) of the element `face` (any count and
// item types); other elements and properties are skipped by their layout.
// A polygon of n >= 3 corners p_0 ... p_{n-1} becomes the n - 2 triangles of
// a fan (c, c+i, c+i+1), i = 1 ... n-2 (indices mod n), from the first corner
// c for which no triangle points against the polygon's Newell normal
// N = sum_i p_i x p_{i+1} (so a convex polygon is fanned from corner 0 and a
// concave quad is cut along its inner diagonal); when no corner gives such a
// fan (a polygon too concave for one), or the polygon has more than 16
// corners (the search costs n^2), from corner 0.
//
// Bounds before allocation: a record takes at least, per property, the
// scalar's bytes (binary; a list's count type's) or two characters (ASCII: a
// digit and a blank), so the element counts are held to the bytes after the
// header; a binary list's count times its item size is held to the bytes
// left; an ASCII list's count to the values left on its line; and the memory
// the announced vertices and faces need to the machine's available memory.
#include "geometry/ply_reader.h"

#include "core/available_memory.h"
#include "core/bounded_line.h"
#include "core/error.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grainlab {
namespace {

enum class Scalar { none, i8, u8, i16, u16, i32, u32, f32, f64 };

Scalar scalar_of(std::string_view t) {
  if (t == "char" || t == "int8") return Scalar::i8;
  if (t == "uchar" || t == "uint8") return Scalar::u8;
  if (t == "short" || t == "int16") return Scalar::i16;
  if (t == "ushort" || t == "uint16") return Scalar::u16;
  if (t == "int" || t == "int32") return Scalar::i32;
  if (t == "uint" || t == "uint32") return Scalar::u32;
  if (t == "float" || t == "float32") return Scalar::f32;
  if (t == "double" || t == "float64") return Scalar::f64;
  return Scalar::none;
}

std::size_t size_of(Scalar s) {
  switch (s) {
    case Scalar::i8: case Scalar::u8: return 1;
    case Scalar::i16: case Scalar::u16: return 2;
    case Scalar::i32: case Scalar::u32: case Scalar::f32: return 4;
    case Scalar::f64: return 8;
    case Scalar::none: break;
  }
  return 0;
}

const char* name_of(Scalar s) {
  constexpr const char* names[] = {"?", "char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
  return names[static_cast<int>(s)];
}

struct Property {
  std::string name;
  Scalar type = Scalar::none;        // a scalar's type, or a list's item type
  Scalar count_type = Scalar::none;  // a list's count type; none for a scalar
  bool list() const { return count_type != Scalar::none; }
};

struct Element {
  std::string name;
  std::uintmax_t count = 0, min_bytes = 0;  // records, and the least bytes one takes
  std::vector<Property> properties;
};

enum class Format { none, ascii, little_endian, big_endian };

struct Header {
  Format format = Format::none;
  std::vector<Element> elements;
  std::uintmax_t bytes = 0;  // where the data starts
};

// Reads and checks the header from `in` (at the file's start); `size` is the file's.
Header read_header(std::istream& in, const std::string& name, std::uintmax_t size) {
  Header h;
  std::string line;
  std::uintmax_t need = 0;
  const auto add = [&](const Element& e) {
    const std::uintmax_t per = std::max<std::uintmax_t>(e.min_bytes, 1);  // no property: still refuse absurd counts
    if (e.count > size / per) need = size + 1;  // also keeps count * per from overflowing
    else need += e.count * per;
    h.elements.push_back(e);
  };
  Element current;
  bool open_element = false, first_line = true;
  while (h.bytes < 65536 && bounded_getline(in, line, 65536, name, "a PLY header")) {
    const std::uintmax_t line_start = h.bytes;
    h.bytes += line.size() + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto control = std::find_if(line.begin(), line.end(), [](char c) {
      const auto u = static_cast<unsigned char>(c);
      return (u < 0x20 && c != '\t') || u == 0x7f;
    });
    if (control != line.end()) {
      input_error("mesh '{}': its PLY header holds a control character (byte 0x{:02x}) at byte {}, where a PLY "
                  "header is text; the file is damaged or not a PLY file, re-export the mesh",
                  name, static_cast<unsigned>(static_cast<unsigned char>(*control)),
                  line_start + static_cast<std::uintmax_t>(control - line.begin()));
    }
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (std::exchange(first_line, false)) {
      std::string more;
      if (word != "ply" || words >> more) {
        input_error("mesh '{}': its first line is '{}', where a PLY file starts with the line 'ply'; the file is "
                    "damaged or not a PLY file, re-export the mesh",
                    name, excerpt(line, 40));
      }
      continue;
    }
    if (word == "format") {
      // A second format line would leave the data's layout ambiguous.
      if (h.format != Format::none)
        input_error("mesh '{}': its PLY header gives 'format' twice; the file is damaged, re-export the mesh", name);
      std::string f;
      words >> f;
      if (f == "ascii") h.format = Format::ascii;
      else if (f == "binary_little_endian") h.format = Format::little_endian;
      else if (f == "binary_big_endian") h.format = Format::big_endian;
      else
        input_error("mesh '{}': PLY format '{}' is none of ascii, binary_little_endian, binary_big_endian; the file "
                    "is damaged, re-export the mesh",
                    name, excerpt(f, 40));
    } else if (!word.empty() && word != "element" && word != "property" && word != "comment" && word != "obj_info" &&
               word != "end_header" && word != "ply") {
      input_error("mesh '{}': PLY header line '{}' starts with no PLY keyword (format, element, property, comment, "
                  "obj_info, end_header); the file is damaged, re-export the mesh",
                  name, excerpt(line, 80));
    } else if (word == "element") {
      if (open_element) add(current);
      current = {};
      open_element = true;
      std::string count, more;
      words >> current.name >> count;
      const bool whole =
          !count.empty() && count.size() <= 19 && count.find_first_not_of("0123456789") == std::string::npos;
      if (!words || !whole || words >> more)
        input_error("mesh '{}': PLY header line '{}' is not 'element NAME COUNT'; re-export the mesh", name,
                    excerpt(line, 80));
      current.count = std::stoull(count);
      if (!std::isalpha(static_cast<unsigned char>(current.name[0])))
        input_error("mesh '{}': PLY header line '{}' names an element '{}', which does not start with a letter; "
                    "the file is damaged, re-export the mesh",
                    name, excerpt(line, 80), excerpt(current.name, 40));
      for (const Element& e : h.elements) {
        if (e.name == current.name)
          input_error("mesh '{}': its PLY header announces the element '{}' twice; the file is damaged, re-export the "
                      "mesh",
                      name, excerpt(current.name, 40));
      }
    } else if (word == "property") {
      std::string type, count_type, item_type;
      Property p;
      words >> type;
      if (type == "list") {
        words >> count_type >> item_type;
        p.count_type = scalar_of(count_type);
        p.type = scalar_of(item_type);
      } else {
        p.type = scalar_of(type);
      }
      words >> p.name;
      const bool known = p.type != Scalar::none && (type != "list" || p.count_type != Scalar::none);
      if (!open_element || !words || !known)
        input_error("mesh '{}': PLY header line '{}' is not 'property TYPE NAME' or 'property list COUNT_TYPE "
                    "ITEM_TYPE NAME' (types: char uchar short ushort int uint float double, or int8 ... float64) "
                    "after an 'element' line; the file is damaged, re-export the mesh",
                    name, excerpt(line, 80));
      // The format line may follow the element lines: min_bytes is set at end_header.
      for (const Property& q : current.properties) {
        if (q.name == p.name)
          input_error("mesh '{}': its PLY header gives element '{}' the property '{}' twice; the file is damaged, "
                      "re-export the mesh",
                      name, excerpt(current.name, 40), excerpt(p.name, 40));
      }
      current.properties.push_back(std::move(p));
    } else if (word == "end_header") {
      if (in.eof()) {
        input_error("mesh '{}': its PLY header ends the file without a line end after 'end_header' and without "
                    "data; the file is truncated, re-export the mesh",
                    name);
      }
      if (h.format == Format::none)
        input_error("mesh '{}': its PLY header has no 'format' line (format ascii 1.0, binary_little_endian 1.0 or "
                    "binary_big_endian 1.0); the file is damaged, re-export the mesh",
                    name);
      if (open_element) add(current);
      need = 0;
      std::vector<Element> elements = std::move(h.elements);
      h.elements.clear();
      for (Element& e : elements) {
        for (const Property& p : e.properties)
          e.min_bytes += h.format == Format::ascii ? 2 : size_of(p.list() ? p.count_type : p.type);
        add(e);
      }
      const std::uintmax_t body = size - std::min(size, h.bytes);
      if (need > body) {
        std::string counts;
        for (const Element& e : h.elements)
          counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", e.count, e.name);
        input_error("mesh '{}': its PLY header announces {} elements ({}), which take at least {} bytes, but the "
                    "file holds {} bytes after its header; the file is truncated or its header is wrong, re-export "
                    "the mesh",
                    name, h.elements.size(), excerpt(counts, 200),
                    need > size ? fmt::format("more than the whole file's {}", size) : std::to_string(need), body);
      }
      return h;
    }
  }
  if (first_line) input_error("mesh '{}': the file is empty (0 bytes); re-export the mesh", name);
  input_error("mesh '{}': its PLY header has no 'end_header' line {}; the file is truncated or damaged, re-export "
              "the mesh",
              name, h.bytes >= 65536 ? "in its first 64 KiB" : "before the file's end");
}

// Where a value is read: the element, the record (from 1), for messages.
struct Place {
  const Element* element = nullptr;
  std::uintmax_t record = 0;
};

// Binary data: values packed in the file's byte order.
class BinaryValues {
 public:
  BinaryValues(std::string data, std::uintmax_t start, bool swap, const std::string& name)
      : data_(std::move(data)), start_(start), swap_(swap), name_(name) {}

  void start_record(const Place& place) { place_ = place; }

  double scalar(Scalar t, bool /*wanted*/) {
    const std::size_t n = size_of(t);
    if (data_.size() - at_ < n) {
      input_error("mesh '{}': its binary PLY data ends inside {} {} of the {} its header announces (at byte {}); the "
                  "file is truncated or its header is wrong, re-export the mesh",
                  name_, place_.element->name, place_.record, place_.element->count, start_ + at_);
    }
    unsigned char b[8] = {};
    for (std::size_t i = 0; i < n && i < 8; ++i)
      b[i] = static_cast<unsigned char>(data_[at_ + (swap_ ? n - 1 - i : i)]);
    at_ += n;
    switch (t) {
      case Scalar::i8: return static_cast<std::int8_t>(b[0]);
      case Scalar::u8: return b[0];
      case Scalar::i16: return as<std::int16_t>(b);
      case Scalar::u16: return as<std::uint16_t>(b);
      case Scalar::i32: return as<std::int32_t>(b);
      case Scalar::u32: return as<std::uint32_t>(b);
      case Scalar::f32: return as<float>(b);
      case Scalar::f64: return as<double>(b);
      case Scalar::none: break;
    }
    return 0;
  }

  // A list's count, held to the bytes left for its items.
  std::uintmax_t count(const Property& p) {
    const std::uintmax_t count_at = start_ + at_;
    const double n = scalar(p.count_type, true);
    const std::uintmax_t left = data_.size() - at_;
    if (!(n >= 0) || n != std::floor(n) || n / static_cast<double>(size_of(p.type)) > static_cast<double>(left) ||
        static_cast<std::uintmax_t>(n) * size_of(p.type) > left) {
      input_error("mesh '{}': {} {} starts a list with the count {} at byte {}, {}; the file is damaged, re-export "
                  "the mesh",
                  name_, place_.element->name, place_.record, n, count_at,
                  n >= 0 && n == std::floor(n)
                      ? fmt::format("whose {}-byte items take more than the {} bytes left in the file",
                                    size_of(p.type), left)
                      : std::string("not a whole number"));
    }
    return static_cast<std::uintmax_t>(n);
  }

  void skip(Scalar t, std::uintmax_t n) { at_ += n * size_of(t); }  // count() checked the bytes
  std::uintmax_t at() const { return start_ + at_; }

 private:
  template <typename T>
  static double as(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof(T));
    return static_cast<double>(v);
  }

  std::string data_;
  std::size_t at_ = 0;
  std::uintmax_t start_;
  bool swap_;
  const std::string& name_;
  Place place_;
};

// ASCII data: a record a line, values separated by blanks.
class AsciiValues {
 public:
  AsciiValues(std::istream& in, std::uintmax_t start, const std::string& name) : in_(in), at_(start), name_(name) {}

  // Reads the record's line (blank lines skipped).
  void start_record(const Place& place) {
    place_ = place;
    for (;;) {
      if (!bounded_getline(in_, line_, 1 << 20, name_, "ASCII PLY data")) {
        input_error("mesh '{}': its ASCII PLY data ends after {} of the {} {} records its header announces; the "
                    "file is truncated or its header is wrong, re-export the mesh",
                    name_, place.record - 1, place.element->count, place.element->name);
      }
      values_.clear();
      next_ = 0;
      for (std::size_t i = 0; i < line_.size(); ++i) {
        const auto u = static_cast<unsigned char>(line_[i]);
        if ((u < 0x20 && u != '\t' && u != '\r') || u == 0x7f) {
          input_error("mesh '{}': its ASCII PLY data holds a control character (byte 0x{:02x}) at byte {}, where "
                      "ASCII data is numbers and spaces; the file is damaged, re-export the mesh",
                      name_, static_cast<unsigned>(u), at_ + i);
        }
        if (std::isspace(u)) continue;
        if (i == 0 || std::isspace(static_cast<unsigned char>(line_[i - 1]))) values_.push_back({i, 0});
        if (++values_.back().second > 64) {
          input_error("mesh '{}': its ASCII PLY data holds a value of more than 64 characters at byte {}; the file "
                      "is damaged, re-export the mesh",
                      name_, at_ + values_.back().first);
        }
      }
      line_at_ = at_;
      at_ += line_.size() + 1;
      if (!values_.empty()) return;
    }
  }

  // The next value as a number of type `t`; when not `wanted`, only stepped over.
  double scalar(Scalar t, bool wanted) {
    const std::string_view v = next_value();
    if (!wanted) return 0;
    std::string_view s = v.size() > 1 && v[0] == '+' ? v.substr(1) : v;
    double x = 0;
    std::from_chars_result r{};
    if (t == Scalar::f32) {
      float f = 0;
      r = std::from_chars(s.data(), s.data() + s.size(), f);
      x = f;
    } else if (t == Scalar::f64) {
      r = std::from_chars(s.data(), s.data() + s.size(), x);
    } else {
      long long i = 0;
      r = std::from_chars(s.data(), s.data() + s.size(), i);
      const double low[] = {0, -128, 0, -32768, 0, -2147483648.0, 0};
      const double high[] = {0, 127, 255, 32767, 65535, 2147483647.0, 4294967295.0};
      const int k = static_cast<int>(t);
      if (r.ec == std::errc() && (i < low[k] || i > high[k])) r.ec = std::errc::result_out_of_range;
      x = static_cast<double>(i);
    }
    if (r.ec != std::errc() || r.ptr != s.data() + s.size()) {
      input_error("mesh '{}': {} {} holds '{}' at byte {}, which is not a number of its type ({}); the file is "
                  "damaged, re-export the mesh",
                  name_, place_.element->name, place_.record, v, line_at_ + values_[next_ - 1].first, name_of(t));
    }
    return x;
  }

  // A list's count: a whole number, held to the values left on its line.
  std::uintmax_t count(const Property&) {
    const std::string_view count = next_value();
    const std::uintmax_t count_at = line_at_ + values_[next_ - 1].first, left = values_.size() - next_;
    const bool whole = count.find_first_not_of("0123456789") == std::string_view::npos;
    const std::uintmax_t n = !whole ? 0 : count.size() <= 18 ? std::stoull(std::string(count)) : UINTMAX_MAX;
    if (!whole || n > left) {
      input_error("mesh '{}': {} {} starts a list with the count '{}' at byte {}, {}; the file is damaged, "
                  "re-export the mesh",
                  name_, place_.element->name, place_.record, excerpt(count, 20), count_at,
                  whole ? fmt::format("more than the {} values left on its line", left)
                        : std::string("not a whole number"));
    }
    return n;
  }

  void skip(Scalar, std::uintmax_t n) { next_ += n; }  // count() checked the values
  std::uintmax_t at() const { return line_at_ + (next_ < values_.size() ? values_[next_].first : line_.size()); }

 private:
  std::string_view next_value() {
    if (next_ == values_.size()) {
      input_error("mesh '{}': {} {} (the line at byte {}) holds fewer values than the {} properties its header "
                  "gives it; the file is damaged, re-export the mesh",
                  name_, place_.element->name, place_.record, line_at_ + values_.front().first,
                  place_.element->properties.size());
    }
    const auto [start, length] = values_[next_++];
    return std::string_view(line_).substr(start, length);
  }

  std::istream& in_;
  std::uintmax_t at_, line_at_ = 0;  // byte of the next line, of the current one
  const std::string& name_;
  std::string line_;
  std::vector<std::pair<std::size_t, std::size_t>> values_;  // the line's values: start, length
  std::size_t next_ = 0;
  Place place_;
};

// The index of the property named `want` of `e` (any of `want`), or -1.
int find_property(const Element& e, std::initializer_list<std::string_view> want) {
  for (std::size_t k = 0; k < e.properties.size(); ++k)
    if (std::find(want.begin(), want.end(), e.properties[k].name) != want.end()) return static_cast<int>(k);
  return -1;
}

// Polygons as read: each one's corner count, and the corners one after another.
struct Polygons {
  std::vector<std::uint32_t> sizes;
  std::vector<Index> corners;
};

// Reads every element's records from `values`: the vertices' positions into
// `mesh`, the faces' corners into `polygons`.
template <typename Values>
void read_data(Values& values, const Header& h, const std::string& name, std::uintmax_t vertex_count,
               TriMesh& mesh, Polygons& polygons) {
  for (const Element& e : h.elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int xyz[3] = {-1, -1, -1}, corners = -1;
    if (is_vertex) {
      for (int k = 0; k < 3; ++k) {
        const std::string_view axis = std::string_view("xyz").substr(k, 1);
        xyz[k] = find_property(e, {axis});
        if (xyz[k] < 0 || e.properties[xyz[k]].list())
          input_error("mesh '{}': its PLY header gives the element 'vertex' no scalar property '{}'; a vertex needs "
                      "x, y and z, re-export the mesh",
                      name, axis);
      }
      mesh.vertices.reserve(e.count);
    }
    if (is_face) {
      corners = find_property(e, {"vertex_indices", "vertex_index"});
      if (corners < 0 || !e.properties[corners].list())
        input_error("mesh '{}': its PLY header gives the element 'face' no list 'vertex_indices' (or "
                    "'vertex_index'); re-export the mesh",
                    name);
      polygons.sizes.reserve(e.count);
      polygons.corners.reserve(3 * e.count);
    }
    for (std::uintmax_t record = 1; record <= e.count; ++record) {
      values.start_record({&e, record});
      Vec3 p = Vec3::Zero();
      for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
        const Property& prop = e.properties[k];
        if (!prop.list()) {
          const int axis = static_cast<int>(std::find(xyz, xyz + 3, k) - xyz);
          const double x = values.scalar(prop.type, axis < 3);
          if (axis < 3) p[axis] = x;
          continue;
        }
        const std::uintmax_t count_at = values.at();
        const std::uintmax_t n = values.count(prop);
        if (k != corners) {
          values.skip(prop.type, n);
          continue;
        }
        if (n < 3) {
          input_error("mesh '{}': face {} has {} (its list at byte {}), where a face needs at least 3; the file is "
                      "damaged, re-export the mesh",
                      name, record, n == 0 ? std::string("no vertex") : fmt::format("{} vertices", n), count_at);
        }
        polygons.sizes.push_back(static_cast<std::uint32_t>(n));
        for (std::uintmax_t i = 0; i < n; ++i) {
          const double v = values.scalar(prop.type, true);
          if (!(v >= 0 && v < static_cast<double>(vertex_count)) || v != std::floor(v))
            input_error("mesh '{}': face {} names vertex {}, but the mesh has {} vertices; the file is damaged, "
                        "re-export the mesh",
                        name, record, v, vertex_count);
          polygons.corners.push_back(static_cast<Index>(v));
        }
      }
      if (is_vertex) mesh.vertices.push_back(p);
    }
  }
}

// Cuts each polygon into triangles (the fan of the file's header comment).
void triangulate(const Polygons& polygons, TriMesh& mesh) {
  std::size_t first = 0;
  for (const std::uint32_t n : polygons.sizes) {
    const Index* c = polygons.corners.data() + first;
    first += n;
    const auto at = [&](std::uint32_t i) { return mesh.vertices[c[i % n]]; };
    std::uint32_t start = 0;
    if (n > 3 && n <= 16) {
      Vec3 normal = Vec3::Zero();
      for (std::uint32_t i = 0; i < n; ++i) normal += at(i).cross(at(i + 1));
      for (std::uint32_t s = 0; s < n; ++s) {
        bool folds = false;
        for (std::uint32_t i = 1; i + 1 < n && !folds; ++i)
          folds = (at(s + i) - at(s)).cross(at(s + i + 1) - at(s)).dot(normal) < 0;
        if (!folds) {
          start = s;
          break;
        }
      }
    }
    for (std::uint32_t i = 1; i + 1 < n; ++i)
      mesh.faces.push_back({c[start], c[(start + i) % n], c[(start + i + 1) % n]});
  }
}

}  // namespace

TriMesh read_ply(const std::filesystem::path& path, std::uintmax_t size) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) input_error("mesh '{}': cannot be read; check its permissions", name);
  const Header h = read_header(in, name, size);

  // What the announced records take in memory: here a position (24 bytes) per
  // vertex and at least a triangle (12) and its corner count (4) per face, in
  // read_mesh a copy of both and a merge-map node per vertex (about 80 bytes).
  std::uintmax_t vertex_count = 0, face_count = 0;
  for (const Element& e : h.elements) {
    if (e.name == "vertex") vertex_count = e.count;
    if (e.name == "face") face_count = e.count;
  }
  // vertex_count < 2^31 (the Index type): a vertex takes at least 3 bytes of a file of at most 1 GiB.
  const bool binary = h.format != Format::ascii;
  const std::uintmax_t need = vertex_count * (24 + 24 + 80) + face_count * (12 + 4 + 12 + 12) +
                              (binary ? size - h.bytes : 0);
  const std::uintmax_t have = available_memory_bytes();
  if (have > 0 && need > have) {
    input_error("mesh '{}': its {} vertices and {} faces need about {:.1f} GiB to read, and this machine has {:.1f} "
                "GiB available; simplify the mesh or use a machine with more memory",
                name, vertex_count, face_count, need / 1073741824.0, have / 1073741824.0);
  }

  TriMesh mesh;
  Polygons polygons;
  if (binary) {
    std::string data(size - h.bytes, '\0');
    in.read(data.data(), static_cast<std::streamsize>(data.size()));
    if (static_cast<std::uintmax_t>(in.gcount()) != data.size())
      input_error("mesh '{}': cannot be read to its end; check the file", name);
    const bool swap = (h.format == Format::big_endian) != (std::endian::native == std::endian::big);
    BinaryValues values(std::move(data), h.bytes, swap, name);
    read_data(values, h, name, vertex_count, mesh, polygons);
  } else {
    AsciiValues values(in, h.bytes, name);
    read_data(values, h, name, vertex_count, mesh, polygons);
  }
  triangulate(polygons, mesh);
  return mesh;
}

}  // namespace grainlab
