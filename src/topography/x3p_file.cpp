#include "topography/x3p_file.hpp"

#include "config/input_error.hpp"
#include "config/text_lines.hpp"
#include "output/table_writer.hpp"
#include "topography/topography_files.hpp"

#include <fmt/format.h>
#include <zip.h>
#include <pugixml.hpp>

#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <ctime>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace geartrib::io {

// ---- MD5 (RFC 1321, section 3) ----

namespace {

constexpr int kMd5Shift[64] = {7,  12, 17, 22, 7,  12, 17, 22, 7,  12, 17, 22, 7,  12, 17, 22, 5,  9,  14, 20, 5,  9,
                               14, 20, 5,  9,  14, 20, 5,  9,  14, 20, 4,  11, 16, 23, 4,  11, 16, 23, 4,  11, 16, 23,
                               4,  11, 16, 23, 6,  10, 15, 21, 6,  10, 15, 21, 6,  10, 15, 21, 6,  10, 15, 21};

// T[i] = floor(2^32 |sin(i + 1)|) (RFC 1321, 3.4). A double's sine is accurate enough for all 64
// (the RFC's test vectors in tests/test_x3p.cpp check the whole digest).
const std::array<std::uint32_t, 64>& md5_sines() {
  static const std::array<std::uint32_t, 64> t = [] {
    std::array<std::uint32_t, 64> v{};
    for (int i = 0; i < 64; ++i)
      v[i] = static_cast<std::uint32_t>(std::floor(std::abs(std::sin(i + 1.0)) * 4294967296.0));
    return v;
  }();
  return t;
}

// Little-endian unsigned integers, whatever the machine's byte order.
template <class U>
U load_le(const unsigned char* p) {
  U v = 0;
  for (std::size_t b = 0; b < sizeof(U); ++b) v |= static_cast<U>(static_cast<U>(p[b]) << (8 * b));
  return v;
}
template <class U>
void store_le(U v, unsigned char* p) {
  for (std::size_t b = 0; b < sizeof(U); ++b) p[b] = static_cast<unsigned char>(v >> (8 * b));
}

}  // namespace

void Md5::block(const unsigned char* p) {
  const auto& t = md5_sines();
  std::uint32_t m[16];
  for (std::size_t i = 0; i < 16; ++i) m[i] = load_le<std::uint32_t>(p + 4 * i);
  std::uint32_t a = state_[0], b = state_[1], c = state_[2], d = state_[3];
  for (int i = 0; i < 64; ++i) {
    std::uint32_t f = 0;
    int g = 0;
    if (i < 16) {
      f = (b & c) | (~b & d), g = i;
    } else if (i < 32) {
      f = (d & b) | (~d & c), g = (5 * i + 1) % 16;
    } else if (i < 48) {
      f = b ^ c ^ d, g = (3 * i + 5) % 16;
    } else {
      f = c ^ (b | ~d), g = (7 * i) % 16;
    }
    f += a + t[i] + m[g];
    a = d, d = c, c = b;
    b += std::rotl(f, kMd5Shift[i]);
  }
  state_[0] += a, state_[1] += b, state_[2] += c, state_[3] += d;
}

void Md5::update(std::string_view bytes) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t n = bytes.size();
  length_ += n;
  if (buffered_ > 0) {
    const std::size_t take = std::min(n, sizeof buffer_ - buffered_);
    if (take > 0) std::memcpy(buffer_ + buffered_, p, take);
    buffered_ += take, p += take, n -= take;
    if (buffered_ < sizeof buffer_) return;
    block(buffer_);
    buffered_ = 0;
  }
  for (; n >= 64; p += 64, n -= 64) block(p);
  if (n > 0) std::memcpy(buffer_, p, n);
  buffered_ = n;
}

std::array<std::uint8_t, 16> Md5::digest() {
  // Padding: a 1 bit, zeros to 56 bytes modulo 64, the message length in bits (64 bits, LE).
  const std::uint64_t bits = length_ * 8;
  static const char pad[64] = {static_cast<char>(0x80)};
  update(std::string_view(pad, buffered_ < 56 ? 56 - buffered_ : 120 - buffered_));
  unsigned char length[8];
  store_le(bits, length);
  update(std::string_view(reinterpret_cast<const char*>(length), 8));
  std::array<std::uint8_t, 16> out{};
  for (std::size_t i = 0; i < 4; ++i) store_le(state_[i], out.data() + 4 * i);
  return out;
}

