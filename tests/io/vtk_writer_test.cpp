// VTK XML PolyData and .pvd files: written, read back identical (bit for bit)
// in both encodings, laid out as VTK expects (inline: the UInt64 byte count
// and the values in one base64 stream; compressed: VTK's zlib blocks in a raw
// appended section, decoded here with zlib directly), damaged files refused,
// inconsistent data refused, and the collection valid after every addition.
#include "io/vtk_writer.h"

#include "core/error.h"
#include "core/atomic_file.h"
#include "io/base64.h"
#include "io/vtk_decoding.h"
#include "io/pvd_reader.h"
#include "io/vtp_reader.h"
#include "io_test_helpers.h"
#include "vtk_test_helpers.h"

#include <gtest/gtest.h>

#include <zlib.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace grainlab {
namespace {

// Two triangles, a line, two vertices and arrays of every type on points and cells.
PolyData every_array_type() {
  PolyData pd;
  const double nan_payload = std::bit_cast<double>(0x7ff8000000012345ull);
  pd.points.values = std::vector<double>{0.0, -0.0, 1e-300,  0.1 + 0.2, -1.5e-3, 2.5e-3,
                                         1, 2, 3,          4.9e-324, std::numeric_limits<double>::max(), -7,
                                         nan_payload, 0.5, std::numeric_limits<double>::infinity()};
  pd.verts.add({0});
  pd.verts.add({4});
  pd.lines.add({1, 3});
  pd.polys.add({0, 1, 2});
  pd.polys.add({2, 3, 4});
  pd.point_data.push_back({"vec64", 3, std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, -0.0, 1e-310, 15}});
  pd.point_data.push_back({"f32", 1, std::vector<float>{0.1f, -0.0f, 3e38f, 1e-45f, 5}});
  pd.point_data.push_back({"ids & <names>", 1, std::vector<std::int32_t>{0, -1, 2147483647, -2147483647 - 1, 4}});
  pd.cell_data.push_back({"c64", 1, std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5}});
  pd.cell_data.push_back({"c32", 2, std::vector<float>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}});
  pd.cell_data.push_back({"cid", 1, std::vector<std::int32_t>{10, 11, 12, 13, 14}});
  return pd;
}

void expect_same(const PolyData& a, const PolyData& b) {
  EXPECT_TRUE(test::same_bits(a.points, b.points));
  EXPECT_EQ(a.verts, b.verts);
  EXPECT_EQ(a.lines, b.lines);
  EXPECT_EQ(a.polys, b.polys);
  ASSERT_EQ(a.point_data.size(), b.point_data.size());
  for (std::size_t i = 0; i < a.point_data.size(); ++i) EXPECT_TRUE(test::same_bits(a.point_data[i], b.point_data[i]));
  ASSERT_EQ(a.cell_data.size(), b.cell_data.size());
  for (std::size_t i = 0; i < a.cell_data.size(); ++i) EXPECT_TRUE(test::same_bits(a.cell_data[i], b.cell_data[i]));
}

TEST(VtkWriter, PolyDataRoundTripsBitForBit) {
  test::IoTempDir dir;
  const PolyData pd = every_array_type();
  ASSERT_EQ(pd.point_count(), 5u);
  ASSERT_EQ(pd.cell_count(), 5u);
  for (const VtpEncoding e : {VtpEncoding::Compressed, VtpEncoding::Inline}) {
    write_vtp(dir.path / "every.vtp", pd, e);
    const PolyData back = read_vtp(dir.path / "every.vtp");
    expect_same(pd, back);
    EXPECT_EQ(back.points.values.index(), 0u);  // Float64 stays Float64
  }
}

TEST(VtkWriter, ArraysLongerThanOneZlibBlockRoundTrip) {
  test::IoTempDir dir;
  PolyData pd;
  std::vector<double> p(3 * 50000);  // 1.2 MB: 5 blocks of 256 KiB, the last one partial
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = std::sin(0.37 * static_cast<double>(i)) * 1e-3;
  pd.points.values = p;
  for (std::int64_t i = 0; i + 2 < 50000; i += 3) pd.polys.add({i, i + 1, i + 2});
  write_vtp(dir.path / "big.vtp", pd);
  expect_same(pd, read_vtp(dir.path / "big.vtp"));
}

