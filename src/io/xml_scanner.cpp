// The XML tag scanner (definitions in xml_scanner.h).
#include "io/xml_scanner.h"

#include "core/bounded_read.h"

#include <fstream>
#include <sstream>
#include <utility>

namespace grainlab::xml {

namespace {

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
         c == '-' || c == '.';
}

}  // namespace

std::string read_text(const std::filesystem::path& path) {
  return read_bounded_file(path, 1024 * kMiB, "XML file");
}

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

bool Scanner::next(Tag& tag) {
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

bool Scanner::closes(const Tag& tag, std::vector<std::string>& open) const {
  if (!tag.closing) return false;
  if (open.empty() || open.back() != tag.name)
    fail("</{}> does not close the open element <{}>", tag.name, open.empty() ? "" : open.back());
  open.pop_back();
  return true;
}

std::string_view Scanner::content_until_close(std::string_view name) {
  const std::string close = "</" + std::string(name) + ">";
  const std::size_t end = text_.find(close, pos_);
  if (end == std::string_view::npos) fail("<{}> is never closed", name);
  const std::string_view content = text_.substr(pos_, end - pos_);
  pos_ = end + close.size();
  return content;
}

void Scanner::skip_past(std::string_view s) {
  const std::size_t end = text_.find(s, pos_);
  if (end == std::string_view::npos) fail("'{}' is never closed", text_.substr(pos_, 4));
  pos_ = end + s.size();
}

void Scanner::skip_spaces() {
  while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
}

void Scanner::expect(char c, const std::string& after) {
  if (pos_ >= text_.size() || text_[pos_] != c) fail("expected '{}' after '{}'", c, after);
  ++pos_;
}

std::string Scanner::read_name(const char* what) {
  const std::size_t start = pos_;
  while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
  if (pos_ == start) fail("expected {}", what);
  return std::string(text_.substr(start, pos_ - start));
}

std::string Scanner::unescape(std::string_view s) const {
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

const std::string* find(const Tag& tag, std::string_view key) {
  const auto it = tag.attributes.find(key);
  return it == tag.attributes.end() ? nullptr : &it->second;
}

// An attribute that must be present.
const std::string& need(const Scanner& xml, const Tag& tag, std::string_view key) {
  const std::string* v = find(tag, key);
  if (!v) xml.fail("<{}> has no '{}' attribute", tag.name, key);
  return *v;
}

}  // namespace grainlab::xml