std::string md5_hex(std::string_view bytes) {
  Md5 m;
  m.update(bytes);
  std::string hex;
  for (const std::uint8_t b : m.digest()) hex += fmt::format("{:02x}", b);
  return hex;
}

// ---- reading ----

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kChunkBytes = std::size_t{1} << 20;

// libzip is loaded when an X3P is first read or written, not linked: linked, it and the libcrypto,
// libbz2 and libz it needs would be loaded at every start of the tool, which mostly never reads an
// X3P (docs/reference/performance.md, "Start-up"). <zip.h> gives the types and the functions'
// declarations; GEARTRIB_LIBZIP_SONAME (CMakeLists.txt) the library found at configure time.
#ifndef GEARTRIB_LIBZIP_SONAME
#error "GEARTRIB_LIBZIP_SONAME (libzip's SONAME, such as \"libzip.so.4\") is set by CMakeLists.txt"
#endif

// The libzip functions used here, resolved once; `error` says why they could not be (then they
// are null).
struct Libzip {
  decltype(&::zip_close) close = nullptr;
  decltype(&::zip_discard) discard = nullptr;
  decltype(&::zip_error_fini) error_fini = nullptr;
  decltype(&::zip_error_init_with_code) error_init_with_code = nullptr;
  decltype(&::zip_error_strerror) error_strerror = nullptr;
  decltype(&::zip_fclose) fclose = nullptr;
  decltype(&::zip_file_add) file_add = nullptr;
  decltype(&::zip_file_strerror) file_strerror = nullptr;
  decltype(&::zip_fopen_index) fopen_index = nullptr;
  decltype(&::zip_fread) fread = nullptr;
  decltype(&::zip_name_locate) name_locate = nullptr;
  decltype(&::zip_open) open = nullptr;
  decltype(&::zip_open_from_source) open_from_source = nullptr;
  decltype(&::zip_set_file_compression) set_file_compression = nullptr;
  decltype(&::zip_source_buffer) source_buffer = nullptr;
  decltype(&::zip_source_free) source_free = nullptr;
  decltype(&::zip_source_function_create) source_function_create = nullptr;
  decltype(&::zip_stat_index) stat_index = nullptr;
  decltype(&::zip_stat_init) stat_init = nullptr;
  decltype(&::zip_strerror) strerror = nullptr;
  std::string error;
};

// Loaded on the first call, by one thread (a function-local static); kept for the process's life.
const Libzip& libzip_loaded() {
  static const Libzip lib = [] {
    Libzip z;
    void* handle = dlopen(GEARTRIB_LIBZIP_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      z.error = why != nullptr ? why : "cannot load " GEARTRIB_LIBZIP_SONAME;
      return z;
    }
    const auto resolve = [&]<class F>(F& function, const char* name) {
      if (!z.error.empty()) return;
      function = reinterpret_cast<F>(dlsym(handle, name));
      if (function == nullptr)
        z.error = fmt::format("{} has no function {} (libzip too old?)", GEARTRIB_LIBZIP_SONAME, name);
    };
    resolve(z.close, "zip_close");
    resolve(z.discard, "zip_discard");
    resolve(z.error_fini, "zip_error_fini");
    resolve(z.error_init_with_code, "zip_error_init_with_code");
    resolve(z.error_strerror, "zip_error_strerror");
    resolve(z.fclose, "zip_fclose");
    resolve(z.file_add, "zip_file_add");
    resolve(z.file_strerror, "zip_file_strerror");
    resolve(z.fopen_index, "zip_fopen_index");
    resolve(z.fread, "zip_fread");
    resolve(z.name_locate, "zip_name_locate");
    resolve(z.open, "zip_open");
    resolve(z.open_from_source, "zip_open_from_source");
    resolve(z.set_file_compression, "zip_set_file_compression");
    resolve(z.source_buffer, "zip_source_buffer");
    resolve(z.source_free, "zip_source_free");
    resolve(z.source_function_create, "zip_source_function_create");
    resolve(z.stat_index, "zip_stat_index");
    resolve(z.stat_init, "zip_stat_init");
    resolve(z.strerror, "zip_strerror");
    if (!z.error.empty()) {
      z = Libzip{.error = z.error};
      dlclose(handle);
    }
    return z;
  }();
  return lib;
}

