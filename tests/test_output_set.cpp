// Output sets: every output of a command or none. A failing writer, a missing folder and a signal
// leave the targets as they were and no temporary behind; a write error (the file-size limit
// standing in for a full disk) is an exception, never a crash; a device, a FIFO or a symbolic link
// is written through, never replaced; temporaries never collide.
#include "config/input_error.hpp"
#include "output/column_table.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace geartrib;
namespace fs = std::filesystem;

namespace {
// A fresh folder per test, removed at the end.
struct ScratchFolder {
  fs::path path;
  explicit ScratchFolder(const std::string& name) : path(fs::temp_directory_path() / ("geartrib_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchFolder() { fs::remove_all(path); }
  std::vector<std::string> entries() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(path)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
};
std::string content(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(OutputSet, CommitWritesEveryTarget) {
  ScratchFolder dir("outputset_commit");
  io::OutputSet set;
  set.add_text(dir.path / "a.csv", "a\n");
  set.add_text(dir.path / "b.txt", "b\n");
  set.commit();
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.csv", "b.txt"}));
  EXPECT_EQ(content(dir.path / "b.txt"), "b\n");
}

TEST(OutputSet, AFailingWriterLeavesTheOldTargetsAndNoTemporary) {
  ScratchFolder dir("outputset_fail");
  std::ofstream(dir.path / "a.csv") << "old\n";
  io::OutputSet set;
  set.add_text(dir.path / "a.csv", "new\n");
  EXPECT_THROW(set.add(dir.path / "b.h5", [](const fs::path&) { throw std::runtime_error("disk full"); }),
               std::runtime_error);
  set.commit();  // nothing left to rename: the failure discarded the whole set
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.csv"}));
  EXPECT_EQ(content(dir.path / "a.csv"), "old\n");
}

TEST(OutputSet, AMissingFolderIsNamedBeforeAnyWork) {
  ScratchFolder dir("outputset_missing");
  io::OutputSet set;
  set.reserve(dir.path / "a.h5");
  try {
    set.reserve(dir.path / "no-such-folder" / "a.csv");
    FAIL() << "a missing folder must be refused";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-folder/a.csv"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());  // the first reservation's temporary went with the set
}

TEST(OutputSet, TheSameTargetTwiceIsRefused) {
  ScratchFolder dir("outputset_twice");
  io::OutputSet set;
  set.add_text(dir.path / "a.csv", "1\n");
  EXPECT_THROW(set.add_text(dir.path / "a.csv", "2\n"), io::InputError);
  EXPECT_TRUE(dir.entries().empty());
}

// A signal while the outputs are being written: the process dies of that signal, and its
// temporaries die with it; the old target stays.
TEST(OutputSet, ASignalRemovesTheTemporaries) {
  ScratchFolder dir("outputset_signal");
  std::ofstream(dir.path / "a.csv") << "old\n";
  for (int signal_number : {SIGTERM, SIGINT}) {
    EXPECT_EXIT(
        {
          io::OutputSet set;
          set.add_text(dir.path / "a.csv", "new\n");
          set.reserve(dir.path / "b.h5");
          std::raise(signal_number);
        },
        testing::KilledBySignal(signal_number), "");
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.csv"})) << "signal " << signal_number;
    EXPECT_EQ(content(dir.path / "a.csv"), "old\n");
  }
}

namespace {
// In a death-test child: the file-size limit at `bytes` with SIGXFSZ ignored, so that a write past
// it fails with EFBIG (what a full disk's ENOSPC does) instead of killing the process.
void limit_file_size(rlim_t bytes) {
  std::signal(SIGXFSZ, SIG_IGN);
  const rlimit limit{bytes, bytes};
  if (setrlimit(RLIMIT_FSIZE, &limit) != 0) std::_Exit(90);
}
// A column table of `rows` x 8 numbers (about 64 rows a KiB in HDF5).
io::ColumnTableFile numbers_table(std::size_t rows) {
  io::ColumnTableFile f;
  for (int c = 0; c < 8; ++c) {
    io::Column column{fmt::format("c{}", c), "m", false, {}, {}};
    for (std::size_t r = 0; r < rows; ++r) column.numbers.push_back(static_cast<double>(r * 8 + c));
    f.table.columns.push_back(std::move(column));
  }
  f.scene = "# scene";
  return f;
}
}  // namespace

TEST(OutputSet, AFolderTargetIsRefusedBeforeAnyWork) {
  ScratchFolder dir("outputset_folder");
  fs::create_directory(dir.path / "out.csv");
  io::OutputSet set;
  set.reserve(dir.path / "a.h5");
  try {
    set.reserve(dir.path / "out.csv");
    FAIL() << "a folder must be refused";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("out.csv: is a folder"), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.csv"}));  // nothing beside it, a.h5's temporary gone
  EXPECT_TRUE(fs::is_empty(dir.path / "out.csv"));
}

// Temporaries were named by PID: one left by a killed run (a container's PID 1 every time) made
// every later run to that target fail with "File exists", and two writers of one path in one
// process collided. They are now unique per attempt.
TEST(OutputSet, AStaleTemporaryNeverBlocksAndWritersDoNotCollide) {
  ScratchFolder dir("outputset_stale");
  std::ofstream(dir.path / (".a.csv.tmp." + std::to_string(::getpid()))) << "stale\n";
  io::write_file_atomically(dir.path / "a.csv", "new\n");
  EXPECT_EQ(content(dir.path / "a.csv"), "new\n");
  io::OutputSet first, second;  // one target, two sets at once (Python threads do this)
  first.add_text(dir.path / "b.csv", "1\n");
  second.add_text(dir.path / "b.csv", "2\n");
  first.commit();
  second.commit();
  EXPECT_EQ(content(dir.path / "b.csv"), "2\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{".a.csv.tmp." + std::to_string(::getpid()), "a.csv", "b.csv"}));
}

// A write error (the file-size limit, EFBIG, standing in for a full disk's ENOSPC): an exception
// naming the target, nothing at the target, no temporary.
TEST(OutputSet, AWriteErrorLeavesNothing) {
  ScratchFolder dir("outputset_efbig");
  std::ofstream(dir.path / "old.csv") << "old\n";
  EXPECT_EXIT(
      {
        limit_file_size(4096);
        try {
          io::OutputSet set;
          set.add_text(dir.path / "small.csv", "fits\n");
          set.add_text(dir.path / "old.csv", std::string(100000, 'x'));
          set.commit();
        } catch (const std::runtime_error& e) {
          const bool named = std::string(e.what()).find("old.csv: not written: cannot write") != std::string::npos;
          std::exit(named ? 3 : 4);
        }
        std::exit(5);
      },
      testing::ExitedWithCode(3), "");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"old.csv"}));
  EXPECT_EQ(content(dir.path / "old.csv"), "old\n");
}

// HDF5 1.10 keeps a file whose flush failed open, and its shutdown at exit crashed (SIGSEGV) after
// a corrupt file had been renamed into place. The file is now built in memory and written by
// geartrib's checked writes: the error is an exception and the process exits normally, HDF5's exit
// handler included (std::exit runs it).
TEST(OutputSet, AnHdf5WriteErrorIsAnExceptionNotACrash) {
  ScratchFolder dir("outputset_hdf5");
  EXPECT_EXIT(
      {
        limit_file_size(64 * 1024);
        try {
          io::write_atomically(dir.path / "table.h5", [](const fs::path& tmp) {
            io::write_column_table_hdf5(tmp, numbers_table(20000));  // about 1.3 MB
          });
        } catch (const std::runtime_error& e) {
          std::exit(std::string(e.what()).find("File too large") != std::string::npos ? 3 : 4);
        }
        std::exit(5);
      },
      testing::ExitedWithCode(3), "");
  EXPECT_TRUE(dir.entries().empty());
  // Unlimited, the same table is written and reads back.
  io::write_atomically(dir.path / "table.h5",
                       [](const fs::path& tmp) { io::write_column_table_hdf5(tmp, numbers_table(20000)); });
  const io::ColumnTableFile back = io::read_column_table_hdf5(dir.path / "table.h5");
  ASSERT_EQ(back.table.rows(), 20000u);
  EXPECT_EQ(back.table.columns[3].numbers[19999], 19999.0 * 8 + 3);
}

// A FIFO is written as a stream (its reader gets the whole content) and stays a FIFO; without a
// reader the commit fails after the wait instead of hanging, and nothing else is committed.
TEST(OutputSet, AFifoIsWrittenThroughNotReplaced) {
  ScratchFolder dir("outputset_fifo");
  const fs::path fifo = dir.path / "pipe.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const std::string text(300000, 'y');  // more than a pipe's buffer
  std::string got;
  std::thread reader([&] { got = content(fifo); });
  io::OutputSet set;
  set.add_text(fifo, text);
  set.add_text(dir.path / "beside.csv", "b\n");
  set.commit();
  if (!fs::is_fifo(fifo)) {  // replaced: the reader waits on the FIFO's inode for ever
    reader.detach();
    FAIL() << "the FIFO was replaced by a file";
  }
  reader.join();
  EXPECT_EQ(got, text);
  EXPECT_EQ(content(dir.path / "beside.csv"), "b\n");

  io::OutputSet unread(std::chrono::milliseconds(200));
  unread.add_text(fifo, "x\n");
  unread.add_text(dir.path / "other.csv", "o\n");
  try {
    unread.commit();
    FAIL() << "a FIFO nobody reads must fail the commit";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no reader opened the FIFO within 0.2 s"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"beside.csv", "pipe.csv"}));
}

// A character device is written, never replaced: a private /dev/null takes the output, a private
// /dev/full refuses it (ENOSPC: exit 1, the other target untouched). mknod needs root (CAP_MKNOD):
// skipped without it.
TEST(OutputSet, ACharacterDeviceIsWrittenThroughNotReplaced) {
  ScratchFolder dir("outputset_device");
  const fs::path null = dir.path / "null", full = dir.path / "full";
  if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) GTEST_SKIP() << "mknod not permitted here";
  const int probe = ::open(null.c_str(), O_WRONLY);
  if (probe < 0) GTEST_SKIP() << "device nodes cannot be opened here (a nodev mount)";
  ::close(probe);
  ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0);
  io::OutputSet set;
  set.add_text(null, "discarded\n");
  set.add_text(dir.path / "kept.csv", "k\n");
  set.commit();
  EXPECT_TRUE(fs::is_character_file(null));
  EXPECT_EQ(content(dir.path / "kept.csv"), "k\n");

  io::OutputSet refused;
  refused.add_text(full, "x\n");
  refused.add_text(dir.path / "kept.csv", "new\n");
  EXPECT_THROW(refused.commit(), std::runtime_error);
  EXPECT_TRUE(fs::is_character_file(full));
  EXPECT_EQ(content(dir.path / "kept.csv"), "k\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"full", "kept.csv", "null"}));
}

// A symbolic link is followed: the file it names gets the content, the link stays. A link to
// nothing is refused before any work.
TEST(OutputSet, ASymbolicLinkIsFollowed) {
  ScratchFolder dir("outputset_link");
  fs::create_directory(dir.path / "real");
  std::ofstream(dir.path / "real" / "a.csv") << "old\n";
  fs::create_symlink("real/a.csv", dir.path / "link.csv");
  io::write_file_atomically(dir.path / "link.csv", "new\n");
  EXPECT_TRUE(fs::is_symlink(dir.path / "link.csv"));
  EXPECT_EQ(content(dir.path / "real" / "a.csv"), "new\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.csv", "real"}));

  fs::create_symlink("real/missing.csv", dir.path / "dangling.csv");
  EXPECT_THROW(io::write_file_atomically(dir.path / "dangling.csv", "x\n"), io::InputError);
  EXPECT_FALSE(fs::exists(dir.path / "real" / "missing.csv"));
}

// One file under two names (a relative and a dotted path, a link and its file) is refused before
// any work: written twice, one output would silently replace the other.
TEST(OutputSet, OneFileUnderTwoNamesIsRefused) {
  ScratchFolder dir("outputset_two_names");
  {
    io::OutputSet set;
    set.reserve(dir.path / "out.csv");
    EXPECT_THROW(set.reserve(dir.path / "." / "out.csv"), io::InputError);
  }
  std::ofstream(dir.path / "real.csv") << "old\n";
  fs::create_symlink("real.csv", dir.path / "link.csv");
  {
    io::OutputSet set;
    set.reserve(dir.path / "link.csv");
    try {
      set.reserve(dir.path / "real.csv");
      FAIL() << "a link and its file are one output";
    } catch (const io::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is the same file as the output"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(content(dir.path / "real.csv"), "old\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.csv", "real.csv"}));  // no temporary left
  io::OutputSet streams;  // a character device is a stream two outputs may share
  streams.reserve("/dev/null");
  EXPECT_NO_THROW(streams.reserve("/dev/./null"));
}

// `-o /dev/stdout` (or /dev/fd/1) with standard output redirected to a file: appended to through
// the descriptor, after what the file held, never a new file renamed over it (a job's log).
TEST(OutputSet, StandardOutputAsATargetIsAppendedToNotReplaced) {
  ScratchFolder dir("outputset_stdout_target");
  const fs::path log = dir.path / "log.txt";
  std::ofstream(log) << "before\n";
  EXPECT_EXIT(
      {
        const int fd = ::open(log.c_str(), O_WRONLY | O_APPEND);
        if (fd < 0 || ::dup2(fd, 1) < 0) std::_Exit(90);
        try {
          io::OutputSet set;
          set.add_stdout("text\n");
          set.add_text("/dev/stdout", "table\n");
          set.commit();
        } catch (...) {
          std::_Exit(4);
        }
        std::_Exit(3);
      },
      testing::ExitedWithCode(3), "");
  EXPECT_EQ(content(log), "before\ntext\ntable\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"log.txt"}));
}

// A temporary's name already taken (a stale one, another writer's) is passed over; a folder whose
// every name is taken is an error, not a loop. The names are random, so the suffix is injected.
TEST(OutputSet, ATakenTemporaryNameIsPassedOver) {
  ScratchFolder dir("outputset_taken");
  std::ofstream(dir.path / ".a.csv.tmp.stale") << "stale\n";
  int calls = 0, error = 0, slot = -1;
  const auto got = io::detail::create_temporary(
      dir.path, ".a.csv.tmp.", error, slot, [&] { return ++calls == 1 ? std::string("stale") : std::string("new"); });
  EXPECT_EQ(got, dir.path / ".a.csv.tmp.new");
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(content(dir.path / ".a.csv.tmp.stale"), "stale\n");  // the other's file untouched
  fs::remove(got);
  calls = 0;
  const auto none = io::detail::create_temporary(dir.path, ".a.csv.tmp.", error, slot, [&] {
    ++calls;
    return std::string("stale");
  });
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(error, EEXIST);
  EXPECT_EQ(calls, 100);  // the tries' bound
  EXPECT_EQ(slot, -1);    // no slot held for a name never created
}

// Standard output, flushed and checked: a full device is an exception (exit 1), not a table cut
// short with exit 0.
TEST(OutputSet, AStandardOutputWriteErrorIsAnException) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  EXPECT_EXIT(
      {
        if (!std::freopen("/dev/full", "w", stdout)) std::_Exit(90);
        try {
          io::OutputSet set;
          set.add_stdout("a table\n");
          set.commit();
        } catch (const std::runtime_error& e) {
          std::_Exit(std::string(e.what()).find("cannot write standard output: No space left on device") !=
                             std::string::npos
                         ? 3
                         : 4);
        }
        std::_Exit(5);
      },
      testing::ExitedWithCode(3), "");
}

namespace {
// A signal's disposition as the process has it.
struct sigaction disposition(int signal_number) {
  struct sigaction a {};
  ::sigaction(signal_number, nullptr, &a);
  return a;
}
bool is_default(int signal_number) {
  const struct sigaction a = disposition(signal_number);
  return (a.sa_flags & SA_SIGINFO) == 0 && a.sa_handler == SIG_DFL;
}
void host_handler(int) {}
}  // namespace

// A library call (the Python module's write_surface) leaves the host's signal handlers as it found
// them: the cleanup handler takes only default dispositions, only while a set holds temporaries;
// a host's own handler (Python's SIGINT, raising KeyboardInterrupt) is never replaced.
TEST(OutputSet, SignalHandlersOnlyWhileTemporariesAndNeverTheHosts) {
  ScratchFolder dir("outputset_handlers");
  struct sigaction host {};
  host.sa_handler = host_handler;
  ::sigemptyset(&host.sa_mask);
  struct sigaction saved {};
  ::sigaction(SIGINT, &host, &saved);
  ASSERT_TRUE(is_default(SIGTERM));
  {
    io::OutputSet outer;
    outer.reserve(dir.path / "a.csv");
    EXPECT_FALSE(is_default(SIGTERM));                         // the temporaries' cleanup
    EXPECT_EQ(disposition(SIGINT).sa_handler, &host_handler);  // the host's, untouched
    {
      io::OutputSet inner;  // a second set (another thread's): the handler stays until both are done
      inner.add_text(dir.path / "b.csv", "b\n");
      inner.commit();
    }
    EXPECT_FALSE(is_default(SIGTERM));
    outer.add_text(dir.path / "a.csv", "a\n");
    outer.commit();
  }
  EXPECT_TRUE(is_default(SIGTERM));  // restored after the last commit
  EXPECT_EQ(disposition(SIGINT).sa_handler, &host_handler);
  {
    io::OutputSet failed;  // a missing folder: refused, and the handler not left behind
    EXPECT_THROW(failed.reserve(dir.path / "missing" / "c.csv"), io::InputError);
  }
  EXPECT_TRUE(is_default(SIGTERM));
  {
    io::OutputSet discarded;  // destroyed without a commit
    discarded.reserve(dir.path / "d.csv");
  }
  EXPECT_TRUE(is_default(SIGTERM));
  ::sigaction(SIGINT, &saved, nullptr);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.csv", "b.csv"}));
}
