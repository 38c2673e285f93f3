#include "output/table_writer.hpp"

#include "config/input_error.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <optional>
#include <random>
#include <stdexcept>
#include <thread>

namespace geartrib::io {

std::string format_csv(const Table& t) {
  std::string out;
  for (std::size_t i = 0; i < t.header.size(); ++i) out += (i ? "," : "") + t.header[i];
  out += '\n';
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const bool labelled = !t.labels.empty();
    if (labelled) out += t.labels[r];
    for (std::size_t i = 0; i < t.rows[r].size(); ++i)
      out += fmt::format("{}{:.10g}", (i || labelled) ? "," : "", t.rows[r][i]);
    out += '\n';
  }
  return out;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

EngineeringValue engineering_value(const std::string& symbol, double v, const std::string& unit) {
  if (unit == "Pa") return {v * 1e-6, "MPa"};
  if (unit == "m") return std::abs(v) < 1e-3 ? EngineeringValue{v * 1e6, "um"} : EngineeringValue{v * 1e3, "mm"};
  if (unit == "N/m") return {v * 1e-3, "N/mm"};
  if (unit == "N/m^2") return {v * 1e-9, "N/(mm um)"};
  if (unit == "Pa^0.5") return {v * 1e-3, "N^0.5/mm"};
  if (unit == "K" && symbol.rfind("theta_fl", 0) != 0) return {v - 273.15, "degC"};
  return {v, unit};
}

std::string format_text(const Table& t) {
  std::vector<std::vector<std::string>> cells;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    std::vector<std::string> r;
    if (!t.labels.empty()) r.push_back(t.labels[k]);
    for (double v : t.rows[k]) r.push_back(fmt::format("{:.6g}", v));
    cells.push_back(std::move(r));
  }
  std::vector<std::size_t> width(t.header.size());
  for (std::size_t i = 0; i < t.header.size(); ++i) {
    width[i] = t.header[i].size();
    for (const auto& r : cells) width[i] = std::max(width[i], r[i].size());
  }
  std::string out;
  for (std::size_t i = 0; i < t.header.size(); ++i)
    out += fmt::format("{}{:>{}}", i ? "  " : "", t.header[i], width[i]);
  out += '\n';
  for (const auto& r : cells) {
    for (std::size_t i = 0; i < r.size(); ++i) out += fmt::format("{}{:>{}}", i ? "  " : "", r[i], width[i]);
    out += '\n';
  }
  return out;
}

void flush_stdout() {
  // std::cout writes through stdio's buffer (synchronised with it, the default): one flush of stdio
  // flushes both, and its errno is the reason.
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  std::cout.flush();
  if (!flushed || std::ferror(stdout) || !std::cout)
    throw std::runtime_error(fmt::format("cannot write standard output: {}",
                                         !flushed && error != 0 ? std::strerror(error) : "a write to it failed"));
}

namespace {

// `text` to standard output, flushed and checked.
void write_stdout(std::string_view text) {
  errno = 0;
  if (!text.empty() && std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) {
    const int error = errno;  // a full buffer's flush failed on the way
    throw std::runtime_error(
        fmt::format("cannot write standard output: {}", error != 0 ? std::strerror(error) : "a write to it failed"));
  }
  flush_stdout();
}

}  // namespace

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

namespace {

[[noreturn]] void fail_write(const std::filesystem::path& file, int error) {
  throw std::runtime_error(fmt::format("cannot write {}: {}", file.string(), std::strerror(error)));
}

}  // namespace

void write_bytes(const std::filesystem::path& file, std::string_view bytes) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail_write(file, errno);
  if (!write_all(fd, bytes.data(), bytes.size())) {
    const int error = errno;
    ::close(fd);
    fail_write(file, error);
  }
  if (::close(fd) != 0) fail_write(file, errno);
}

