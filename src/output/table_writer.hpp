// Tables for people (aligned columns) or programs (CSV), and files written atomically.
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::io {

// A numeric table; when `labels` is not empty, each row starts with its label and header[0]
// names that label column.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::vector<std::string> labels;
  // A labelled row (name/value summaries, per-asperity rows).
  void add_row(std::string label, std::vector<double> values) {
    labels.push_back(std::move(label));
    rows.push_back(std::move(values));
  }
};

// CSV: header line, then rows with full precision (%.10g). Text: right-aligned columns (%.6g).
std::string format_csv(const Table& t);
std::string format_text(const Table& t);
// One CSV field: as it is, or quoted (its quotes doubled) when it holds a comma, a quote or a newline.
std::string csv_field(const std::string& s);
// A value of SI unit `unit` in the unit an engineer reads: Pa -> MPa, m -> um (below 1 mm) or mm,
// N/m -> N/mm, N/m^2 -> N/(mm um), Pa^0.5 -> N^0.5/mm, K -> degC unless `symbol` names a temperature
// rise (theta_fl...); others as they are. The unit is plain text ("um", "degC").
struct EngineeringValue {
  double value = 0.0;
  std::string unit;
};
EngineeringValue engineering_value(const std::string& symbol, double value, const std::string& unit);

// Standard output flushed (what stdio and std::cout hold) and checked: a write that failed (a full
// disk, a closed pipe with SIGPIPE ignored) is a std::runtime_error (exit 1), never a table
// silently cut short. src/app/main.cpp calls it after every command; OutputSet::add_stdout's text
// is written and checked at the commit.
void flush_stdout();

// Every byte of [data, data + size) to the descriptor `fd`, resuming after a signal or a short
// write; false with errno set on an error.
bool write_all(int fd, const char* data, std::size_t size);

// Writes `bytes` to `file` (created, or emptied first), each write checked, the file closed and
// checked: a std::runtime_error naming the file and the system's reason (EFBIG, ENOSPC, EIO).
void write_bytes(const std::filesystem::path& file, std::string_view bytes);

namespace detail {
// OutputSet's temporary `folder/<prefix><suffix()>`, created exclusively (a taken name is passed
// over, up to 100 tries) and put in the signal handler's list (`slot`, -1 when it had no room)
// before it exists; empty with `error` set when the folder cannot take it. Exposed for its test.
std::filesystem::path create_temporary(const std::filesystem::path& folder, const std::string& prefix, int& error,
                                       int& slot, const std::function<std::string()>& suffix);
}  // namespace detail

// How long a FIFO target's reader is waited for at the commit (then the commit fails: exit 1).
inline constexpr std::chrono::milliseconds kFifoReaderWait{10000};

// A command's outputs, all or none.
//
// reserve(target) checks the target and creates its temporary before any work, so that a target
// that cannot be written is refused (io::InputError, exit 2) before anything is computed:
//   - a new name or a regular file: the temporary is `.NAME.tmp.XXXXXXXXXX` beside it (a random
//     suffix, created exclusively: a temporary left by a killed run never blocks a later one, and
//     threads or processes writing one path do not collide), renamed onto it by commit();
//   - a symbolic link is followed: the file it names is replaced (the link stays); a link to
//     nothing is refused;
//   - a character device or a FIFO (/dev/null, /dev/stdout on a pipe, a named pipe) is written
//     as a stream at commit, from a complete temporary in the temporary folder ($TMPDIR): never
//     replaced by a file. A FIFO's reader is waited for kFifoReaderWait at most (then exit 1: a
//     FIFO nobody opens does not hang the command; one whose reader stops reading blocks the
//     write, as any pipe does). A stream cannot be taken back: it may hold part of the output when
//     the write fails;
//   - the file standard output or error is (/dev/stdout, /dev/fd/1, or the file either is
//     redirected to) is written through that descriptor, appended after standard output's own
//     text: a log the job appends to is never replaced;
//   - one file under two names (out.csv and ./out.csv, a link and its file) is refused, as is the
//     same target given twice;
//   - a folder, a block device or a socket is refused; so is a missing or read-only folder.
// add() writes a target's content at once (`write` gets the temporary's path); add_stdout() keeps
// text for standard output. commit() syncs every file's temporary to disk (a deferred write error shows
// here), writes the streams (standard output first), then renames the temporaries onto their
// targets. Until then no target changes: an exception, the set's destruction or SIGINT, SIGTERM,
// SIGHUP, SIGQUIT, SIGPIPE or SIGXFSZ (the process ends as the signal would have it) removes the
// temporaries. That handler is installed only while a set holds temporaries and only where the
// disposition is the default: a host's own handler (Python's KeyboardInterrupt) and an ignored
// signal (SIGHUP under nohup) are left alone, and the defaults come back when the last set is done.
// (SIGKILL cannot be caught: it may leave a
// temporary, never a half-written target; a later run does not trip over it.)
class OutputSet {
 public:
  explicit OutputSet(std::chrono::milliseconds fifo_reader_wait = kFifoReaderWait)
      : fifo_reader_wait_(fifo_reader_wait) {}
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();
  void reserve(const std::filesystem::path& target);
  // Returns the temporary, complete (what commit() puts in place), for a later writer that reads it.
  std::filesystem::path add(const std::filesystem::path& target,
                            const std::function<void(const std::filesystem::path&)>& write);
  std::filesystem::path add_text(const std::filesystem::path& target, const std::string& content);
  void add_stdout(std::string text);
  void commit();

 private:
  struct Pending {
    std::filesystem::path temporary, target;
    std::filesystem::path destination;  // what commit() renames onto or streams to
    bool stream;                        // a character device or FIFO: written, not replaced
    int descriptor;                     // 1 or 2: standard output or error, written through it
    int slot;                           // in the signal handler's list, -1 when it had no room
    bool written;
  };
  std::vector<Pending> pending_;
  std::vector<std::string> stdout_;
  std::chrono::milliseconds fifo_reader_wait_;
  void discard();
};

// One file through an OutputSet of one.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path&)>& write_temporary);
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace geartrib::io
