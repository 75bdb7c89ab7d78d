// Host-side parallel loop over [0, n) on the persistent thread pool (ThreadPool.h). Work is
// handed out dynamically but every item writes only its own outputs, so results never depend on
// the thread count. A parallelFor inside another one's body runs inline on its thread.
#pragma once

#include "core/ThreadPool.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace amrdm
{

/// Number of worker threads to use: `requested` if > 0, else the hardware concurrency.
inline int resolveThreadCount(int requested)
{
  if (requested > 0)
  {
    return requested;
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

/// Calls body(i) for every i in [0, n) on up to `threads` threads (0 = all cores): the calling
/// thread and workers of ThreadPool::instance(). The first exception thrown by any body is
/// rethrown on the calling thread after all workers stopped; the items not started by then are
/// skipped. Called from inside a body (nested), it runs on the calling thread alone.
template<typename Body>
void parallelFor(std::size_t n, int threads, Body&& body)
{
  const int numThreads = static_cast<int>(
    std::min<std::size_t>(static_cast<std::size_t>(resolveThreadCount(threads)), n));
  if (numThreads <= 1 || ThreadPool::insideJob())
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      body(i);
    }
    return;
  }
  std::atomic<std::size_t> next{ 0 };
  std::exception_ptr failure;
  std::mutex failureMutex;
  const std::function<void()> worker = [&]()
  {
    for (std::size_t i = next++; i < n; i = next++)
    {
      try
      {
        body(i);
      }
      catch (...)
      {
        std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure)
        {
          failure = std::current_exception();
        }
        next = n;
      }
    }
  };
  ThreadPool::instance().run(numThreads, worker);
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}

} // namespace amrdm
