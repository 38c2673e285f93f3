// ISO 25178-72 (X3P) topography: MD5 against RFC 1321, the writer and reader round trip bit for
// bit, hand-built files of every height type, and the refusals (each an InputError naming the file
// and the field). The hand-built files are made here with libzip.
#include "config/input_error.hpp"
#include "topography/topography_files.hpp"
#include "topography/x3p_file.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <zip.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

using namespace geartrib;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::filesystem::path temp(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("geartrib-x3p-" + name);
}

// A zip of these entries (name, bytes), stored.
void write_zip(const std::filesystem::path& path, const std::vector<std::pair<std::string, std::string>>& entries) {
  std::filesystem::remove(path);
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(z, nullptr);
  for (const auto& [name, bytes] : entries) {
    zip_source_t* s = zip_source_buffer(z, bytes.data(), bytes.size(), 0);
    ASSERT_NE(s, nullptr);
    ASSERT_GE(zip_file_add(z, name.c_str(), s, ZIP_FL_ENC_UTF_8), 0);
  }
  ASSERT_EQ(zip_close(z), 0);
}

// One entry of a zip, whole.
std::string read_entry(const std::filesystem::path& path, const std::string& name) {
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_RDONLY, &error);
  if (!z) return "<no zip>";
  zip_stat_t st;
  zip_stat_init(&st);
  std::string out;
  if (zip_stat(z, name.c_str(), 0, &st) == 0) {
    out.resize(st.size);
    zip_file_t* f = zip_fopen(z, name.c_str(), 0);
    if (f) {
      if (zip_fread(f, out.data(), out.size()) != static_cast<zip_int64_t>(out.size())) out = "<short read>";
      zip_fclose(f);
    }
  }
  zip_discard(z);
  return out;
}

// Little-endian bytes of a value.
template <class T>
std::string bytes_of(T v) {
  using U = std::conditional_t<sizeof(T) == 8, std::uint64_t,
                               std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint16_t>>;
  const U u = std::bit_cast<U>(v);
  std::string s(sizeof(T), '\0');
  for (std::size_t b = 0; b < sizeof(T); ++b) s[b] = static_cast<char>(u >> (8 * b));
  return s;
}

// main.xml of a hand-built file; `data` is Record3's DataLink or DataList element(s).
struct Spec {
  std::string feature = "SUR";
  std::string x_axis = "I";
  std::string dx = "1e-06", dy = "2e-06";
  std::string type = "D";
  std::string z_increment_offset;  // e.g. "<Increment>1e-9</Increment><Offset>0</Offset>"
  std::string size_x = "4", size_y = "3", size_z = "1";
  std::string data;
};
std::string main_xml(const Spec& s) {
  return fmt::format(
      R"(<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
  <Record1><Revision>ISO5436 - 2000</Revision><FeatureType>{}</FeatureType>
    <Axes>
      <CX><AxisType>{}</AxisType><DataType>D</DataType><Increment>{}</Increment><Offset>0.001</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>{}</Increment><Offset>0</Offset></CY>
      <CZ><AxisType>A</AxisType><DataType>{}</DataType>{}</CZ>
    </Axes>
  </Record1>
  <Record3>
    <MatrixDimension><SizeX>{}</SizeX><SizeY>{}</SizeY><SizeZ>{}</SizeZ></MatrixDimension>
    {}
  </Record3>
  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
)",
      s.feature, s.x_axis, s.dx, s.dy, s.type, s.z_increment_offset, s.size_x, s.size_y, s.size_z, s.data);
}
std::string data_link(const std::string& data, const std::string& valid = "") {
  std::string x = fmt::format(
      "<DataLink><PointDataLink>bindata/data.bin</PointDataLink>"
      "<MD5ChecksumPointData>{}</MD5ChecksumPointData>",
      io::md5_hex(data));
  if (!valid.empty())
    x += fmt::format(
        "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>"
        "<MD5ChecksumValidPoints>{}</MD5ChecksumValidPoints>",
        io::md5_hex(valid));
  return x + "</DataLink>";
}