namespace {

// The temporaries a signal must remove. A signal handler can use only async-signal-safe calls
// (unlink, sigaction, raise) and no locks: a fixed table of paths, each claimed by an atomic flag.
constexpr int kSignalSlots = 64;
constexpr std::size_t kSlotPathBytes = 4096;
struct SignalSlot {
  std::atomic<bool> claimed{false};  // owned by an OutputSet
  std::atomic<bool> ready{false};    // path complete: the handler may unlink it
  char path[kSlotPathBytes] = {};
};
SignalSlot signal_slots[kSignalSlots];
// SIGPIPE (a reader gone) and SIGXFSZ (the file-size limit) end the process too, by default.
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXFSZ};

void remove_temporaries_and_reraise(int signal_number) {
  for (auto& slot : signal_slots)
    if (slot.ready.load()) ::unlink(slot.path);
  struct sigaction restore {};
  restore.sa_handler = SIG_DFL;
  ::sigemptyset(&restore.sa_mask);
  ::sigaction(signal_number, &restore, nullptr);
  ::raise(signal_number);
}

// The handler is the process's only while an output set holds temporaries, and only for the signals
// whose disposition is the default (they would end the process anyway: the temporaries go first, then
// the signal ends it as it would have). A host's own handler (Python's KeyboardInterrupt, a Jupyter
// kernel's interrupt) or an ignored signal (SIGHUP under nohup) is left as it is, and each default is
// restored when the last set is done: a library call leaves the host's signal handlers as it found them.
std::mutex handler_mutex;
int handler_users = 0;  // output sets holding temporaries
bool handler_installed[std::size(kCleanupSignals)] = {};

void acquire_cleanup_handler() {
  const std::lock_guard lock(handler_mutex);
  if (handler_users++ > 0) return;
  for (std::size_t i = 0; i < std::size(kCleanupSignals); ++i) {
    struct sigaction previous {};
    ::sigaction(kCleanupSignals[i], nullptr, &previous);
    handler_installed[i] = (previous.sa_flags & SA_SIGINFO) == 0 && previous.sa_handler == SIG_DFL;
    if (!handler_installed[i]) continue;
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_reraise;
    ::sigemptyset(&action.sa_mask);
    ::sigaction(kCleanupSignals[i], &action, nullptr);
  }
}

void release_cleanup_handler() {
  const std::lock_guard lock(handler_mutex);
  if (--handler_users > 0) return;
  for (std::size_t i = 0; i < std::size(kCleanupSignals); ++i) {
    if (!handler_installed[i]) continue;
    handler_installed[i] = false;
    struct sigaction current {};
    ::sigaction(kCleanupSignals[i], nullptr, &current);
    if ((current.sa_flags & SA_SIGINFO) != 0 || current.sa_handler != remove_temporaries_and_reraise)
      continue;  // the host set its own meanwhile: keep it
    struct sigaction restore {};
    restore.sa_handler = SIG_DFL;
    ::sigemptyset(&restore.sa_mask);
    ::sigaction(kCleanupSignals[i], &restore, nullptr);
  }
}

int claim_slot(const std::filesystem::path& temporary) {
  const std::string text = temporary.string();
  if (text.size() >= kSlotPathBytes) return -1;
  for (int i = 0; i < kSignalSlots; ++i) {
    bool expected = false;
    if (!signal_slots[i].claimed.compare_exchange_strong(expected, true)) continue;
    std::copy(text.begin(), text.end(), signal_slots[i].path);
    signal_slots[i].path[text.size()] = '\0';
    signal_slots[i].ready.store(true);
    return i;
  }
  return -1;
}

void release_slot(int slot) {
  if (slot < 0) return;
  signal_slots[slot].ready.store(false);
  signal_slots[slot].claimed.store(false);
}

// Ten random characters of [0-9a-z] (about 52 bits) from the kernel's generator.
std::string random_suffix() {
  constexpr char kDigits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
  unsigned char bytes[10];
  std::size_t got = 0;
  while (got < sizeof bytes) {
    const ssize_t n = ::getrandom(bytes + got, sizeof bytes - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got < sizeof bytes) {  // no getrandom (an old kernel): the C++ library's source
    std::random_device device;
    for (auto& b : bytes) b = static_cast<unsigned char>(device());
  }
  std::string s;
  for (unsigned char b : bytes) s += kDigits[b % 36];
  return s;
}

}  // namespace

