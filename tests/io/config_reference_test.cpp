// docs/config.md is the generated configuration reference: it must be exactly
// what the code generates, so that a key added, renamed or re-documented in
// the code cannot leave the page behind.
#include "io/config_reference.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace grainlab {
namespace {

const std::filesystem::path kConfigPage = std::filesystem::path(GRAINLAB_TEST_DATA) / ".." / ".." / "docs" / "config.md";

TEST(ConfigReference, DocsPageIsWhatTheCodeGenerates) {
  std::ifstream in(kConfigPage);
  ASSERT_TRUE(in) << "cannot read " << kConfigPage;
  std::stringstream page;
  page << in.rdbuf();
  EXPECT_EQ(page.str(), config_reference_markdown())
      << "docs/config.md differs from the config schema: regenerate it with\n"
         "  build/grainlab run --print-reference > docs/config.md";
}

TEST(ConfigReference, ListsEveryTableWithItsKeysAndDefaults) {
  const std::string md = config_reference_markdown();
  // A key of every kind of table: common, test-specific, top-level.
  for (const char* s : {"## [grains]", "| `faces` | `200` |", "## [oedometer]", "Read only by the test `oedometer`.",
                        "## [triaxial]", "| `seed` | `1` |", "## Top-level keys"})
    EXPECT_NE(md.find(s), std::string::npos) << s;
  // A default that differs between tests names both.
  EXPECT_NE(md.find("(`oedometer`: `\"runs/oedometer\"`)"), std::string::npos);
}

}  // namespace
}  // namespace grainlab
