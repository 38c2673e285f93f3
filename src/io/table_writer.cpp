#include "io/table_writer.hpp"

#include "io/input_error.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>

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

void output_table(const Table& t, bool csv, const std::string& path) {
  const std::string text = csv ? format_csv(t) : format_text(t);
  if (path.empty()) std::fwrite(text.data(), 1, text.size(), stdout);
  else write_file_atomically(path, text);
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
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

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

}  // namespace

OutputSet::~OutputSet() { discard(); }

void OutputSet::discard() {
  for (const auto& p : pending_) {
    std::error_code ignored;
    std::filesystem::remove(p.temporary, ignored);
    release_slot(p.slot);
  }
  if (!pending_.empty()) release_cleanup_handler();  // a set holds the handler while it has temporaries
  pending_.clear();
}

void OutputSet::reserve(const std::filesystem::path& target) {
  for (const auto& p : pending_)
    if (p.target == target) return;
  const bool first = pending_.empty();
  if (first) acquire_cleanup_handler();
  const auto dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  const auto temporary = dir / fmt::format(".{}.tmp.{}", target.filename().string(), ::getpid());
  const int slot = claim_slot(temporary);
  // Created exclusively here, so that a missing or read-only folder is named before any work.
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int error = errno;
    release_slot(slot);
    if (first) release_cleanup_handler();  // discard() releases it only for a set with temporaries
    discard();
    throw InputError(target.string(), 0, "", "",
                     fmt::format("cannot be written: {} (folder {})", std::strerror(error), dir.string()));
  }
  ::close(fd);
  pending_.push_back({temporary, target, slot, false});
}

void OutputSet::add(const std::filesystem::path& target,
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
  } catch (...) {
    discard();
    throw;
  }
}

void OutputSet::add_text(const std::filesystem::path& target, const std::string& content) {
  add(target, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
    out << content;
    out.flush();
    if (!out) throw std::runtime_error(fmt::format("error while writing {} (disk full?)", tmp.string()));
  });
}

void OutputSet::commit() {
  // A reserved target never written is a programming error: nothing is renamed.
  for (const auto& p : pending_)
    if (!p.written) {
      discard();
      throw std::logic_error("OutputSet: " + p.target.string() + " reserved but not written");
    }
  for (std::size_t k = 0; k < pending_.size(); ++k) {
    std::error_code ec;
    std::filesystem::rename(pending_[k].temporary, pending_[k].target, ec);
    if (ec) {
      const std::string what = fmt::format("cannot rename {} to {}: {}", pending_[k].temporary.string(),
                                           pending_[k].target.string(), ec.message());
      pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(k));
      discard();
      throw std::runtime_error(what);
    }
    release_slot(pending_[k].slot);
  }
  if (!pending_.empty()) release_cleanup_handler();
  pending_.clear();
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