namespace detail {

// A new empty file `folder/<prefix><suffix()>`, created exclusively with the mode any new file
// gets (0666 less the umask); a name already taken (a stale temporary, another writer's) is passed
// over. The name is in the signal handler's list (`slot`) before the file exists, so that a signal
// never leaves it. Empty with `error` set when the folder cannot take it.
std::filesystem::path create_temporary(const std::filesystem::path& folder, const std::string& prefix, int& error,
                                       int& slot, const std::function<std::string()>& suffix) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::filesystem::path candidate = folder / (prefix + suffix());
    slot = claim_slot(candidate);
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return candidate;
    }
    error = errno;
    release_slot(slot);
    slot = -1;
    if (error != EEXIST) return {};
  }
  return {};
}

}  // namespace detail

namespace {

// Where a target's content goes, decided by what the target is (see OutputSet in the header).
struct Destination {
  std::filesystem::path path;    // the file to replace or the stream to write
  std::filesystem::path folder;  // where the temporary goes
  bool stream = false;
  int descriptor = -1;  // 1 or 2: the target is the process's standard output or error (written through it)
};

// The descriptor (1, standard output; 2, standard error) whose file `st` is, or -1: `-o /dev/stdout`
// with standard output redirected to a file is that file, which must be appended to through the
// descriptor, never replaced (a log the job appends to) nor reopened at its start.
int standard_descriptor_of(const struct stat& st) {
  for (int fd : {1, 2}) {
    struct stat s {};
    if (::fstat(fd, &s) == 0 && s.st_dev == st.st_dev && s.st_ino == st.st_ino) return fd;
  }
  return -1;
}

[[noreturn]] void refuse_target(const std::filesystem::path& target, const std::string& rule) {
  throw InputError(target.string(), 0, "", "", rule);
}

Destination destination_of(const std::filesystem::path& target) {
  const auto parent = [](const std::filesystem::path& p) {
    return p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  };
  struct stat link {};
  if (::lstat(target.c_str(), &link) != 0) {
    if (errno == ENOENT) return {target, parent(target), false};  // new: a missing folder shows at its temporary
    refuse_target(target, fmt::format("cannot be written: {}", std::strerror(errno)));
  }
  struct stat st = link;
  if (S_ISLNK(link.st_mode) && ::stat(target.c_str(), &st) != 0) {
    const int error = errno;
    std::error_code ec;
    const auto to = std::filesystem::read_symlink(target, ec);
    if (error == ENOENT)
      refuse_target(target, fmt::format("a symbolic link to {}, which does not exist: give the file to write itself",
                                        to.string()));
    refuse_target(target, fmt::format("cannot be written: {}", std::strerror(error)));
  }
  // A stream's temporary goes to the temporary folder (a device's folder takes no files).
  const auto stream = [&](int descriptor) -> Destination {
    std::error_code ec;
    const auto folder = std::filesystem::temp_directory_path(ec);
    if (ec) refuse_target(target, fmt::format("a stream needs a temporary folder: {}", ec.message()));
    return {target, folder, true, descriptor};
  };
  if (const int fd = standard_descriptor_of(st); fd >= 0) return stream(fd);
  if (S_ISREG(st.st_mode)) {
    if (!S_ISLNK(link.st_mode)) return {target, parent(target), false};
    std::error_code ec;
    const auto file = std::filesystem::canonical(target, ec);  // the link's file, replaced; the link stays
    if (ec)
      refuse_target(target, fmt::format("cannot be written: the symbolic link cannot be followed: {}", ec.message()));
    return {file, parent(file), false};
  }
  if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
    if (::faccessat(AT_FDCWD, target.c_str(), W_OK, AT_EACCESS) != 0)
      refuse_target(target, fmt::format("cannot be written: {}", std::strerror(errno)));
    return stream(-1);
  }
  if (S_ISDIR(st.st_mode)) refuse_target(target, "is a folder: an output is a file (name one inside the folder)");
  if (S_ISBLK(st.st_mode))
    refuse_target(target, "is a block device: a result is never written onto a disk (name a file)");
  refuse_target(target, "is a socket or another special file: a result goes to a file, a character device or a FIFO");
}

