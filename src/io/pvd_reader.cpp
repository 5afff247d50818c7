// Reading grainlab's .pvd collections (see pvd_reader.h).
#include "io/pvd_reader.h"

#include "io/xml_scanner.h"

namespace grainlab {

using xml::need;
using xml::parse_number;
using xml::Tag;

std::vector<PvdEntry> parse_pvd(std::string_view text, const std::string& source_name) {
  xml::Scanner xml(text, source_name);
  std::vector<PvdEntry> entries;
  std::vector<std::string> stack;
  bool seen_root = false, seen_collection = false;
  Tag tag;
  while (xml.next(tag)) {
    if (xml.closes(tag, stack)) continue;
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

std::vector<PvdEntry> read_pvd(const std::filesystem::path& path) { return parse_pvd(xml::read_text(path), path.string()); }

}  // namespace grainlab
