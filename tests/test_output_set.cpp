// Output sets: every output of a command or none. A failing writer, a missing folder and a signal
// leave the targets as they were and no temporary behind.
#include "io/input_error.hpp"
#include "io/table_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

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