// The stream opened for writing without blocking on it (a FIFO without a reader is ENXIO, retried
// for `wait`: a FIFO nobody reads never hangs the command), then switched to blocking writes. -1
// with errno set on failure.
int open_stream(const std::filesystem::path& to, std::chrono::milliseconds wait) {
  const auto deadline = std::chrono::steady_clock::now() + wait;
  for (;;) {
    const int fd = ::open(to.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (fd >= 0) {
      const int flags = ::fcntl(fd, F_GETFL);
      if (flags >= 0 && ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == 0) return fd;
      const int error = errno;
      ::close(fd);
      errno = error;
      return -1;
    }
    if (errno == EINTR) continue;
    if (errno != ENXIO || std::chrono::steady_clock::now() >= deadline) return -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

// The complete temporary `from` to the stream `to` (a character device or a FIFO).
// With `descriptor` 1 or 2, through that descriptor (standard output or error) instead.
void copy_to_stream(const std::filesystem::path& from, const std::filesystem::path& to, int descriptor,
                    std::chrono::milliseconds wait) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) fail_write(from, errno);
  const int out = descriptor >= 0 ? ::fcntl(descriptor, F_DUPFD_CLOEXEC, 3) : open_stream(to, wait);
  if (out < 0) {
    const int error = errno;
    ::close(in);
    if (error == ENXIO)
      throw std::runtime_error(fmt::format("cannot write {}: no reader opened the FIFO within {:g} s", to.string(),
                                           static_cast<double>(wait.count()) / 1e3));
    fail_write(to, error);
  }
  struct stat st {};
  int error = 0;
  if (::fstat(out, &st) != 0) error = errno;
  else if (descriptor < 0 && !S_ISCHR(st.st_mode) && !S_ISFIFO(st.st_mode)) error = EEXIST;  // replaced since reserved
  std::vector<char> buffer(std::size_t{1} << 20);
  while (error == 0) {
    const ssize_t n = ::read(in, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) error = errno;
    if (n <= 0) break;
    if (!write_all(out, buffer.data(), static_cast<std::size_t>(n))) error = errno;
  }
  ::close(in);
  if (::close(out) != 0 && error == 0) error = errno;
  if (error != 0) fail_write(to, error);
}

// Whether two destinations are one file: the same existing file (device and inode; a standard
// descriptor's file as fstat sees it), or the same path once made absolute and normal. Character
// devices are streams that two outputs may share (/dev/null twice, or with standard output on it).
bool same_file(const std::filesystem::path& a, int a_descriptor, const std::filesystem::path& b, int b_descriptor) {
  const auto stat_of = [](const std::filesystem::path& p, int descriptor) {
    std::optional<struct stat> st{std::in_place};
    if ((descriptor >= 0 ? ::fstat(descriptor, &*st) : ::stat(p.c_str(), &*st)) != 0) st.reset();
    return st;
  };
  const auto sa = stat_of(a, a_descriptor), sb = stat_of(b, b_descriptor);
  if (sa && sb) return !S_ISCHR(sa->st_mode) && sa->st_dev == sb->st_dev && sa->st_ino == sb->st_ino;
  std::error_code ea, eb;
  const auto ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a), ea);
  const auto cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b), eb);
  return !ea && !eb && ca == cb;
}

// The temporary's data on the disk: a write error the kernel deferred (NFS, a quota) shows here.
void sync_to_disk(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail_write(file, errno);
  int error = 0;
  while (::fsync(fd) != 0) {
    if (errno == EINTR) continue;
    if (errno != EINVAL && errno != EROFS) error = errno;  // a file system that cannot sync has nothing deferred
    break;
  }
  ::close(fd);
  if (error != 0) fail_write(file, error);
}

}  // namespace

OutputSet::~OutputSet() { discard(); }

