// Reads each registered test's commented default config line by line:
//   "# meaning of the table" / "[table]" / "key = value   # unit, meaning"
// and merges the tables of all tests in first-seen order.
#include "core/text.h"
#include "io/config_reference.h"

#include "dynamics/contact_law.h"
#include "io/config.h"
#include "lab/lab_test.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

namespace grainlab {

namespace {

struct KeyDoc {
  std::string key, doc;
  std::vector<std::pair<std::string, std::string>> defaults;  // (test, value)
};

struct TableDoc {
  std::string name, doc;  // "" = the top-level keys
  std::vector<std::string> tests;
  std::vector<KeyDoc> keys;
};

// Markdown table cells may not hold a bare '|'.
std::string cell(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

template <typename T>
T& find_or_add(std::vector<T>& items, const std::string& name, std::string T::*field) {
  const auto it = std::find_if(items.begin(), items.end(), [&](const T& t) { return t.*field == name; });
  if (it != items.end()) return *it;
  items.push_back(T{});
  items.back().*field = name;
  return items.back();
}

// Adds the tables of test's commented defaults with contact law `law`; with
// laws_only, only the law's own table [material.<law>].
void read_defaults(const std::string& test, ContactLaw law, bool laws_only, std::vector<TableDoc>& tables) {
  std::istringstream in(default_config_toml(test, law));
  std::string line, comment;
  TableDoc skipped;
  TableDoc* table = laws_only ? &skipped : &find_or_add(tables, std::string(), &TableDoc::name);
  table->tests.push_back(test);
  bool header = true;  // the file's opening comment lines
  while (std::getline(in, line)) {
    if (line.empty()) {
      header = false;
      continue;
    }
    if (line.starts_with("#")) {
      if (!header) comment = trim(line.substr(1), " ");
      continue;
    }
    if (line.starts_with("[")) {
      const std::string name = line.substr(1, line.find(']') - 1);
      if (laws_only && !name.starts_with("material.")) {
        table = &skipped;
        continue;
      }
      table = &find_or_add(tables, name, &TableDoc::name);
      table->doc = comment;
      table->tests.push_back(test);
      continue;
    }
    const auto eq = line.find(" = ");
    const auto hash = line.find(" # ", eq);
    KeyDoc& key = find_or_add(table->keys, line.substr(0, eq), &KeyDoc::key);
    key.doc = hash == std::string::npos ? std::string() : trim(line.substr(hash + 3), " ");
    key.defaults.emplace_back(test, trim(line.substr(eq + 3, hash == std::string::npos ? std::string::npos : hash - eq - 3), " "));
  }
}

// The default, and where another test's default differs, that one too.
std::string default_text(const KeyDoc& k) {
  std::string out = "`" + k.defaults.front().second + "`";
  for (const auto& [test, value] : k.defaults)
    if (value != k.defaults.front().second) out += fmt::format(" (`{}`: `{}`)", test, value);
  return out;
}

}  // namespace

std::string config_reference_markdown() {
  const std::vector<std::string> tests = lab_test_names();
  std::vector<TableDoc> tables;
  for (const std::string& t : tests) read_defaults(t, ContactLaw{}, false, tables);
  for (const ContactLawEntry& law : contact_laws())  // every law's own parameter table
    read_defaults(tests.front(), parse_contact_law(std::string(law.name)), true, tables);

  std::string out =
      "# Configuration keys\n\n"
      "Every key of a run's TOML config, table by table: its default, unit and meaning. SI units\n"
      "throughout (m, kg, s, N, Pa). Every key is optional: a key left out keeps its default.\n"
      "`grainlab run --print-defaults [--test NAME]` writes the same as a commented config to\n"
      "start from. A table that only some tests read says which. A contact law's parameters\n"
      "go in its own table [material.<law>] (or, as in older configs, as flat [material] keys).\n\n"
      "This page is generated from the code (`grainlab run --print-reference > docs/config.md`);\n"
      "a test fails when the two differ.\n";
  for (const TableDoc& t : tables) {
    out += t.name.empty() ? std::string("\n## Top-level keys\n\n") : fmt::format("\n## [{}]\n\n", t.name);
    if (!t.doc.empty()) out += static_cast<char>(std::toupper(static_cast<unsigned char>(t.doc[0]))) + t.doc.substr(1) + ".";
    const bool only_some = t.tests.size() < tests.size() && !t.name.starts_with("material.");  // a law's table: any test
    if (only_some) {
      std::string only;
      for (const std::string& name : t.tests) only += (only.empty() ? "" : ", ") + ("`" + name + "`");
      out += fmt::format("{}Read only by the test {}.", t.doc.empty() ? "" : " ", only);
    }
    if (!t.doc.empty() || only_some) out += "\n\n";
    out += "| key | default | unit and meaning |\n| --- | --- | --- |\n";
    for (const KeyDoc& k : t.keys) out += fmt::format("| `{}` | {} | {} |\n", k.key, cell(default_text(k)), cell(k.doc));
  }
  return out;
}

}  // namespace grainlab