// libzip's functions, or an InputError naming `file` when libzip cannot be loaded.
const Libzip& libzip(const std::string& file, const char* verb) {
  const Libzip& z = libzip_loaded();
  if (!z.error.empty()) {
    // Debian's package of a library is its SONAME without ".so.": libzip.so.4 in libzip4.
    std::string package = GEARTRIB_LIBZIP_SONAME;
    if (const auto so = package.find(".so."); so != std::string::npos) package.erase(so, 4);
    throw InputError(file, 0, "", "",
                     fmt::format("libzip ({}, the {} package) is needed to {} X3P files: {}", GEARTRIB_LIBZIP_SONAME,
                                 package, verb, z.error));
  }
  return z;
}

// Deleters, called only for what libzip made (so libzip is loaded).
struct ZipDiscard {
  void operator()(zip_t* z) const { libzip_loaded().discard(z); }
};
using ZipArchive = std::unique_ptr<zip_t, ZipDiscard>;
struct ZipFileClose {
  void operator()(zip_file_t* f) const { libzip_loaded().fclose(f); }
};

std::string zip_error_text(const Libzip& z, int code) {
  zip_error_t e;
  z.error_init_with_code(&e, code);
  std::string s = z.error_strerror(&e);
  z.error_fini(&e);
  return s;
}

// An element of main.xml and its path for messages ("Record3/MatrixDimension/SizeX").
struct Field {
  pugi::xml_node node;
  std::string path;
};

// Element names compared without a namespace prefix: writers qualify them differently.
std::string_view local_name(const char* name) {
  const std::string_view n(name);
  const auto colon = n.find(':');
  return colon == std::string_view::npos ? n : n.substr(colon + 1);
}

std::optional<Field> find(const Field& parent, std::string_view name) {
  for (pugi::xml_node c : parent.node.children())
    if (c.type() == pugi::node_element && local_name(c.name()) == name)
      return Field{c, parent.path.empty() ? std::string(name) : parent.path + "/" + std::string(name)};
  return std::nullopt;
}

std::string text(const Field& f) { return trim(f.node.child_value()); }

// The heights' type: DataType of the CZ axis.
struct ZType {
  char code = 'D';
  std::size_t bytes = 8;
  bool integer = false;
};
std::optional<ZType> z_type(const std::string& code) {
  if (code == "D") return ZType{'D', 8, false};
  if (code == "F") return ZType{'F', 4, false};
  if (code == "L") return ZType{'L', 4, true};
  if (code == "I") return ZType{'I', 2, true};
  return std::nullopt;
}
double raw_value(const ZType& t, const unsigned char* p) {
  switch (t.code) {
    case 'D':
      return std::bit_cast<double>(load_le<std::uint64_t>(p));
    case 'F':
      return std::bit_cast<float>(load_le<std::uint32_t>(p));
    case 'L':
      return static_cast<std::int32_t>(load_le<std::uint32_t>(p));
    default:
      return static_cast<std::int16_t>(load_le<std::uint16_t>(p));
  }
}

bool is_md5(const std::string& s) {
  return s.size() == 32 && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
}
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

class X3pReader {
 public:
  explicit X3pReader(const std::filesystem::path& path) : file_(path.string()) {
    if (const std::string why = data_file_problem(path, kNoSizeLimit); !why.empty()) fail("", "", why);
    lz_ = &libzip(file_, "read");
    int error = 0;
    zip_.reset(lz_->open(file_.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &error));
    if (!zip_) {
      if (error == ZIP_ER_NOZIP) fail("", "", "not an X3P file: not a zip archive");
      fail("", "", "cannot open as an X3P file (a zip archive): " + zip_error_text(*lz_, error));
    }
  }

