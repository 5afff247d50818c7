// Portable byte writer and reader for checkpoints and every part saved in one
// (the State, a lab test's protocol, a controller's integral).
//
// Every number is written little-endian byte by byte: integers by shifts,
// doubles as their IEEE-754 bits (std::bit_cast), so the bytes are the same on
// every host, exact, and struct padding never reaches them. A read past the
// end throws InputError naming the source ("<source> is corrupted (it ends
// early).<advice>"), so a truncated file is reported, never read as garbage.
#pragma once

#include "core/error.h"
#include "core/types.h"

#include <bit>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// Appends little-endian values to `bytes`.
class ByteWriter {
 public:
  std::vector<std::uint8_t> bytes;  // what was written so far

  // Unsigned and signed integers, little-endian.
  void u8(std::uint8_t v) { bytes.push_back(v); }
  void u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  // A double as its IEEE-754 bits.
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  // A boolean as one byte, 0 or 1.
  void flag(bool v) { u8(v ? 1 : 0); }
  // A vector as x, y, z.
  void vec(const Vec3& v) { f64(v.x()), f64(v.y()), f64(v.z()); }
  // A quaternion as x, y, z, w.
  void quat(const Quat& q) { f64(q.x()), f64(q.y()), f64(q.z()), f64(q.w()); }
  // A count (u64) then the doubles.
  void f64s(const std::vector<double>& v) {
    u64(v.size());
    for (double x : v) f64(x);
  }
  // A count (u64) then the vectors.
  void vecs(const std::vector<Vec3>& v) {
    u64(v.size());
    for (const Vec3& x : v) vec(x);
  }
  // Raw bytes as they are (no count).
  void raw(std::span<const std::uint8_t> b) { bytes.insert(bytes.end(), b.begin(), b.end()); }
};

// Reads little-endian values written by ByteWriter; any read past the end,
// an impossible count or a bad flag throws InputError naming the source.
class ByteReader {
 public:
  // `source` names the bytes in messages (e.g. "checkpoint 'run/checkpoint.bin'");
  // `advice` follows the message (e.g. " Delete it and start again.").
  ByteReader(std::span<const std::uint8_t> bytes, std::string source, std::string advice = "")
      : bytes_(bytes), source_(std::move(source)), advice_(std::move(advice)) {}

  // Bytes not read yet.
  std::size_t left() const { return bytes_.size() - pos_; }
  // Readers of the values ByteWriter writes.
  std::uint8_t u8() { return take(1)[0]; }
  std::uint32_t u32() {
    const std::uint8_t* p = take(4);
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(p[i]) << (8 * i);
    return v;
  }
  std::uint64_t u64() {
    const std::uint8_t* p = take(8);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
  }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64() { return std::bit_cast<double>(u64()); }
  bool flag() {
    const std::uint8_t v = u8();
    if (v > 1) corrupted("a boolean holds a value other than 0 or 1");
    return v == 1;
  }
  Vec3 vec() {
    Vec3 v;
    v.x() = f64(), v.y() = f64(), v.z() = f64();
    return v;
  }
  Quat quat() {
    Quat q;
    q.x() = f64(), q.y() = f64(), q.z() = f64(), q.w() = f64();
    return q;
  }
  std::vector<double> f64s() {
    std::vector<double> v(count(8));
    for (double& x : v) x = f64();
    return v;
  }
  std::vector<Vec3> vecs() {
    std::vector<Vec3> v(count(24));
    for (Vec3& x : v) x = vec();
    return v;
  }
  // The next n bytes as they are (what ByteWriter::raw wrote).
  std::span<const std::uint8_t> raw(std::size_t n) { return {take(n), n}; }
  // A count of items of at least `item_size` bytes each, checked against what is left.
  std::size_t count(std::size_t item_size) {
    const std::uint64_t n = u64();
    if (item_size > 0 && n > left() / item_size) corrupted("a count is larger than the data");
    return static_cast<std::size_t>(n);
  }
  // Throws unless every byte was read.
  void expect_end() const {
    if (left() != 0) corrupted("bytes left over after the last field");
  }
  // Throws InputError: "<source> is corrupted (<what>).<advice>".
  [[noreturn]] void corrupted(std::string_view what) const {
    input_error("{} is corrupted ({}).{}", source_, what, advice_);
  }

 private:
  const std::uint8_t* take(std::size_t n) {
    if (n > left()) corrupted("it ends early");
    const std::uint8_t* p = bytes_.data() + pos_;
    pos_ += n;
    return p;
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
  std::string source_, advice_;
};

}  // namespace grainlab