void OutputSet::discard() {
  for (const auto& p : pending_) {
    std::error_code ignored;
    if (!p.temporary.empty()) std::filesystem::remove(p.temporary, ignored);
    release_slot(p.slot);
  }
  if (!pending_.empty()) release_cleanup_handler();  // a set holds the handler while it has temporaries
  pending_.clear();
  stdout_.clear();
}

void OutputSet::reserve(const std::filesystem::path& target) {
  for (const auto& p : pending_)
    if (p.target == target) return;
  const bool first = pending_.empty();  // the set takes the signals' handler with its first temporary
  Destination d;
  try {
    d = destination_of(target);
    // One file under two names (out.csv and ./out.csv, a link and its file): one would be lost.
    for (const auto& p : pending_)
      if (same_file(p.destination, p.descriptor, d.path, d.descriptor))
        refuse_target(target,
                      fmt::format("is the same file as the output {}: give each output once", p.target.string()));
    pending_.reserve(pending_.size() + 1);  // the push below cannot throw once the temporary exists
  } catch (...) {
    discard();
    throw;
  }
  const std::string name = d.path.filename().string();
  if (first) acquire_cleanup_handler();
  int error = 0, slot = -1;
  const auto temporary = detail::create_temporary(
      d.folder, d.stream ? ".geartrib-" + name + ".tmp." : "." + name + ".tmp.", error, slot, random_suffix);
  if (temporary.empty()) {
    if (first) release_cleanup_handler();  // discard() releases it only for a set with temporaries
    discard();
    throw InputError(target.string(), 0, "", "",
                     fmt::format("cannot be written: {} (folder {})", std::strerror(error), d.folder.string()));
  }
  pending_.push_back({temporary, target, d.path, d.stream, d.descriptor, slot, false});
}

std::filesystem::path OutputSet::add(const std::filesystem::path& target,
                                     const std::function<void(const std::filesystem::path&)>& write) {
  reserve(target);
  auto at = std::find_if(pending_.begin(), pending_.end(), [&](const Pending& p) { return p.target == target; });
  if (at->written) {
    discard();
    throw InputError(target.string(), 0, "", "", "given twice as an output");
  }
  at->written = true;
  try {
    write(at->temporary);
  } catch (const InputError&) {
    discard();
    throw;
  } catch (const std::runtime_error& e) {  // a write error: named with the target it was for
    const std::string what = fmt::format("{}: not written: {}", target.string(), e.what());
    discard();
    throw std::runtime_error(what);
  } catch (...) {
    discard();
    throw;
  }
  return at->temporary;
}

std::filesystem::path OutputSet::add_text(const std::filesystem::path& target, const std::string& content) {
  return add(target, [&](const std::filesystem::path& tmp) { write_bytes(tmp, content); });
}

void OutputSet::add_stdout(std::string text) { stdout_.push_back(std::move(text)); }

void OutputSet::commit() {
  // A reserved target never written is a programming error: nothing is renamed.
  for (const auto& p : pending_)
    if (!p.written) {
      discard();
      throw std::logic_error("OutputSet: " + p.target.string() + " reserved but not written");
    }
  try {
    for (const auto& p : pending_)
      if (!p.stream) sync_to_disk(p.temporary);
    for (const auto& text : stdout_) write_stdout(text);
    for (const auto& p : pending_)
      if (p.stream) copy_to_stream(p.temporary, p.destination, p.descriptor, fifo_reader_wait_);
    for (auto& p : pending_) {
      if (p.stream) continue;
      if (::rename(p.temporary.c_str(), p.destination.c_str()) != 0)
        throw std::runtime_error(fmt::format("cannot rename {} to {}: {}", p.temporary.string(), p.destination.string(),
                                             std::strerror(errno)));
      p.temporary.clear();  // in place: nothing left to remove (a rename cannot be taken back)
    }
  } catch (...) {
    discard();
    throw;
  }
  discard();  // the streams' temporaries, the signal slots
}

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path&)>& write_temporary) {
  OutputSet set;
  set.add(path, write_temporary);
  set.commit();
}

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  OutputSet set;
  set.add_text(path, content);
  set.commit();
}

}  // namespace geartrib::io