  surface::HeightGrid read() {
    const Field root = document();
    const Field r1 = need(root, "Record1");
    const Field feature_field = need(r1, "FeatureType");
    const std::string feature = text(feature_field);
    if (feature == "PCL")
      fail(feature_field.path, feature,
           "a point cloud (FeatureType PCL) is not read: export the surface as a grid (FeatureType SUR)");
    if (feature != "SUR" && feature != "PRF")
      fail(feature_field.path, feature, "unknown feature type (SUR surface, PRF profile, PCL point cloud)");
    const bool profile = feature == "PRF";

    const Field axes = need(r1, "Axes");
    const double dx = lateral_spacing(need(axes, "CX"));
    const double dy = profile ? dx : lateral_spacing(need(axes, "CY"));  // a profile's y has no spacing
    const Field cz = need(axes, "CZ");
    const Field type_field = need(cz, "DataType");
    const auto type = z_type(text(type_field));
    if (!type)
      fail(type_field.path, text(type_field), "DataType must be D (float64), F (float32), L (int32) or I (int16)");
    double z_increment = 1.0, z_offset = 0.0;
    if (const auto f = find(cz, "Increment")) z_increment = number(*f);
    if (const auto f = find(cz, "Offset")) z_offset = number(*f);
    if (type->integer && z_increment == 0.0)
      fail(cz.path + "/Increment", "0", "the Increment of an integer z axis scales its values: it cannot be 0");
    // A float height is the value plus the offset; an integer one the value in increments. The
    // offset is added only when there is one: -0.0 stays -0.0, every height bit for bit.
    const auto height = [&](double raw) {
      const double z = type->integer ? raw * z_increment : raw;
      return z_offset == 0.0 ? z : z + z_offset;
    };

    const Field r3 = need(root, "Record3");
    if (!find(r3, "MatrixDimension") && find(r3, "ListDimension"))
      fail(r3.path + "/ListDimension", "",
           "a point list (ListDimension) is not read: export the surface as a matrix (MatrixDimension)");
    const Field md = need(r3, "MatrixDimension");
    const Field sx = need(md, "SizeX"), sy = need(md, "SizeY"), sz = need(md, "SizeZ");
    const std::uint64_t nx = count(sx), ny = count(sy), nz = count(sz);
    if (nz != 1) fail(sz.path, text(sz), "SizeZ must be 1: one height a point (layered data is not read)");
    if (nx < 2) fail(sx.path, text(sx), "a surface needs at least 2 points along x");
    if (ny < 1) fail(sy.path, text(sy), "a surface needs at least 1 row");
    if (profile && ny != 1) fail(sy.path, text(sy), "a profile (FeatureType PRF) has SizeY 1");
    const std::string shape = fmt::format("SizeX x SizeY = {} x {}", nx, ny);
    // The declared size against the grid's limit before anything is allocated.
    if (ny > surface::kMaxGridPoints / nx)
      fail(md.path, shape, fmt::format("more than {} points (the limit of a grid)", surface::kMaxGridPoints));
    const std::size_t points = static_cast<std::size_t>(nx * ny);

    surface::HeightGrid g;
    std::string where;  // the data's name for messages on heights
    if (const auto link = find(r3, "DataLink")) {
      const Field pl = need(*link, "PointDataLink");
      const std::string name = text(pl);
      const Entry data = entry_named(pl, name);
      const std::uint64_t data_bytes = static_cast<std::uint64_t>(points) * type->bytes;
      if (data.size != data_bytes)
        fail(md.path, shape,
             fmt::format("{} holds {} bytes; {} points of DataType {} are {} bytes", name, data.size, points,
                         type->code, data_bytes));
      // valid.bin (a bit a point, LSB first, 1 = valid): read and checked before the heights, so
      // that an invalid point's value is never judged.
      std::string valid_bits;
      if (const auto vl = find(*link, "ValidPointsLink")) {
        const std::string valid_name = text(*vl);
        const Entry valid = entry_named(*vl, valid_name);
        const std::uint64_t valid_bytes = (static_cast<std::uint64_t>(points) + 7) / 8;
        if (valid.size != valid_bytes)
          fail(vl->path, valid_name,
               fmt::format("{} holds {} bytes; {} points need {} (a bit a point)", valid_name, valid.size, points,
                           valid_bytes));
        Md5 md5;
        stream(valid, vl->path, [&](std::string_view s) {
          md5.update(s);
          valid_bits.append(s);
        });
        check_md5(find(*link, "MD5ChecksumValidPoints"), valid_name, md5);
      }
      g = surface::make_grid(static_cast<int>(nx), static_cast<int>(ny), dx, dy);
      std::size_t k = 0;
      std::string tail;  // a value split across two chunks
      Md5 md5;
      stream(data, pl.path, [&](std::string_view s) {
        md5.update(s);
        tail.append(s);
        const std::size_t whole = tail.size() / type->bytes;
        const auto* p = reinterpret_cast<const unsigned char*>(tail.data());
        for (std::size_t n = 0; n < whole; ++n, ++k) {
          const double raw = raw_value(*type, p + n * type->bytes);
          const bool bit = valid_bits.empty() || ((static_cast<unsigned char>(valid_bits[k / 8]) >> (k % 8)) & 1u);
          const bool ok = bit && !std::isnan(raw);
          g.valid[k] = ok;
          g.z[k] = ok ? height(raw) : 0.0;
        }
        tail.erase(0, whole * type->bytes);
      });
      check_md5(find(*link, "MD5ChecksumPointData"), name, md5);
      where = name;
    } else if (const auto list = find(r3, "DataList")) {
      // Inline values: one <Datum> a point (an empty one is invalid), counted before allocating.
      std::size_t n = 0;
      for (pugi::xml_node c : list->node.children())
        if (c.type() == pugi::node_element && local_name(c.name()) == "Datum") ++n;
      if (n != points)
        fail(md.path, shape, fmt::format("the DataList holds {} Datum elements; {} points expected", n, points));
      g = surface::make_grid(static_cast<int>(nx), static_cast<int>(ny), dx, dy);
      std::size_t k = 0;
      for (pugi::xml_node c : list->node.children()) {
        if (c.type() != pugi::node_element || local_name(c.name()) != "Datum") continue;
        const Field datum{c, fmt::format("{}/Datum[{}]", list->path, k)};
        const std::string t = text(datum);
        double raw = kNaN;
        if (!t.empty() && !parse_number(t, raw))
          fail(datum.path, t, "not a number (lists of x;y;z of absolute axes are not read)");
        const bool ok = !std::isnan(raw);
        g.valid[k] = ok;
        g.z[k] = ok ? height(raw) : 0.0;
        ++k;
      }
      where = list->path;
    } else {
      fail(r3.path, "", "neither DataLink nor DataList: the file holds no heights");
    }

    for (std::size_t k = 0; k < g.size(); ++k)
      if (g.valid[k] && !(std::abs(g.z[k]) <= surface::kMaxHeight))
        check_grid_height(file_, 0, fmt::format("{}[{}][{}]", where, k / g.nx, k % g.nx), fmt::format("{}", g.z[k]),
                          g.z[k], "an X3P holds metres (ISO 25178-72); NaN or valid.bin alone marks an invalid point");
    check_valid_points(g, file_, 0);
    return g;
  }