// A grid's heights with NaN at its missing points, as bytes (for memcmp).
std::vector<double> with_nan(const surface::HeightGrid& g) {
  std::vector<double> z(g.z);
  for (std::size_t k = 0; k < z.size(); ++k)
    if (!g.valid[k]) z[k] = kNaN;
  return z;
}
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// The InputError `read` throws: it names `file` and its key contains `field`.
template <class F>
void expect_refusal(F read, const std::filesystem::path& file, const std::string& field, const std::string& rule) {
  try {
    read();
    ADD_FAILURE() << "no InputError for " << field;
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), file.string()) << e.what();
    EXPECT_NE(e.key().find(field), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(Md5, Rfc1321TestVectors) {
  // RFC 1321, appendix A.5.
  EXPECT_EQ(io::md5_hex(""), "d41d8cd98f00b204e9800998ecf8427e");
  EXPECT_EQ(io::md5_hex("a"), "0cc175b9c0f1b6a831c399e269772661");
  EXPECT_EQ(io::md5_hex("abc"), "900150983cd24fb0d6963f7d28e17f72");
  EXPECT_EQ(io::md5_hex("message digest"), "f96b697d7cb7938d525a2f31aaf161d0");
  EXPECT_EQ(io::md5_hex("abcdefghijklmnopqrstuvwxyz"), "c3fcd3d76192e4007dfb496cca67e13b");
  EXPECT_EQ(io::md5_hex("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789"),
            "d174ab98d277d9f5a5611c2c9f419d9f");
  EXPECT_EQ(io::md5_hex("12345678901234567890123456789012345678901234567890123456789012345678901234567890"),
            "57edf4a22be3c955ac49da2e2107b67a");
}

TEST(Md5, PiecewiseEqualsWhole) {
  // Lengths around the 64-byte block and the 56-byte padding boundary, fed in uneven pieces.
  std::mt19937 rng(7);
  for (std::size_t n : {55u, 56u, 63u, 64u, 65u, 119u, 120u, 1000u}) {
    std::string s(n, '\0');
    for (auto& c : s) c = static_cast<char>(rng());
    const std::string whole = io::md5_hex(s);
    for (std::size_t piece : {1u, 7u, 63u, 64u, 65u}) {
      io::Md5 m;
      for (std::size_t k = 0; k < n; k += piece) m.update(std::string_view(s).substr(k, piece));
      std::string hex;
      for (auto b : m.digest()) hex += fmt::format("{:02x}", b);
      EXPECT_EQ(hex, whole) << n << " bytes in pieces of " << piece;
    }
  }
}

TEST(X3p, RoundTripIsBitExact) {
  // Non-square spacing, holes, a negative zero, extreme but valid heights.
  surface::HeightGrid g = surface::make_grid(37, 23, 0.37e-6, 1.3e-6);
  std::mt19937 rng(11);
  std::normal_distribution<double> n(0.0, 0.4e-6);
  for (double& z : g.z) z = n(rng);
  g.z[1] = -0.0;
  g.z[2] = 1.0;
  g.z[3] = -std::nextafter(1.0, 0.0);
  g.z[4] = 5e-324;  // the smallest subnormal
  for (std::size_t k : {0u, 10u, 36u, 37u, 400u, 850u}) g.valid[k] = 0, g.z[k] = 0.0;
  const auto path = temp("roundtrip.x3p");
  io::write_x3p(path, g);
  const surface::HeightGrid r = io::read_x3p(path);
  ASSERT_EQ(r.nx, g.nx);
  ASSERT_EQ(r.ny, g.ny);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(r.dx), std::bit_cast<std::uint64_t>(g.dx));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(r.dy), std::bit_cast<std::uint64_t>(g.dy));
  EXPECT_EQ(r.valid, g.valid);
  EXPECT_TRUE(same_bits(with_nan(r), with_nan(g)));
  EXPECT_TRUE(std::signbit(r.z[1]));
  // Through the format dispatch too (read_topography by extension).
  const surface::HeightGrid t = io::read_topography(path);
  EXPECT_TRUE(same_bits(with_nan(t), with_nan(g)));
  std::filesystem::remove(path);
}

