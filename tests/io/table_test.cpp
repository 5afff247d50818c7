// series.csv tables: exact doubles out and back in, and clear errors.
#include "io/table.h"

#include "core/error.h"
#include "core/atomic_file.h"
#include "io_test_helpers.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>

namespace grainlab {
namespace {

TEST(Table, CsvRoundTripsBitForBit) {
  Table t;
  t.columns = {"strain", "F", "N", "e"};
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 500; ++i) {
    std::vector<double> row(4);
    for (double& x : row) {
      do x = std::bit_cast<double>(bits(rng));
      while (!std::isfinite(x));
    }
    t.add_row(row);
  }
  t.add_row({0.1 + 0.2, -0.0, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max()});
  t.add_row({1e-300, 5e-324, 1.0, 123456789012345678.0});

  test::IoTempDir dir;
  write_file_atomically(dir.path / "series.csv", t.to_csv());
  const Table back = read_csv(dir.path / "series.csv");
  ASSERT_EQ(back.columns, t.columns);
  ASSERT_EQ(back.rows.size(), t.rows.size());
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    for (std::size_t c = 0; c < t.columns.size(); ++c)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(back.rows[r][c]), std::bit_cast<std::uint64_t>(t.rows[r][c]))
          << "row " << r << " column " << c;
}

TEST(Table, TextLooksLikeCsv) {
  Table t;
  t.columns = {"a", "b"};
  t.add_row({0.5, 100000});
  EXPECT_EQ(t.to_csv(), "a,b\n0.5,100000\n");
  EXPECT_EQ(t.column("b"), 1u);
  EXPECT_THROW(t.column("c"), std::out_of_range);
  EXPECT_THROW(t.add_row({1}), std::invalid_argument);
}

TEST(Table, BadCsvNamesFileAndLine) {
  const std::string short_row = test::error_of<InputError>([] { parse_csv("a,b\n1,2\n3\n", "s.csv"); });
  EXPECT_NE(short_row.find("s.csv (line 3)"), std::string::npos) << short_row;
  const std::string word = test::error_of<InputError>([] { parse_csv("a,b\n1,x2\n", "s.csv"); });
  EXPECT_NE(word.find("'x2' is not a number"), std::string::npos) << word;
  const std::string missing = test::error_of<InputError>([] { read_csv("/no/such/series.csv"); });
  EXPECT_NE(missing.find("/no/such/series.csv"), std::string::npos) << missing;
}

}  // namespace
}  // namespace grainlab