TEST(VtkWriter, Float32PointsAndEmptyDataRoundTrip) {
  test::IoTempDir dir;
  PolyData pd;
  pd.points = {"Points", 3, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}};
  pd.polys.add({0, 1, 2});
  write_vtp(dir.path / "tri.vtp", pd);
  expect_same(pd, read_vtp(dir.path / "tri.vtp"));

  PolyData empty;  // no points, no cells: a contacts file of a run with no contacts
  empty.cell_data.push_back({"force", 3, std::vector<double>{}});
  write_vtp(dir.path / "empty.vtp", empty);
  const PolyData back = read_vtp(dir.path / "empty.vtp");
  expect_same(empty, back);
  EXPECT_EQ(back.point_count(), 0u);
}

TEST(VtkWriter, BinaryLayoutIsVtksInlineBase64WithUInt64Header) {
  PolyData pd;
  pd.points.values = std::vector<double>{1, 2, 3};
  pd.verts.add({0});
  const std::string text = vtp_text(pd, VtpEncoding::Inline);
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(text.find("byte_order=\"LittleEndian\""), std::string::npos);
  EXPECT_NE(text.find("NumberOfPoints=\"1\" NumberOfVerts=\"1\" NumberOfLines=\"0\""), std::string::npos);
  // 24 bytes of points: the count (24 as a little-endian u64) and the values in
  // one base64 stream, not two padded blocks (VTK's reader seeks into one stream).
  std::vector<std::uint8_t> payload(8 + 24, 0);
  payload[0] = 24;
  std::memcpy(payload.data() + 8, std::get<std::vector<double>>(pd.points.values).data(), 24);
  const std::string expected = "format=\"binary\">" + base64_encode(payload) + "</DataArray>";
  EXPECT_NE(text.find(expected), std::string::npos) << text;
  // Connectivity {0} and offsets {1} as Int64 (base64 computed independently).
  EXPECT_NE(text.find("Name=\"connectivity\" format=\"binary\">CAAAAAAAAAAAAAAAAAAAAA==</DataArray>"),
            std::string::npos);
  EXPECT_NE(text.find("Name=\"offsets\" format=\"binary\">CAAAAAAAAAABAAAAAAAAAA==</DataArray>"), std::string::npos);
}

TEST(VtkWriter, ReadsUInt32HeadersEncodedTogetherOrApart) {
  // The other header type VTK writes: a u32 byte count; the same data with the
  // header in the values' stream (as VTK writes) and padded apart (as some writers do).
  const auto file = [](const char* points, const char* conn, const char* offsets) {
    return std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                       "<PolyData><Piece NumberOfPoints=\"1\" NumberOfVerts=\"1\">\n"
                       "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" Name=\"Points\" format=\"binary\">") +
           points + "</DataArray></Points>\n<Verts><DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\">" +
           conn + "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"binary\">" + offsets +
           "</DataArray></Verts>\n</Piece></PolyData></VTKFile>\n";
  };
  for (const std::string& text : {file("DAAAAAAAgD8AAABAAABAQA==", "BAAAAAAAAAA=", "BAAAAAEAAAA="),
                                  file("DAAAAA==AACAPwAAAEAAAEBA", "BAAAAA==AAAAAA==", "BAAAAA==AQAAAA==")}) {
    const PolyData pd = parse_vtp(text, "u32.vtp");
    EXPECT_EQ(std::get<std::vector<float>>(pd.points.values), (std::vector<float>{1, 2, 3}));
    EXPECT_EQ(pd.verts.connectivity, (std::vector<std::int64_t>{0}));
    EXPECT_EQ(pd.verts.offsets, (std::vector<std::int64_t>{1}));
  }
}

TEST(VtkWriter, RefusesInconsistentPolyData) {
  const auto refused = [](const PolyData& pd) {
    test::IoTempDir dir;
    EXPECT_THROW(write_vtp(dir.path / "bad.vtp", pd), std::invalid_argument);
    EXPECT_FALSE(std::filesystem::exists(dir.path / "bad.vtp"));
  };
  PolyData pd = every_array_type();
  pd.polys.connectivity[4] = 5;  // point 5 of 5
  refused(pd);
  pd = every_array_type();
  pd.lines.offsets[0] = 3;  // beyond the connectivity
  refused(pd);
  pd = every_array_type();
  pd.cell_data[0] = {"c64", 1, std::vector<double>{1, 2}};  // 2 tuples for 5 cells
  refused(pd);
  pd = every_array_type();
  pd.point_data[1].name = "vec64";  // repeated name
  refused(pd);
  pd = every_array_type();
  pd.points = {"Points", 3, std::vector<std::int32_t>{0, 0, 0}};  // integer points
  refused(pd);
}