TEST(X3p, RewriteGivesTheSameDataBin) {
  surface::HeightGrid g = surface::make_grid(16, 9, 0.5e-6, 0.25e-6);
  for (std::size_t k = 0; k < g.size(); ++k) g.z[k] = 1e-7 * std::sin(0.3 * static_cast<double>(k));
  g.valid[17] = 0, g.z[17] = 0.0;
  const auto a = temp("first.x3p"), b = temp("second.x3p");
  io::write_topography(a, g);
  const surface::HeightGrid once = io::read_topography(a);
  io::write_topography(b, once);
  const surface::HeightGrid twice = io::read_topography(b);
  const std::string data_a = read_entry(a, "bindata/data.bin"), data_b = read_entry(b, "bindata/data.bin");
  EXPECT_EQ(data_a.size(), g.size() * 8);
  EXPECT_EQ(data_a, data_b);
  EXPECT_TRUE(same_bits(with_nan(once), with_nan(twice)));
  // md5checksum.hex holds main.xml's MD5 in md5sum's form.
  EXPECT_EQ(read_entry(a, "md5checksum.hex"), io::md5_hex(read_entry(a, "main.xml")) + " *main.xml\n");
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

TEST(X3p, IntegerHeightsScaleByTheIncrement) {
  // int16 (I) with a valid.bin marking two points invalid, and int32 (L): z = Increment value + Offset.
  const std::vector<int> values = {-32768, -1000, -1, 0, 1, 2, 3, 77, 1000, 12345, 32767, 5};
  const double increment = 1e-9, offset = 2e-7;
  std::string data, valid(2, '\0');
  for (std::size_t k = 0; k < values.size(); ++k) {
    data += bytes_of(static_cast<std::int16_t>(values[k]));
    if (k != 3 && k != 9) valid[k / 8] = static_cast<char>(valid[k / 8] | (1 << (k % 8)));
  }
  Spec s;
  s.type = "I";
  s.z_increment_offset = "<Increment>1e-9</Increment><Offset>2e-7</Offset>";
  s.data = data_link(data, valid);
  const auto path = temp("int16.x3p");
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}, {"bindata/valid.bin", valid}});
  const surface::HeightGrid g = io::read_x3p(path);
  ASSERT_EQ(g.nx, 4);
  ASSERT_EQ(g.ny, 3);
  EXPECT_EQ(g.dx, 1e-6);
  EXPECT_EQ(g.dy, 2e-6);
  for (std::size_t k = 0; k < values.size(); ++k) {
    EXPECT_EQ(g.valid[k] != 0, k != 3 && k != 9) << k;
    if (g.valid[k]) {
      EXPECT_EQ(g.z[k], values[k] * increment + offset) << k;  // the same operations: exact
    }
  }

  std::string data32;
  const std::vector<std::int32_t> big = {-2147483647 - 1, -5, 0, 9, 2147483647, 100, 200, 300, 400, 500, 600, 700};
  for (std::int32_t v : big) data32 += bytes_of(v);
  s.type = "L";
  s.z_increment_offset = "<Increment>1e-10</Increment><Offset>-1e-6</Offset>";
  s.data = data_link(data32);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data32}});
  const surface::HeightGrid l = io::read_x3p(path);
  for (std::size_t k = 0; k < big.size(); ++k) {
    EXPECT_TRUE(l.valid[k]);
    EXPECT_EQ(l.z[k], big[k] * 1e-10 + -1e-6) << k;
  }
  std::filesystem::remove(path);
}

TEST(X3p, FloatHeightsInlineDataAndProfiles) {
  // float32 (F): NaN is an invalid point, the Offset is added, the Increment (a resolution) is not applied.
  std::string data;
  std::vector<float> values;
  for (int k = 0; k < 12; ++k) values.push_back(k == 5 ? std::numeric_limits<float>::quiet_NaN() : 1e-7f * k);
  for (float v : values) data += bytes_of(v);
  Spec s;
  s.type = "F";
  s.z_increment_offset = "<Increment>1e-9</Increment><Offset>1e-6</Offset>";
  s.data = data_link(data);
  const auto path = temp("float.x3p");
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
  const surface::HeightGrid f = io::read_x3p(path);
  for (std::size_t k = 0; k < values.size(); ++k) {
    EXPECT_EQ(f.valid[k] != 0, k != 5);
    if (f.valid[k]) {
      EXPECT_EQ(f.z[k], static_cast<double>(values[k]) + 1e-6) << k;
    }
  }

  // The heights inline (DataList): an empty Datum is invalid.
  s.type = "D";
  s.z_increment_offset = "<Increment>1</Increment>";
  s.data = "<DataList>";
  for (int k = 0; k < 12; ++k) s.data += k == 7 ? "<Datum/>" : fmt::format("<Datum>{}</Datum>", 1e-8 * k);
  s.data += "</DataList>";
  write_zip(path, {{"main.xml", main_xml(s)}});
  const surface::HeightGrid list = io::read_x3p(path);
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(list.valid[k] != 0, k != 7);
    if (k != 7) {
      EXPECT_EQ(list.z[k], 1e-8 * k);  // shortest round-trip text: exact
    }
  }

  // A profile (PRF) is one row at the x spacing.
  std::string profile;
  for (int k = 0; k < 12; ++k) profile += bytes_of(1e-7 * k);
  s = Spec{};
  s.feature = "PRF";
  s.size_x = "12", s.size_y = "1";
  s.data = data_link(profile);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", profile}});
  const surface::HeightGrid p = io::read_x3p(path);
  EXPECT_EQ(p.nx, 12);
  EXPECT_EQ(p.ny, 1);
  EXPECT_EQ(p.dy, p.dx);
  std::filesystem::remove(path);
}

