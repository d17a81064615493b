// SPDX-License-Identifier: GPL-3.0-or-later
//
// Loops spread over threads with oneTBB when the package is built with it
// (CGAL_LINKED_WITH_TBB, as CGAL's own parallel code), plain loops otherwise.
// A caller's result must not depend on the number of threads: the work of an
// index may use the scratch space of the worker that runs it, never anything
// another index writes, and the results are combined afterwards in index order.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_PARALLEL_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_PARALLEL_H

#include <algorithm>
#include <cstddef>
#include <memory>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

class Thread_pool
{
public:
  /// `threads` workers, at most one per core (more would only wait), 0 for
  /// one per core; one without oneTBB.
  explicit Thread_pool(int threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    const int cores = tbb::this_task_arena::max_concurrency();
    workers_ = threads > 0 ? (std::min)(threads, cores) : cores;
    if(workers_ > 1) arena_ = std::make_unique<tbb::task_arena>(workers_);
#else
    (void)threads;
#endif
  }

  /// The number of workers; `for_each` passes a worker index below it.
  int workers() const { return workers_; }

  /// Runs f() in the pool: the loops it runs start without waking the
  /// workers again (many short loops in a row stay cheap).
  template <typename Function>
  void execute(const Function& f)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(arena_ && !inside_) {
      arena_->execute([&] {
        inside_ = true;
        try {
          f();
        } catch(...) {
          inside_ = false;
          throw;
        }
        inside_ = false;
      });
      return;
    }
#endif
    f();
  }

  /// Calls f(i, worker) for every i in [0, n).
  template <typename Function>
  void for_each(std::size_t n, const Function& f)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(arena_ && n > 1) {
      execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
          const int worker = tbb::this_task_arena::current_thread_index();
          for(std::size_t i = r.begin(); i != r.end(); ++i) f(i, worker);
        });
      });
      return;
    }
#endif
    for(std::size_t i = 0; i < n; ++i) f(i, 0);
  }

  /// Calls f() and g(), side by side when there are workers.
  template <typename F, typename G>
  void invoke(const F& f, const G& g)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(arena_) {
      execute([&] { tbb::parallel_invoke(f, g); });
      return;
    }
#endif
    f();
    g();
  }

private:
  int workers_ = 1;
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::task_arena> arena_;
  bool inside_ = false;
#endif
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_PARALLEL_H
