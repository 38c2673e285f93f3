// The pool the fidelities share their positions out with (contact/position_threads.hpp): every item
// done once and the progress counted from the calling thread, the threads clamped to 1..count, and
// the first exception rethrown only after every thread has joined.
#include "contact/position_threads.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace geartrib::contact;

namespace {

// The threads run_in_threads starts for `threads` asked and `count` items: the work's calls.
int threads_run(int threads, int count) {
  std::atomic<int> calls{0};
  run_in_threads(threads, count, [&](ThreadItems& items) {
    ++calls;
    for (int i = items.take(); i >= 0; i = items.take()) items.finished();
  });
  return calls;
}

}  // namespace

TEST(PositionThreads, EveryItemDoneOnceWithProgressFromTheCallingThread) {
  constexpr int kCount = 1000;
  std::vector<std::atomic<int>> done(kCount);
  std::mutex seen_lock;
  std::set<std::thread::id> seen;
  std::vector<int> reported;
  const std::thread::id caller = std::this_thread::get_id();
  bool reported_elsewhere = false;
  run_in_threads(
      4, kCount,
      [&](ThreadItems& items) {
        {
          const std::lock_guard lock(seen_lock);
          seen.insert(std::this_thread::get_id());
        }
        for (int i = items.take(); i >= 0; i = items.take()) {
          ++done[static_cast<std::size_t>(i)];
          items.finished();
        }
      },
      [&](int finished, int total) {
        EXPECT_EQ(total, kCount);
        reported_elsewhere = reported_elsewhere || std::this_thread::get_id() != caller;
        reported.push_back(finished);
      });
  for (const auto& d : done) EXPECT_EQ(d, 1);
  EXPECT_EQ(seen.size(), 4u);  // four threads, the caller one of them
  EXPECT_TRUE(seen.count(caller));
  EXPECT_FALSE(reported_elsewhere);  // progress only from the calling thread: no lock needed in it
  ASSERT_FALSE(reported.empty());
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  EXPECT_EQ(reported.back(), kCount);  // the last report: all done
}

TEST(PositionThreads, ThreadsClampedToOneToCount) {
  EXPECT_EQ(threads_run(8, 3), 3);  // no more threads than items
  EXPECT_EQ(threads_run(0, 5), 1);  // at least one
  EXPECT_EQ(threads_run(-2, 5), 1);
  EXPECT_EQ(threads_run(4, 0), 1);  // no items: the caller's alone, which takes none
  EXPECT_EQ(threads_run(2, 5), 2);
  geartrib::ContactSettings cs;
  cs.threads = 3;
  EXPECT_EQ(position_threads(cs, 2), 2);
  EXPECT_EQ(position_threads(cs, 10), 3);
  EXPECT_EQ(position_threads(cs, 0), 1);
  cs.threads = 0;  // the hardware's
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  EXPECT_EQ(position_threads(cs, 1000), std::min(hardware, 1000));
}

TEST(PositionThreads, FirstExceptionRethrownAfterAllThreadsJoin) {
  // Item 0 throws at once; the other thread's items take 1 ms each, so it is still taking items
  // when the failure lands (its 999 items would take a second), sees take() end, and throws later.
  constexpr int kCount = 1000;
  std::atomic<int> taken{0}, ended{0};
  try {
    run_in_threads(2, kCount, [&](ThreadItems& items) {
      for (int i = items.take(); i >= 0; i = items.take()) {
        ++taken;
        if (i == 0) throw std::runtime_error("first");
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        items.finished();
      }
      ++ended;
      throw std::logic_error("later");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "first");
  }
  EXPECT_EQ(ended, 1);       // the other thread ran to its end before the rethrow
  EXPECT_LT(taken, kCount);  // and took no more items once the failure was recorded
  // One thread: the exception passes through unchanged, no progress at the end.
  bool reported_all = false;
  EXPECT_THROW(run_in_threads(
                   1, 3, [](ThreadItems&) { throw std::invalid_argument("refused"); },
                   [&](int done, int total) { reported_all = reported_all || done == total; }),
               std::invalid_argument);
  EXPECT_FALSE(reported_all);
}
