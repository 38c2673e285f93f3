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