TEST(X3p, RefusalsNameTheFileAndTheField) {
  const auto path = temp("bad.x3p");
  auto read = [&] { io::read_x3p(path); };
  std::string data;
  for (int k = 0; k < 12; ++k) data += bytes_of(1e-7 * k);

  write_zip(path, {{"bindata/data.bin", data}});
  expect_refusal(read, path, "main.xml", "no main.xml");

  Spec s;
  s.size_y = "4";  // 16 points, data for 12
  s.data = data_link(data);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
  expect_refusal(read, path, "Record3/MatrixDimension", "holds 96 bytes; 16 points");

  s = Spec{};
  s.data = data_link(data);
  std::string changed = data;
  changed[20] ^= 1;
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", changed}});
  expect_refusal(read, path, "Record3/DataLink/MD5ChecksumPointData", "the MD5 of bindata/data.bin is");

  s.feature = "PCL";
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
  expect_refusal(read, path, "Record1/FeatureType", "point cloud");

  s = Spec{};
  s.x_axis = "A";
  s.data = data_link(data);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
  expect_refusal(read, path, "Record1/Axes/CX/AxisType", "incremental");

  s = Spec{};
  s.size_z = "2";
  s.data = data_link(data);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
  expect_refusal(read, path, "Record3/MatrixDimension/SizeZ", "SizeZ must be 1");

  s = Spec{};
  s.dx = "0";
  s.data = data_link(data);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
  expect_refusal(read, path, "Record1/Axes/CX/Increment", "spacing must be positive");

  s = Spec{};
  s.type = "Q";
  s.data = data_link(data);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
  expect_refusal(read, path, "Record1/Axes/CZ/DataType", "DataType must be");

  s = Spec{};
  s.data = data_link(data, std::string(1, '\xff'));  // 12 points need 2 bytes
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}, {"bindata/valid.bin", "\xff"}});
  expect_refusal(read, path, "Record3/DataLink/ValidPointsLink", "a bit a point");

  std::string far = data;
  const std::string two_metres = bytes_of(2.0);
  far.replace(8 * 5, 8, two_metres);
  s = Spec{};
  s.data = data_link(far);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", far}});
  expect_refusal(read, path, "bindata/data.bin[1][1]", "beyond");

  write_zip(path, {{"main.xml", "<ISO5436_2><Record1>"}});
  expect_refusal(read, path, "main.xml", "not well-formed XML");

  write_zip(path, {{"main.xml", std::string(io::kMaxX3pMainXmlBytes + 1, ' ')}});
  expect_refusal(read, path, "main.xml", "16 MiB");

  { std::ofstream(path, std::ios::trunc) << "not a zip"; }
  expect_refusal(read, path, "", "not a zip archive");
  std::filesystem::remove(path);
}

TEST(X3p, AbsurdSizesAreRefusedBeforeAllocating) {
  // 2^40 points declared over 96 bytes of data: refused on the declared size, nothing allocated.
  std::string data;
  for (int k = 0; k < 12; ++k) data += bytes_of(1e-7 * k);
  const auto path = temp("huge.x3p");
  for (const auto& [x, y] : {std::pair{"1048576", "1048576"}, std::pair{"1099511627776", "1"},
                             std::pair{"4294967296", "4294967296"}, std::pair{"18446744073709551615", "2"}}) {
    Spec s;
    s.size_x = x, s.size_y = y;
    s.data = data_link(data);
    write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
    expect_refusal([&] { io::read_x3p(path); }, path, "Record3/MatrixDimension", "more than 33554432 points");
  }
  // Beyond an unsigned 64-bit number: not a count.
  Spec s;
  s.size_x = "18446744073709551616";
  s.data = data_link(data);
  write_zip(path, {{"main.xml", main_xml(s)}, {"bindata/data.bin", data}});
  expect_refusal([&] { io::read_x3p(path); }, path, "Record3/MatrixDimension/SizeX", "not a whole number");
  std::filesystem::remove(path);
}