TEST(VtkWriter, CompressedLayoutIsVtksZlibBlocksInRawAppendedData) {
  PolyData pd;
  const std::vector<double> xyz{1, 2, 3, 4, 5, 6};
  pd.points.values = xyz;
  pd.lines.add({0, 1});
  const std::string text = vtp_text(pd);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos) << text;
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  // Points come first in the appended data (no point or cell data here), then
  // the Int32 connectivity and offsets.
  EXPECT_NE(text.find("NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/>"), std::string::npos) << text;
  EXPECT_NE(text.find("<DataArray type=\"Int32\" Name=\"connectivity\" format=\"appended\""), std::string::npos);
  const std::size_t underscore = text.find('_', text.find("<AppendedData encoding=\"raw\">"));
  ASSERT_NE(underscore, std::string::npos);
  const char* data = text.data() + underscore + 1;
  std::uint64_t head[4];
  std::memcpy(head, data, sizeof head);
  EXPECT_EQ(head[0], 1u);        // one block
  EXPECT_EQ(head[2], 48u);       // holding all 48 bytes
  EXPECT_LE(head[2], head[1]);   // within the block size
  std::vector<double> back(6);
  uLongf len = 48;
  ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(back.data()), &len, reinterpret_cast<const Bytef*>(data + 32),
                       static_cast<uLong>(head[3])),
            Z_OK);
  EXPECT_EQ(len, 48u);
  EXPECT_EQ(back, xyz);
  // The connectivity's header follows right after the points' block.
  const std::size_t conn_offset = 32 + head[3];
  EXPECT_NE(text.find(fmt::format("Name=\"connectivity\" format=\"appended\" offset=\"{}\"/>", conn_offset)),
            std::string::npos) << text;
}

TEST(VtkWriter, ReaderRefusesDamagedCompressedFiles) {
  const std::string good = vtp_text(every_array_type());
  ASSERT_NO_THROW(parse_vtp(good, "good.vtp"));
  const auto damaged = [&](const std::string& text, const char* why) {
    const std::string msg = test::error_of<InputError>([&] { parse_vtp(text, "damaged.vtp"); });
    EXPECT_NE(msg.find("damaged.vtp"), std::string::npos) << why << ": " << msg;
  };
  damaged(good.substr(0, good.size() - 40), "truncated in the appended data");
  damaged(good.substr(0, good.find("<AppendedData") + 20), "truncated in the appended tag");
  std::string t = good;
  const std::size_t data = t.find('_', t.find("<AppendedData")) + 1;
  t[data + 40] = static_cast<char>(t[data + 40] ^ 0x5a);  // inside the first zlib block
  damaged(t, "corrupt block");
  t = good;
  t.replace(t.find("offset=\"0\""), 10, "offset=\"9\"");
  damaged(t, "wrong offset");
}

TEST(VtkWriter, ReaderRefusesDamagedFiles) {
  const std::string good = vtp_text(every_array_type(), VtpEncoding::Inline);
  const auto damaged = [&](std::string text, const char* why) {
    const std::string msg = test::error_of<InputError>([&] { parse_vtp(text, "damaged.vtp"); });
    EXPECT_NE(msg.find("damaged.vtp"), std::string::npos) << why << ": " << msg;
  };
  damaged(good.substr(0, good.size() / 2), "truncated");
  std::string t = good;
  t.replace(t.find("NumberOfPoints=\"5\""), 18, "NumberOfPoints=\"6\"");
  damaged(t, "count mismatch");
  t = good;
  const std::size_t start = t.find("binary\">", t.find("Name=\"c64\"")) + 8;
  const std::size_t end = t.find('<', start);
  std::vector<std::uint8_t> payload = base64_decode(t.substr(start, end - start));
  ASSERT_EQ(payload[0], 40);  // 5 doubles
  payload[0] = 48;            // the byte count says 6
  t.replace(start, end - start, base64_encode(payload));
  damaged(t, "byte count");
  t = good;
  t.replace(t.find("</Points>"), 9, "</Pointz>");
  damaged(t, "mismatched tags");
  damaged("<VTKFile type=\"UnstructuredGrid\"></VTKFile>", "other type");
  EXPECT_THROW(read_vtp("/nonexistent/grainlab.vtp"), InputError);
}

