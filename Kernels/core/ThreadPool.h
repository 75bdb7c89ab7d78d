// A persistent pool of worker threads behind parallelFor (ParallelFor.h). Workers start on first
// need (as many as the largest job asked for, less the calling thread, which always takes part)
// and then wait on a condition variable for the next job, so a render of many passes creates
// threads once, not once per pass. One job at a time: a second thread calling run() waits until
// the job in flight is done. A run() from inside a job (a worker, or the calling thread while it
// takes part) runs the job on that thread alone, so nested parallel loops cannot deadlock.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace amrdm
{

class ThreadPool
{
public:
  /// The process's pool (constructed on first use, its workers joined at exit).
  static ThreadPool& instance()
  {
    static ThreadPool pool;
    return pool;
  }

  /// Runs job() on `threads` threads at once, the calling thread and threads - 1 workers, and
  /// returns when every one of them has returned. threads <= 1, or a call from inside a job,
  /// runs job() once on the calling thread. job must not throw (parallelFor catches for it).
  void run(int threads, const std::function<void()>& job)
  {
    if (threads <= 1 || insideJob())
    {
      job();
      return;
    }
    std::lock_guard<std::mutex> oneJob(this->JobMutex);
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      while (static_cast<int>(this->Workers.size()) < threads - 1)
      {
        const int index = static_cast<int>(this->Workers.size());
        this->Workers.emplace_back([this, index] { this->workerLoop(index); });
      }
      this->Job = &job;
      this->Wanted = threads - 1;
      this->Pending = threads - 1;
      ++this->Generation;
    }
    this->Wake.notify_all();
    {
      InsideJob inside;
      job();
    }
    std::unique_lock<std::mutex> lock(this->Mutex);
    this->Done.wait(lock, [this] { return this->Pending == 0; });
    this->Job = nullptr;
  }

  /// Whether the calling thread is running a job of the pool (as a worker or as the caller).
  static bool insideJob() { return insideFlag(); }

  /// Workers started so far (the calling thread of a job is not one of them).
  int workerCount() const
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    return static_cast<int>(this->Workers.size());
  }

  /// The workers' thread ids, in start order.
  std::vector<std::thread::id> workerIds() const
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    std::vector<std::thread::id> ids;
    ids.reserve(this->Workers.size());
    for (const std::thread& worker : this->Workers)
    {
      ids.push_back(worker.get_id());
    }
    return ids;
  }

  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  ~ThreadPool()
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Stop = true;
    }
    this->Wake.notify_all();
    for (std::thread& worker : this->Workers)
    {
      worker.join();
    }
  }

private:
  ThreadPool() = default;

  static bool& insideFlag()
  {
    thread_local bool inside = false;
    return inside;
  }

  /// Marks the calling thread as inside a job for its lifetime.
  struct InsideJob
  {
    InsideJob() { insideFlag() = true; }
    ~InsideJob() { insideFlag() = false; }
    InsideJob(const InsideJob&) = delete;
    InsideJob& operator=(const InsideJob&) = delete;
  };

  /// Worker `index` takes part in every job that wants more than `index` workers. A job cannot
  /// finish without each of its workers, so none of them misses a generation it belongs to.
  void workerLoop(int index)
  {
    InsideJob inside;
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(this->Mutex);
    for (;;)
    {
      this->Wake.wait(lock, [&] { return this->Stop || this->Generation != seen; });
      if (this->Stop)
      {
        return;
      }
      seen = this->Generation;
      if (index >= this->Wanted)
      {
        continue;
      }
      const std::function<void()>* job = this->Job;
      lock.unlock();
      (*job)();
      lock.lock();
      if (--this->Pending == 0)
      {
        this->Done.notify_one();
      }
    }
  }

  std::mutex JobMutex;      ///< held by run() for a whole job: one job at a time
  mutable std::mutex Mutex; ///< guards everything below
  std::condition_variable Wake;
  std::condition_variable Done;
  std::vector<std::thread> Workers;
  const std::function<void()>* Job = nullptr;
  int Wanted = 0;  ///< workers taking part in the current job (indices below it)
  int Pending = 0; ///< of those, the ones not finished yet
  std::uint64_t Generation = 0;
  bool Stop = false;
};

} // namespace amrdm
