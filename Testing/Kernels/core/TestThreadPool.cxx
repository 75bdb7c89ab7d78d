// parallelFor on the persistent pool (core/ParallelFor.h, core/ThreadPool.h): the same worker
// threads (kernel thread ids) serve every call; every item runs exactly once and results are
// bit-identical for any thread count; the first exception reaches the caller and the pool still
// works afterwards; a nested parallelFor runs inline on its body's thread instead of
// deadlocking; two threads calling at once are both served.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "core/ParallelFor.h"
#include "core/Random.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <sys/syscall.h>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace amrdm;

namespace
{
/// The kernel's thread id: unlike std::thread::id (a pthread_t, whose memory glibc reuses for the
/// next thread), a new thread never gets the id of one that just ended.
long kernelThreadId()
{
  return static_cast<long>(::syscall(SYS_gettid));
}

/// Runs `threads` items on `threads` threads, each item waiting until all have started (so each
/// thread holds exactly one), and returns the kernel ids of the threads that ran them. A pool
/// that cannot run them all at once stops waiting after 60 s and the ids are then fewer.
std::set<long> idsOfOneCall(int threads)
{
  std::atomic<int> started{ 0 };
  std::mutex m;
  std::set<long> ids;
  parallelFor(static_cast<std::size_t>(threads),
    threads,
    [&](std::size_t)
    {
      {
        std::lock_guard<std::mutex> lock(m);
        ids.insert(kernelThreadId());
      }
      ++started;
      const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(60);
      while (started.load() < threads && std::chrono::steady_clock::now() < giveUp)
      {
        std::this_thread::yield();
      }
    });
  return ids;
}

/// A per-item value from the item's own random stream, so a wrong item-to-output mapping or a
/// skipped or repeated item changes the result.
std::vector<double> itemValues(std::size_t n, int threads, std::vector<int>& runs)
{
  std::vector<double> out(n, -1.0);
  std::vector<std::atomic<int>> counts(n);
  parallelFor(n,
    threads,
    [&](std::size_t i)
    {
      Rng rng(i, 17u, 0u);
      double s = 0.0;
      for (int k = 0; k < 64; ++k)
      {
        s += rng.next() * double(k + 1);
      }
      out[i] = s;
      ++counts[i];
    });
  runs.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    runs[i] = counts[i].load();
  }
  return out;
}
} // namespace

TEST_CASE("the same worker threads serve every call")
{
  const long caller = kernelThreadId();
  const std::set<long> first = idsOfOneCall(4);
  const std::set<long> second = idsOfOneCall(4);
  const std::set<long> third = idsOfOneCall(3);
  CHECK(first.size() == 4);
  CHECK(first.count(caller) == 1);
  CHECK(second == first);
  CHECK(std::includes(first.begin(), first.end(), third.begin(), third.end()));
  CHECK(ThreadPool::instance().workerCount() == 3);
  // A larger job adds workers and keeps the old ones.
  const std::set<long> wider = idsOfOneCall(6);
  CHECK(wider.size() == 6);
  CHECK(std::includes(wider.begin(), wider.end(), first.begin(), first.end()));
  CHECK(ThreadPool::instance().workerCount() == 5);
  CHECK(ThreadPool::instance().workerIds().size() == 5);
}

TEST_CASE("every item once, results independent of the thread count")
{
  const std::size_t n = 10007;
  std::vector<int> runs;
  const std::vector<double> serial = itemValues(n, 1, runs);
  CHECK(std::count(runs.begin(), runs.end(), 1) == static_cast<long>(n));
  for (int threads : { 2, 3, 8, 0, 64 })
  {
    CAPTURE(threads);
    const std::vector<double> parallel = itemValues(n, threads, runs);
    CHECK(std::count(runs.begin(), runs.end(), 1) == static_cast<long>(n));
    CHECK(parallel == serial);
  }
  // Fewer items than threads, and none.
  CHECK(itemValues(3, 8, runs) == std::vector<double>(serial.begin(), serial.begin() + 3));
  CHECK(itemValues(0, 8, runs).empty());
}

TEST_CASE("the first exception reaches the caller; the pool works afterwards")
{
  for (int threads : { 1, 4 })
  {
    CAPTURE(threads);
    std::atomic<int> ran{ 0 };
    CHECK_THROWS_WITH_AS(parallelFor(1000,
                           threads,
                           [&](std::size_t i)
                           {
                             ++ran;
                             if (i == 37)
                             {
                               throw std::runtime_error("item 37 failed");
                             }
                           }),
      "item 37 failed",
      std::runtime_error);
    CHECK(ran.load() >= 38);
    if (threads == 1)
    {
      CHECK(ran.load() == 38); // serially, the items after the failure are skipped
    }
    // Every body throws: one of their exceptions, not a crash or a hang.
    CHECK_THROWS_AS(
      parallelFor(64, threads, [](std::size_t i) { throw std::out_of_range(std::to_string(i)); }),
      std::out_of_range);
    std::vector<int> runs;
    itemValues(500, threads, runs);
    CHECK(std::count(runs.begin(), runs.end(), 1) == 500);
  }
}

TEST_CASE("a nested parallelFor runs inline on its body's thread")
{
  const std::size_t outer = 16, inner = 32;
  std::vector<std::atomic<int>> marks(outer * inner);
  std::atomic<int> foreign{ 0 };
  parallelFor(outer,
    4,
    [&](std::size_t i)
    {
      const long self = kernelThreadId();
      parallelFor(inner,
        4,
        [&](std::size_t j)
        {
          ++marks[i * inner + j];
          if (kernelThreadId() != self)
          {
            ++foreign;
          }
        });
    });
  int once = 0;
  for (const std::atomic<int>& m : marks)
  {
    once += m.load() == 1 ? 1 : 0;
  }
  CHECK(once == static_cast<int>(outer * inner));
  CHECK(foreign.load() == 0);
  // An exception from a nested loop reaches the outermost caller.
  CHECK_THROWS_WITH(parallelFor(8,
                      4,
                      [](std::size_t i)
                      {
                        parallelFor(8,
                          4,
                          [i](std::size_t j)
                          {
                            if (i == 5 && j == 6)
                            {
                              throw std::runtime_error("inner 5/6");
                            }
                          });
                      }),
    "inner 5/6");
}

TEST_CASE("two threads calling at once are both served")
{
  std::vector<double> a, b;
  std::vector<int> runsA, runsB;
  std::thread other([&] { a = itemValues(20000, 4, runsA); });
  b = itemValues(20000, 4, runsB);
  other.join();
  CHECK(a == b);
  CHECK(std::count(runsA.begin(), runsA.end(), 1) == 20000);
  CHECK(std::count(runsB.begin(), runsB.end(), 1) == 20000);
}