TEST(PvdCollection, IsValidAfterEveryAddAndKeepsExactTimes) {
  test::IoTempDir dir;
  PvdCollection pvd(dir.path / "grains.pvd");
  const std::vector<PvdEntry> want = {{0, "grains_0000.vtp"}, {0.1 + 0.2, "grains_0001.vtp"}, {1e-7, "a&b \"c\".vtp"}};
  for (std::size_t k = 0; k < want.size(); ++k) {
    pvd.add(want[k].time, want[k].file);
    const std::vector<PvdEntry> got = read_pvd(dir.path / "grains.pvd");
    EXPECT_EQ(got, std::vector<PvdEntry>(want.begin(), want.begin() + k + 1));
  }
  EXPECT_EQ(pvd.entries(), want);
  // Each DataSet is one line with a timestep and a file.
  const std::string text = test::file_text(dir.path / "grains.pvd");
  std::size_t lines = 0;
  for (std::size_t p = text.find("<DataSet "); p != std::string::npos; p = text.find("<DataSet ", p + 1)) {
    const std::string line = text.substr(p, text.find('\n', p) - p);
    EXPECT_EQ(line.substr(line.size() - 2), "/>") << line;
    EXPECT_NE(line.find("timestep=\""), std::string::npos) << line;
    ++lines;
  }
  EXPECT_EQ(lines, 3u);
  EXPECT_NE(text.find("file=\"a&amp;b &quot;c&quot;.vtp\""), std::string::npos) << text;
}

TEST(PvdCollection, ReplacesARewrittenSnapshotAndRefusesBadTimes) {
  test::IoTempDir dir;
  PvdCollection pvd(dir.path / "walls.pvd");
  pvd.add(0, "walls_0000.vtp");
  pvd.add(1, "walls_0001.vtp");
  pvd.add(0.5, "walls_0001.vtp");  // written again after a restart
  EXPECT_EQ(read_pvd(dir.path / "walls.pvd"),
            (std::vector<PvdEntry>{{0, "walls_0000.vtp"}, {0.5, "walls_0001.vtp"}}));
  EXPECT_THROW(pvd.add(std::nan(""), "walls_0002.vtp"), std::invalid_argument);
  EXPECT_EQ(read_pvd(dir.path / "walls.pvd").size(), 2u);

  PvdCollection missing(dir.path / "no" / "such" / "folder.pvd");
  EXPECT_THROW(missing.add(0, "x.vtp"), RunError);
  EXPECT_TRUE(missing.entries().empty());  // as the (absent) file is
}

TEST(VtkWriter, FilesAreWellFormedXmlPerXmllint) {
  if (!test::have_xmllint()) GTEST_SKIP() << "xmllint is not installed";
  test::IoTempDir dir;
  write_vtp(dir.path / "every.vtp", every_array_type(), VtpEncoding::Inline);
  // A compressed file is XML up to its raw appended bytes.
  const std::string compressed = vtp_text(every_array_type());
  write_file_atomically(dir.path / "head.vtp", compressed.substr(0, compressed.find("<AppendedData")) + "</VTKFile>\n");
  EXPECT_EQ(test::xmllint_status(dir.path / "head.vtp"), 0);
  PvdCollection pvd(dir.path / "every.pvd");
  pvd.add(0.25, "every & more.vtp");
  EXPECT_EQ(test::xmllint_status(dir.path / "every.vtp"), 0);
  EXPECT_EQ(test::xmllint_status(dir.path / "every.pvd"), 0);
  // And it does fail on a broken file, so the check means something.
  write_file_atomically(dir.path / "broken.vtp", "<VTKFile><PolyData></VTKFile>\n");
  EXPECT_NE(test::xmllint_status(dir.path / "broken.vtp"), 0);
}

}  // namespace
}  // namespace grainlab
