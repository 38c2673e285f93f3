#include "contact/position_threads.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace geartrib::contact {

int position_threads(const ContactSettings& cs, int positions) {
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return std::clamp(cs.threads > 0 ? cs.threads : hardware, 1, std::max(1, positions));
}

struct ThreadItems::Shared {
  int count = 0;
  const std::function<void(int, int)>* progress = nullptr;
  std::atomic<int> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;  // guards failure
  std::exception_ptr failure;
};

int ThreadItems::take() {
  const int i = shared_.next++;
  return i < shared_.count && !shared_.failed ? i : -1;
}

void ThreadItems::finished() {
  const int done = ++shared_.done;
  if (reports_ && *shared_.progress) (*shared_.progress)(done, shared_.count);
}

void run_in_threads(int threads, int count, const std::function<void(ThreadItems&)>& work,
                    const std::function<void(int, int)>& progress) {
  ThreadItems::Shared shared;
  shared.count = count;
  shared.progress = &progress;
  auto run = [&](bool reports) {
    ThreadItems items(shared, reports);
    try {
      work(items);
    } catch (...) {
      const std::lock_guard lock(shared.mutex);
      if (!shared.failure) shared.failure = std::current_exception();
      shared.failed = true;
    }
  };
  std::vector<std::jthread> pool;  // joined on the way out should a thread fail to start
  for (int t = 1; t < std::clamp(threads, 1, std::max(1, count)); ++t) pool.emplace_back(run, false);
  run(true);
  for (auto& t : pool) t.join();
  if (shared.failure) std::rethrow_exception(shared.failure);
  if (progress) progress(count, count);
}

}  // namespace geartrib::contact