 private:
  struct Entry {
    zip_uint64_t index = 0;
    std::uint64_t size = 0;
    std::string name;
  };

  std::string file_;
  const Libzip* lz_ = nullptr;
  ZipArchive zip_;

  [[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& rule) const {
    throw InputError(file_, 0, key, value, rule);
  }

  Field need(const Field& parent, std::string_view name) const {
    auto f = find(parent, name);
    if (!f)
      fail(parent.path.empty() ? std::string(name) : parent.path + "/" + std::string(name), "", "missing in main.xml");
    return *f;
  }

  static bool parse_number(std::string t, double& v) {
    if (!t.empty() && t[0] == '+') t.erase(0, 1);  // xsd:double allows a sign from_chars does not
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    return ec == std::errc{} && end == t.data() + t.size();
  }
  double number(const Field& f) const {
    const std::string t = text(f);
    double v = 0.0;
    if (!parse_number(t, v)) fail(f.path, t, "not a number");
    if (!std::isfinite(v)) fail(f.path, t, "must be finite");
    return v;
  }
  std::uint64_t count(const Field& f) const {
    std::string t = text(f);
    if (!t.empty() && t[0] == '+') t.erase(0, 1);
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc{} || end != t.data() + t.size()) fail(f.path, text(f), "not a whole number of points");
    return v;
  }

