// The threads a mesh's positions are solved on, and the pool that shares the positions out among
// them: the deterministic fidelity's strips and the mixed-EHL fidelity's windows.
#pragma once

#include "contact/contact_options.hpp"

#include <functional>

namespace geartrib::contact {

// The threads a run solves its positions on: contact.threads, or the hardware's when 0, at least 1
// and at most one a position.
int position_threads(const ContactSettings& cs, int positions);

// One thread's hand in run_in_threads: the items it takes, one at a time, and those it finishes.
class ThreadItems {
 public:
  struct Shared;  // the items' counters and the failure, one for all the threads
  ThreadItems(Shared& shared, bool reports) : shared_(shared), reports_(reports) {}
  // The next item no thread has taken; -1 once all are taken or a thread has thrown.
  int take();
  // The item taken last is done: counted, and progress(done, count) when this is the calling thread.
  void finished();

 private:
  Shared& shared_;
  bool reports_;
};

// Runs work(items) on `threads` threads (clamped to 1..count), the calling thread one of them; the
// work loops `for (int i = items.take(); i >= 0; i = items.take())` over the items 0..count-1, each
// taken by one thread once. The first exception a thread throws stops the others taking items and
// is rethrown once all have joined; otherwise progress(count, count) at the end.
void run_in_threads(int threads, int count, const std::function<void(ThreadItems&)>& work,
                    const std::function<void(int, int)>& progress = {});

}  // namespace geartrib::contact
