// A minimal XML tag scanner for grainlab's own VTK files (.pvd here, .vtp in
// the tests' reader): it walks the tags in order (<name attrs>, <name attrs/>,
// </name>), skipping the declaration, comments and the text between tags,
// unescapes the five XML entities in attribute values, and reports a problem
// as an InputError naming the file and the line.
#pragma once

#include "core/error.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab::xml {

using Attributes = std::map<std::string, std::string, std::less<>>;

// The whole file as text; InputError when it cannot be opened.
std::string read_text(const std::filesystem::path& path);

// One tag: <name attrs>, <name attrs/> or </name>.
struct Tag {
  std::string name;
  Attributes attributes;
  bool closing = false;       // </name>
  bool self_closing = false;  // <name/>
};

// Walks the tags of an XML text.
class Scanner {
 public:
  Scanner(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  // The next tag, or false at the end of the text. Text between tags is skipped.
  bool next(Tag& tag);

  // For a closing tag: fails unless it closes the innermost open element (the
  // last of `open`), pops that and returns true; false for any other tag.
  bool closes(const Tag& tag, std::vector<std::string>& open) const;

  // The text up to the closing tag </name>, which is consumed.
  std::string_view content_until_close(std::string_view name);

  // Throws InputError naming the source and the line of the current position.
  template <typename... Args>
  [[noreturn]] void fail(fmt::format_string<Args...> f, Args&&... args) const {
    const std::size_t line = 1 + std::count(text_.begin(), text_.begin() + std::min(pos_, text_.size()), '\n');
    input_error("{}, line {}: {}. The file is not a VTK file written by grainlab, or it is damaged", source_, line,
                fmt::format(f, std::forward<Args>(args)...));
  }

 private:
  bool starts_with(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }
  void skip_past(std::string_view s);
  void skip_spaces();
  void expect(char c, const std::string& after);
  std::string read_name(const char* what);
  std::string unescape(std::string_view s) const;

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
};

bool is_space(char c);

// The attribute's value, or nullptr.
const std::string* find(const Tag& tag, std::string_view key);

// An attribute that must be present.
const std::string& need(const Scanner& xml, const Tag& tag, std::string_view key);

// An attribute's value s as a number of type T.
template <typename T>
T parse_number(const Scanner& xml, const Tag& tag, std::string_view key, const std::string& s) {
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size())
    xml.fail("attribute '{}' of <{}> is '{}', not a number", key, tag.name, s);
  return v;
}

}  // namespace grainlab::xml
