#include "ct/slice_stack.h"

#include "core/error.h"
#include "ct/itk_bridge.h"

#include <algorithm>
#include <cctype>

namespace grainlab::ct {

namespace fs = std::filesystem;

namespace {

bool is_slice_file(const fs::directory_entry& e) {
  const std::string name = e.path().filename().string();
  if (name.empty() || name[0] == '.' || !e.is_regular_file()) return false;
  const std::string f = itk_bridge::format_for(name);
  return f == "TIFF" || f == "PNG";
}

std::string size_text(const itk_bridge::Header& h) {
  std::string s;
  for (std::size_t a = 0; a < h.extent.size(); ++a) s += (a ? " x " : "") + std::to_string(h.extent[a]);
  return s;
}

}  // namespace

SliceName parse_slice_name(const std::string& filename, int run_from_end) {
  SliceName n;
  n.before = filename;
  // The runs of digits, last first.
  std::size_t end = filename.size();
  for (int run = 0;; ++run) {
    const auto last_digit = filename.find_last_of("0123456789", end == 0 ? 0 : end - 1);
    if (end == 0 || last_digit == std::string::npos) return n;
    auto first_digit = last_digit;
    while (first_digit > 0 && std::isdigit(static_cast<unsigned char>(filename[first_digit - 1]))) --first_digit;
    if (run == run_from_end) {
      const std::string digits = filename.substr(first_digit, last_digit - first_digit + 1);
      if (digits.size() > 15) return n;  // not a slice number
      n.before = filename.substr(0, first_digit);
      n.after = filename.substr(last_digit + 1);
      n.number = std::stoll(digits);
      return n;
    }
    end = first_digit;
  }
}

SliceStack scan_slice_folder(const fs::path& folder) {
  const std::string where = folder.string();
  struct Entry {
    fs::path path;
    SliceName name;
  };
  std::vector<Entry> entries;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    if (is_slice_file(e)) entries.push_back({e.path(), parse_slice_name(e.path().filename().string())});
  }
  // The slice number is the last run of digits that differs between the files (scan_0012_v2.tif: 12).
  for (int run = 1; entries.size() > 1; ++run) {
    const bool same = std::all_of(entries.begin(), entries.end(), [&](const Entry& e) {
      return e.name.number >= 0 && e.name.number == entries.front().name.number;
    });
    if (!same) break;
    std::vector<Entry> earlier = entries;
    for (Entry& e : earlier) e.name = parse_slice_name(e.path.filename().string(), run);
    if (earlier.front().name.number < 0) break;
    entries = std::move(earlier);
  }
  if (ec) input_error("cannot list the slice folder '{}': {}", where, ec.message());
  if (entries.size() < 2) {
    input_error("folder '{}' holds {} 2D slice file(s) (.tif, .tiff or .png); a slice stack needs one file per z, "
                "numbered in their names (slice_0000.tif, slice_0001.tif, ...)",
                where, entries.size());
  }
  for (const Entry& e : entries) {
    if (e.name.number < 0) {
      input_error("slice folder '{}': '{}' has no number in its name, so its place in the stack is unknown: name "
                  "every slice with its number (slice_0000.tif, slice_0001.tif, ...) or move it out",
                  where, e.path.filename().string());
    }
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.name.number != b.name.number ? a.name.number < b.name.number
                                          : a.path.filename() < b.path.filename();
  });
  SliceStack stack;
  const Entry& first = entries.front();
  stack.first_number = first.name.number;
  for (std::size_t z = 0; z < entries.size(); ++z) {
    const Entry& e = entries[z];
    const std::string name = e.path.filename().string();
    if (e.name.before != first.name.before ||
        itk_bridge::format_for(name) != itk_bridge::format_for(first.path.string())) {
      input_error("slice folder '{}' mixes two series or formats: '{}' and '{}'; keep one series of slices (one "
                  "name pattern, TIFF or PNG) per folder",
                  where, first.path.filename().string(), name);
    }
    if (z > 0) {
      const Entry& prev = entries[z - 1];
      if (e.name.number == prev.name.number) {
        input_error("slice folder '{}': '{}' and '{}' carry the same slice number {}; remove the duplicate", where,
                    prev.path.filename().string(), name, e.name.number);
      }
      if (e.name.number != prev.name.number + 1) {
        const std::int64_t missing = e.name.number - prev.name.number - 1;
        input_error("slice folder '{}' has a gap in its numbering: {} slice(s) missing between '{}' and '{}' "
                    "(numbers {} to {}); a stack must be complete: copy the missing slices, or crop the stack "
                    "into a folder of consecutive slices",
                    where, missing, prev.path.filename().string(), name, prev.name.number + 1,
                    e.name.number - 1);
      }
    }
    stack.files.push_back(e.path);
  }
  stack.format = itk_bridge::format_for(first.path.string());

  // Headers: every slice 2D, one channel, the same size and pixel type as the first.
  itk_bridge::Header ref;
  for (std::size_t z = 0; z < stack.files.size(); ++z) {
    const std::string path = stack.files[z].string();
    const itk_bridge::Header h = itk_bridge::read_header(path);
    const bool flat = h.dimensions == 2 || (h.dimensions == 3 && h.extent[2] == 1);
    if (!flat) {
      input_error("slice '{}' is not a 2D image ({} voxels): a slice folder holds one 2D image per file; a "
                  "multi-page TIFF is a volume by itself: segment that file",
                  path, size_text(h));
    }
    if (h.components != 1) {
      input_error("slice '{}' has {} channels (colour); CT slices have one grey level per pixel: convert the "
                  "slices to greyscale",
                  path, h.components);
    }
    if (z == 0) {
      ref = h;
      continue;
    }
    if (h.extent[0] != ref.extent[0] || h.extent[1] != ref.extent[1]) {
      input_error("slices of different sizes in '{}': '{}' is {} x {} pixels, but '{}' is {} x {}; every slice of "
                  "a stack must have the same width and height",
                  where, stack.files[0].filename().string(), ref.extent[0], ref.extent[1],
                  stack.files[z].filename().string(), h.extent[0], h.extent[1]);
    }
    if (h.component_type != ref.component_type) {
      input_error("slices of different pixel types in '{}': '{}' holds {}, but '{}' holds {}; a stack must be one "
                  "pixel type throughout (export all slices the same way)",
                  where, stack.files[0].filename().string(), ref.component_type, stack.files[z].filename().string(),
                  h.component_type);
    }
  }
  stack.size = {ref.extent[0], ref.extent[1], static_cast<std::int64_t>(stack.files.size())};
  stack.pixel_type = ref.component_type;
  return stack;
}

void read_slice(const SliceStack& stack, std::int64_t z, std::vector<float>& values) {
  values = itk_bridge::read_values(stack.files[static_cast<std::size_t>(z)].string());
  if (static_cast<std::int64_t>(values.size()) != stack.size[0] * stack.size[1]) {
    input_error("slice '{}' changed while it was read ({} voxels, {} x {} expected)",
                stack.files[static_cast<std::size_t>(z)].string(), values.size(), stack.size[0], stack.size[1]);
  }
}

}  // namespace grainlab::ct
