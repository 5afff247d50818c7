// core/bytes.h: the little-endian layout is fixed (checked byte by byte), every
// value round-trips exactly, and a truncated or damaged buffer is refused with
// a message naming its source.
#include "core/bytes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

using namespace grainlab;

TEST(Bytes, IntegersAreLittleEndian) {
  ByteWriter w;
  w.u32(0x04030201u);
  w.i64(-2);
  ASSERT_EQ(w.bytes.size(), 12u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(w.bytes[i], i + 1);
  for (int i = 4; i < 12; ++i) EXPECT_EQ(w.bytes[i], i == 4 ? 0xfe : 0xff);
}

TEST(Bytes, DoublesAreTheirIeeeBits) {
  ByteWriter w;
  w.f64(1.0);  // 0x3ff0000000000000
  ASSERT_EQ(w.bytes.size(), 8u);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(w.bytes[i], 0);
  EXPECT_EQ(w.bytes[6], 0xf0);
  EXPECT_EQ(w.bytes[7], 0x3f);
}

TEST(Bytes, EveryValueRoundTripsExactly) {
  ByteWriter w;
  const Vec3 v(0.1, -2.5e-300, std::numeric_limits<double>::denorm_min());
  const Quat q(0.5, -0.5, 0.5, std::nextafter(0.5, 1.0));
  const std::vector<double> ds = {1.0 / 3.0, -0.0, std::numeric_limits<double>::infinity()};
  const std::vector<Vec3> vs = {v, -v};
  w.u8(200), w.u32(4000000000u), w.u64(~0ull), w.i32(-7), w.i64(-9000000000ll), w.f64(M_PI);
  w.flag(true), w.vec(v), w.quat(q), w.f64s(ds), w.vecs(vs);

  ByteReader r(w.bytes, "test bytes");
  EXPECT_EQ(r.u8(), 200);
  EXPECT_EQ(r.u32(), 4000000000u);
  EXPECT_EQ(r.u64(), ~0ull);
  EXPECT_EQ(r.i32(), -7);
  EXPECT_EQ(r.i64(), -9000000000ll);
  EXPECT_EQ(r.f64(), M_PI);
  EXPECT_TRUE(r.flag());
  EXPECT_EQ(r.vec(), v);
  const Quat q2 = r.quat();
  EXPECT_EQ(q2.coeffs(), q.coeffs());
  const std::vector<double> ds2 = r.f64s();
  ASSERT_EQ(ds2.size(), 3u);
  EXPECT_EQ(ds2[0], ds[0]);
  EXPECT_TRUE(std::signbit(ds2[1]));
  EXPECT_EQ(ds2[2], ds[2]);
  EXPECT_EQ(r.vecs(), vs);
  EXPECT_EQ(r.left(), 0u);
  EXPECT_NO_THROW(r.expect_end());
}

namespace {
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Bytes, TruncationIsAClearErrorNamingTheSource) {
  ByteWriter w;
  w.f64(1.5);
  w.bytes.pop_back();
  ByteReader r(w.bytes, "protocol of 'a.bin'", " Start again.");
  EXPECT_EQ(error_of([&] { r.f64(); }), "protocol of 'a.bin' is corrupted (it ends early). Start again.");
}

TEST(Bytes, BadFlagsCountsAndLeftoversAreRefused) {
  ByteWriter w;
  w.u8(2);
  ByteReader flags(w.bytes, "flags");
  EXPECT_NE(error_of([&] { flags.flag(); }).find("flags is corrupted (a boolean"), std::string::npos);

  ByteWriter c;
  c.u64(1000);  // 1000 doubles announced, none follow
  ByteReader counts(c.bytes, "counts");
  EXPECT_NE(error_of([&] { counts.f64s(); }).find("a count is larger than the data"), std::string::npos);

  ByteWriter l;
  l.u32(1), l.u8(0);
  ByteReader left(l.bytes, "leftovers");
  left.u32();
  EXPECT_NE(error_of([&] { left.expect_end(); }).find("bytes left over"), std::string::npos);
}