  // CX or CY: incremental, its Increment the spacing [m].
  double lateral_spacing(const Field& axis) const {
    const Field type = need(axis, "AxisType");
    const std::string t = text(type);
    if (t == "A")
      fail(type.path, t,
           "absolute x or y coordinates (a point list) are not read: export the surface with incremental axes "
           "(AxisType I)");
    if (t != "I") fail(type.path, t, "AxisType must be I (incremental) or A (absolute)");
    const Field increment = need(axis, "Increment");
    const double h = number(increment);
    check_grid_spacing(file_, 0, increment.path, text(increment), h);
    return h;
  }

  std::optional<Entry> entry(std::string name) const {
    std::replace(name.begin(), name.end(), '\\', '/');
    const zip_int64_t index = lz_->name_locate(zip_.get(), name.c_str(), ZIP_FL_NOCASE);
    if (index < 0) return std::nullopt;
    zip_stat_t st;
    lz_->stat_init(&st);
    if (lz_->stat_index(zip_.get(), static_cast<zip_uint64_t>(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
      fail(name, "", std::string("cannot read the archive's entry: ") + lz_->strerror(zip_.get()));
    return Entry{static_cast<zip_uint64_t>(index), st.size, name};
  }
  Entry entry_named(const Field& link, const std::string& name) const {
    if (name.empty()) fail(link.path, "", "empty: names no file of the archive");
    const auto e = entry(name);
    if (!e) fail(link.path, name, "not in the archive");
    return *e;
  }

  // The entry's bytes in chunks; exactly its stated size, its CRC checked (libzip, at the end).
  void stream(const Entry& e, const std::string& key, const std::function<void(std::string_view)>& sink) const {
    std::unique_ptr<zip_file_t, ZipFileClose> f(lz_->fopen_index(zip_.get(), e.index, 0));
    if (!f) fail(key, e.name, std::string("cannot read it from the archive: ") + lz_->strerror(zip_.get()));
    std::vector<char> buffer(static_cast<std::size_t>(std::min<std::uint64_t>(e.size + 1, kChunkBytes)));
    std::uint64_t total = 0;
    for (;;) {
      const zip_int64_t n = lz_->fread(f.get(), buffer.data(), buffer.size());
      if (n < 0) fail(key, e.name, std::string("corrupt in the archive: ") + lz_->file_strerror(f.get()));
      if (n == 0) break;
      total += static_cast<std::uint64_t>(n);
      if (total > e.size) fail(key, e.name, fmt::format("holds more than the {} bytes the archive states", e.size));
      sink(std::string_view(buffer.data(), static_cast<std::size_t>(n)));
    }
    if (total != e.size)
      fail(key, e.name, fmt::format("holds {} bytes, fewer than the {} the archive states", total, e.size));
  }

  // The MD5 main.xml gives for an entry, when it gives one, against the entry's.
  void check_md5(const std::optional<Field>& given, const std::string& name, Md5& md5) const {
    if (!given) return;
    const std::string stated = text(*given);
    if (stated.empty()) return;
    if (!is_md5(stated)) fail(given->path, stated, "not an MD5 digest (32 hex digits)");
    std::string actual;
    for (const std::uint8_t b : md5.digest()) actual += fmt::format("{:02x}", b);
    if (lower(stated) != actual)
      fail(given->path, stated,
           fmt::format("the MD5 of {} is {}: the data are corrupt or were changed after main.xml was written", name,
                       actual));
  }

  // main.xml, bounded, parsed (pugixml reads no DTD and expands no external entity).
  Field document() {
    const auto main = entry("main.xml");
    if (!main) fail("main.xml", "", "no main.xml in the archive: not an X3P file (ISO 25178-72)");
    if (main->size > kMaxX3pMainXmlBytes)
      fail("main.xml", fmt::format("{} bytes", main->size),
           fmt::format("larger than the {} MiB an X3P's main.xml may have", kMaxX3pMainXmlBytes >> 20));
    std::string xml;
    xml.reserve(static_cast<std::size_t>(main->size));
    stream(*main, "main.xml", [&](std::string_view s) { xml.append(s); });
    const pugi::xml_parse_result parsed = doc_.load_buffer(xml.data(), xml.size());
    if (!parsed)
      fail("main.xml", "", fmt::format("not well-formed XML at byte {}: {}", parsed.offset, parsed.description()));
    const auto root = find(Field{doc_, ""}, "ISO5436_2");
    if (!root) fail("main.xml", "", "its root element is not ISO5436_2: not an X3P main.xml");
    return Field{root->node, ""};
  }
  pugi::xml_document doc_;
};

// ---- writing ----

// The archive's bytes go through this libzip source into geartrib's own temporary (an
// io::OutputSet's, which a signal removes): zip_close() on a file opened by name would write a
// mkstemp file of its own beside it (NAME.XXXXXX), which a signal would leave behind. A new
// archive only: it reads nothing back (STAT says there is no archive yet).
class ZipSink {
 public:
  explicit ZipSink(std::filesystem::path path) : path_(std::move(path)) {}
  ZipSink(const ZipSink&) = delete;
  ZipSink& operator=(const ZipSink&) = delete;
  ~ZipSink() {
    if (fd_ >= 0) ::close(fd_);
  }
  static zip_int64_t callback(void* state, void* data, zip_uint64_t length, zip_source_cmd_t command) {
    return static_cast<ZipSink*>(state)->on(data, length, command);
  }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  int zip_error_ = ZIP_ER_OK, system_error_ = 0;

  zip_int64_t fail(int zip_error, int system_error) {
    zip_error_ = zip_error;
    system_error_ = system_error;
    return -1;
  }
  zip_int64_t on(void* data, zip_uint64_t length, zip_source_cmd_t command) {
    switch (command) {
      case ZIP_SOURCE_SUPPORTS:
        return ZIP_SOURCE_SUPPORTS_WRITABLE;
      case ZIP_SOURCE_STAT:
        return fail(ZIP_ER_READ, ENOENT);  // no archive yet: libzip starts a new one
      case ZIP_SOURCE_ERROR: {
        if (length < 2 * sizeof(int)) return -1;
        const int codes[2] = {zip_error_, system_error_};
        std::memcpy(data, codes, sizeof codes);
        return sizeof codes;
      }
      case ZIP_SOURCE_BEGIN_WRITE:
        fd_ = ::open(path_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        return fd_ < 0 ? fail(ZIP_ER_OPEN, errno) : 0;
      case ZIP_SOURCE_WRITE: {
        if (!write_all(fd_, static_cast<const char*>(data), length)) return fail(ZIP_ER_WRITE, errno);
        return static_cast<zip_int64_t>(length);
      }
      case ZIP_SOURCE_SEEK_WRITE: {
        if (length < sizeof(zip_source_args_seek_t)) return fail(ZIP_ER_INVAL, 0);
        const auto* seek = static_cast<const zip_source_args_seek_t*>(data);
        return ::lseek(fd_, seek->offset, seek->whence) < 0 ? fail(ZIP_ER_SEEK, errno) : 0;
      }
      case ZIP_SOURCE_TELL_WRITE: {
        const off_t at = ::lseek(fd_, 0, SEEK_CUR);
        return at < 0 ? fail(ZIP_ER_TELL, errno) : static_cast<zip_int64_t>(at);
      }
      case ZIP_SOURCE_COMMIT_WRITE: {
        const int fd = std::exchange(fd_, -1);
        return ::close(fd) != 0 ? fail(ZIP_ER_WRITE, errno) : 0;
      }
      case ZIP_SOURCE_ROLLBACK_WRITE:  // the OutputSet removes the temporary
        if (fd_ >= 0) ::close(std::exchange(fd_, -1));
        return 0;
      case ZIP_SOURCE_REMOVE:  // an archive of no entries: the temporary stays empty
      case ZIP_SOURCE_FREE:
        return 0;
      default:  // OPEN, READ, SEEK, TELL, CLOSE: never asked of a new archive
        return fail(ZIP_ER_OPNOTSUPP, 0);
    }
  }
};

std::string main_xml(const surface::HeightGrid& g, const std::string& data_md5) {
  char date[32] = "1970-01-01T00:00:00Z";
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  if (gmtime_r(&now, &utc)) std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  // Increments in the shortest form that reads back to the same double.
  return fmt::format(
      R"(<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.opengps.eu/2008/ISO5436_2 http://www.opengps.eu/2008/ISO5436_2/ISO5436_2.xsd">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>SUR</FeatureType>
    <Axes>
      <CX><AxisType>I</AxisType><DataType>D</DataType><Increment>{}</Increment><Offset>0</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>{}</Increment><Offset>0</Offset></CY>
      <CZ><AxisType>A</AxisType><DataType>D</DataType><Increment>1</Increment><Offset>0</Offset></CZ>
    </Axes>
  </Record1>
  <Record2>
    <Date>{}</Date>
    <Instrument>
      <Manufacturer>geartrib</Manufacturer>
      <Model>geartrib</Model>
      <Serial>not available</Serial>
      <Version>{}</Version>
    </Instrument>
    <ProbingSystem>
      <Type>Software</Type>
      <Identification>geartrib surface</Identification>
    </ProbingSystem>
    <Comment>Heights in metres; NaN marks a missing point.</Comment>
  </Record2>
  <Record3>
    <MatrixDimension>
      <SizeX>{}</SizeX>
      <SizeY>{}</SizeY>
      <SizeZ>1</SizeZ>
    </MatrixDimension>
    <DataLink>
      <PointDataLink>bindata/data.bin</PointDataLink>
      <MD5ChecksumPointData>{}</MD5ChecksumPointData>
    </DataLink>
  </Record3>
  <Record4>
    <ChecksumFile>md5checksum.hex</ChecksumFile>
  </Record4>
</p:ISO5436_2>
)",
      g.dx, g.dy, date, GEARTRIB_VERSION, g.nx, g.ny, data_md5);
}

}  // namespace

surface::HeightGrid read_x3p(const std::filesystem::path& file) { return X3pReader(file).read(); }

void write_x3p(const std::filesystem::path& file, const surface::HeightGrid& g) {
  write_atomically(file, [&](const std::filesystem::path& tmp) { write_x3p_archive(tmp, g); });
}

void write_x3p_archive(const std::filesystem::path& file, const surface::HeightGrid& g) {
  g.validate();
  std::string data(g.size() * 8, '\0');
  auto* p = reinterpret_cast<unsigned char*>(data.data());
  for (std::size_t k = 0; k < g.size(); ++k)
    store_le(std::bit_cast<std::uint64_t>(g.valid[k] ? g.z[k] : kNaN), p + 8 * k);
  const std::string xml = main_xml(g, md5_hex(data));
  const std::string sums = md5_hex(xml) + " *main.xml\n";
  const Libzip& lz = libzip(file.string(), "write");  // before anything is written
  ZipSink sink(file);
  zip_error_t error;
  lz.error_init_with_code(&error, ZIP_ER_OK);
  zip_source_t* source = lz.source_function_create(&ZipSink::callback, &sink, &error);
  ZipArchive z(source ? lz.open_from_source(source, ZIP_CREATE | ZIP_TRUNCATE, &error) : nullptr);
  if (!z) {
    const std::string why = lz.error_strerror(&error);
    if (source) lz.source_free(source);  // not taken by the archive
    lz.error_fini(&error);
    throw std::runtime_error(fmt::format("cannot create {}: {}", file.string(), why));
  }
  lz.error_fini(&error);
  auto add = [&](const char* name, const std::string& bytes, bool deflate) {
    zip_source_t* s = lz.source_buffer(z.get(), bytes.data(), bytes.size(), 0);
    if (!s) throw std::runtime_error(fmt::format("cannot write {}: {}", file.string(), lz.strerror(z.get())));
    const zip_int64_t index = lz.file_add(z.get(), name, s, ZIP_FL_ENC_UTF_8);
    if (index < 0) {
      lz.source_free(s);
      throw std::runtime_error(fmt::format("cannot write {}: {}", file.string(), lz.strerror(z.get())));
    }
    if (lz.set_file_compression(z.get(), static_cast<zip_uint64_t>(index), deflate ? ZIP_CM_DEFLATE : ZIP_CM_STORE,
                                0) != 0)
      throw std::runtime_error(fmt::format("cannot write {}: {}", file.string(), lz.strerror(z.get())));
  };
  add("main.xml", xml, true);
  add("bindata/data.bin", data, false);  // heights hardly compress: stored, fast to write and read
  add("md5checksum.hex", sums, true);
  zip_t* archive = z.release();
  if (lz.close(archive) != 0) {
    const std::string why = lz.strerror(archive);
    lz.discard(archive);
    throw std::runtime_error(fmt::format("cannot write {}: {}", file.string(), why));
  }
}

}  // namespace geartrib::io
