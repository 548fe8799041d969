#pragma once
// A buffer kept per thread and reused across calls, so a query allocates only while the buffer grows to the largest
// size a call on that thread has needed. A nested use on the same thread (a user callback that runs another query
// while the buffer is in use) gets a buffer of its own for that call.
#include <vector>

namespace gq::detail {

template <class E> class ThreadScratch {
 public:
  ThreadScratch() : items_(acquire()) {}
  ~ThreadScratch() {
    if (&items_ == &pool().items) pool().busy = false;
  }
  ThreadScratch(const ThreadScratch&) = delete;
  ThreadScratch& operator=(const ThreadScratch&) = delete;

  // Empty on construction.
  std::vector<E>& get() { return items_; }

 private:
  struct Pool {
    std::vector<E> items;
    bool busy = false;
  };
  static Pool& pool() {
    thread_local Pool p;
    return p;
  }
  std::vector<E>& acquire() {
    Pool& p = pool();
    if (p.busy) return own_;
    p.busy = true;
    p.items.clear();
    return p.items;
  }

  std::vector<E> own_;
  std::vector<E>& items_;
};

}  // namespace gq::detail
