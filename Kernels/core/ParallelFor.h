// Host-side parallel loop over [0, n) in chunks, on std::thread. Work is handed out dynamically
// but every chunk writes only its own outputs, so results never depend on the thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

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

/// Calls body(i) for every i in [0, n) on up to `threads` threads (0 = all cores). The first
/// exception thrown by any body is rethrown on the calling thread after all workers stopped.
template<typename Body>
void parallelFor(std::size_t n, int threads, Body&& body)
{
  const int numThreads = static_cast<int>(
    std::min<std::size_t>(static_cast<std::size_t>(resolveThreadCount(threads)), n));
  if (numThreads <= 1)
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
  auto worker = [&]()
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
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(numThreads - 1));
  for (int t = 1; t < numThreads; ++t)
  {
    pool.emplace_back(worker);
  }
  worker();
  for (auto& thread : pool)
  {
    thread.join();
  }
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}

} // namespace amrdm
