// ISO 25178-72 (X3P, the openGPS ISO5436_2 XML container): a zip holding main.xml (what the data
// are), bindata/data.bin (the heights, little-endian, x fastest then y), optionally
// bindata/valid.bin (a bit a point, least significant bit first, 1 = valid) and md5checksum.hex.
// Lengths are metres by the standard: no unit is assumed or asked for.
//
// Read: FeatureType SUR (and PRF, a one-row surface); CX, CY incremental (AxisType I: Increment
// the spacing, Offset ignored: a grid has no origin); CZ of DataType D (float64), F (float32),
// L (int32) or I (int16): an integer height is Increment x value + Offset, a float one value +
// Offset (the Increment of a float axis is its resolution, as openGPS reads it); invalid points NaN
// (float types) or a 0 bit in valid.bin (any type); the data in bindata (DataLink) or inline in
// main.xml (DataList, one <Datum> a point, empty: invalid). The MD5 of data.bin and valid.bin is
// checked when main.xml gives it; md5checksum.hex (main.xml's MD5) is not checked (writers differ
// on what they hash). Rotation and vendor-specific files are ignored.
// Refused, each an InputError naming the file and the field: FeatureType PCL, absolute x or y axes
// (AxisType A: a point list, not a grid), ListDimension, SizeZ other than 1, more than
// surface::kMaxGridPoints points, a data.bin or valid.bin whose size is not SizeX x SizeY of its
// type (checked before allocating), a main.xml beyond kMaxX3pMainXmlBytes, an MD5 mismatch, a zip
// that libzip finds inconsistent, heights beyond surface::kMaxHeight, fewer than 9 valid points.
//
// Written: Record1 (Revision ISO5436 - 2000, SUR, CX/CY incremental at dx/dy, CZ absolute float64),
// Record2 (date, Instrument geartrib and its version, ProbingSystem Software), Record3
// (MatrixDimension, DataLink to bindata/data.bin with its MD5), Record4 (md5checksum.hex holding
// main.xml's MD5): missing points as NaN. data.bin is stored (heights hardly compress; storing is
// fast), main.xml deflated. Atomically (io::write_atomically).
//
// libzip is loaded (dlopen) when an X3P is first read or written, not at start-up: without it,
// both throw an InputError naming the file and the package to install.
#pragma once

#include "surface/height_grid.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace geartrib::io {

// main.xml beyond this is refused before it is read (a real one is a few kilobytes; a DataList of
// a large grid is refused here, not parsed into millions of nodes).
inline constexpr std::uint64_t kMaxX3pMainXmlBytes = std::uint64_t{16} << 20;  // 16 MiB

surface::HeightGrid read_x3p(const std::filesystem::path& file);
// Throws std::invalid_argument for an invalid grid (HeightGrid::validate), std::runtime_error when
// the file cannot be written (nothing is left at `file` then).
void write_x3p(const std::filesystem::path& file, const surface::HeightGrid& g);
// The archive written to `file` as it is (an io::OutputSet's temporary; write_x3p's own writer):
// libzip writes into `file` alone, through a source of geartrib's, never into a temporary of its
// own beside it (which a signal would leave behind).
void write_x3p_archive(const std::filesystem::path& file, const surface::HeightGrid& g);

// MD5 (RFC 1321), for the checksums X3P carries; not for security.
class Md5 {
 public:
  void update(std::string_view bytes);
  std::array<std::uint8_t, 16> digest();  // finishes: call once
 private:
  void block(const unsigned char* p);
  std::uint32_t state_[4] = {0x67452301u, 0xefcdab89u, 0x98badcfeu, 0x10325476u};
  std::uint64_t length_ = 0;  // bytes so far
  unsigned char buffer_[64] = {};
  std::size_t buffered_ = 0;
};
// The MD5 of `bytes` as 32 lowercase hex digits.
std::string md5_hex(std::string_view bytes);

}  // namespace geartrib::io
