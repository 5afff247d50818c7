// Base64: RFC 4648 test vectors, round trips of every length mod 3 and every
// byte value, and the inputs the decoder must refuse.
#include "io/base64.h"
#include "io/vtk_decoding.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace grainlab {
namespace {

std::vector<std::uint8_t> bytes(std::string_view s) { return {s.begin(), s.end()}; }

TEST(Base64, Rfc4648Vectors) {
  const std::pair<const char*, const char*> vectors[] = {
      {"", ""},         {"f", "Zg=="},         {"fo", "Zm8="},         {"foo", "Zm9v"},
      {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}, {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : vectors) {
    EXPECT_EQ(base64_encode(bytes(plain)), encoded) << plain;
    EXPECT_EQ(base64_decode(encoded), bytes(plain)) << encoded;
    EXPECT_EQ(base64_length(std::string_view(plain).size()), std::string_view(encoded).size());
  }
}

TEST(Base64, RoundTripsEveryLengthAndByteValue) {
  // Lengths 0..70 cover 0, 1, 2 mod 3 many times; the bytes run through all 256 values.
  for (std::size_t n = 0; n <= 70; ++n) {
    std::vector<std::uint8_t> b(n);
    for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::uint8_t>(37 * i + 11 * n + 255 * (i % 2));
    const std::string text = base64_encode(b);
    EXPECT_EQ(text.size(), base64_length(n));
    EXPECT_EQ(text.size() % 4, 0u);
    EXPECT_EQ(text.find('='), n % 3 == 0 ? std::string::npos : text.size() - (n % 3 == 1 ? 2 : 1)) << n;
    EXPECT_EQ(base64_decode(text), b) << n;
  }
  std::vector<std::uint8_t> all(256);
  for (int i = 0; i < 256; ++i) all[i] = static_cast<std::uint8_t>(i);
  EXPECT_EQ(base64_decode(base64_encode(all)), all);
}

TEST(Base64, AppendConcatenatesGroups) {
  std::string s = "x";
  base64_append(s, bytes("fo"));
  base64_append(s, bytes("obar"));
  EXPECT_EQ(s, "xZm8=b2Jhcg==");
}

TEST(Base64, DecodeSkipsWhitespace) {
  EXPECT_EQ(base64_decode(" Zm9v\n Ym\tFy\r\n"), bytes("foobar"));
}

TEST(Base64, DecodeRefusesMalformedText) {
  for (const char* bad : {"Zg=", "Zm9vY", "Z===", "=Zg=", "Zg=a", "Zm9v!mFy", "Zg==Zg==", "Zm9\xff"})
    EXPECT_THROW(base64_decode(bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace grainlab
