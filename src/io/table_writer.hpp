// Tables for people (aligned columns) or programs (CSV), and files written atomically.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
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

// The table as CSV or text, to stdout when `path` is empty, else to `path` atomically.
void output_table(const Table& t, bool csv, const std::string& path);

// A command's output files, all or none. add() writes a target's content at once to a temporary
// beside it (`.NAME.tmp.PID`; `write` gets the temporary's path); commit() renames every temporary
// onto its target. Until then no target changes: an exception, the set's destruction or SIGINT,
// SIGTERM, SIGHUP or SIGQUIT (the process ends as the signal would have it) removes the
// temporaries. The signals' handler is installed only while a set holds temporaries and only where
// the disposition is the default: a host's own handlers (Python's KeyboardInterrupt) and ignored
// signals are left alone, and the defaults come back when the last set is done. reserve() creates a target's temporary
// ahead (a command reserves its outputs before computing): a folder that is missing or not writable is an InputError
// naming the target; the same target written twice is an InputError too. (SIGKILL cannot be caught: it may leave a
// temporary, never a half-written target.)
class OutputSet {
 public:
  OutputSet() = default;
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();
  void reserve(const std::filesystem::path& target);
  void add(const std::filesystem::path& target, const std::function<void(const std::filesystem::path&)>& write);
  void add_text(const std::filesystem::path& target, const std::string& content);
  void commit();

 private:
  struct Pending {
    std::filesystem::path temporary, target;
    int slot;  // in the signal handler's list, -1 when it had no room
    bool written;
  };
  std::vector<Pending> pending_;
  void discard();
};

// One file through an OutputSet of one.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path&)>& write_temporary);
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace geartrib::io
