// Cancellation of a running render pass, shared by the CPU and CUDA renderers. cancel() stops the
// pass that is running when it is called and nothing else: a request while no pass runs is
// dropped, so a late request (the pass ended between the caller's check and its cancel()) never
// stops the next pass. The caller that wants a pass stopped (the VTK mapper polling
// vtkRenderWindow::CheckAbortStatus from the thread that started the pass) asks repeatedly while
// it wants it stopped. Workers read requested() between tiles; tilesDone() is the progress of
// the running pass. Host code.
#pragma once

#include <atomic>
#include <cstddef>
#include <mutex>

namespace amrdm
{

class PassCancellation
{
public:
  /// Marks a pass as running (clears any earlier request and the progress).
  void begin()
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Running = true;
    this->Requested.store(false, std::memory_order_relaxed);
    this->Done.store(0, std::memory_order_relaxed);
  }
  /// Ends the running pass; true when it was asked to stop while it ran.
  bool end()
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Running = false;
    const bool stopped = this->Requested.load(std::memory_order_relaxed);
    this->Requested.store(false, std::memory_order_relaxed);
    return stopped;
  }
  /// Asks the running pass to stop (thread safe); no effect when no pass runs.
  void request()
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    if (this->Running)
    {
      this->Requested.store(true, std::memory_order_relaxed);
    }
  }
  /// Whether the running pass was asked to stop (read by the workers between tiles).
  bool requested() const { return this->Requested.load(std::memory_order_relaxed); }
  /// Work items (tiles) the running pass has finished.
  void addDone(std::size_t n = 1) { this->Done.fetch_add(n, std::memory_order_relaxed); }
  std::size_t tilesDone() const { return this->Done.load(std::memory_order_relaxed); }

private:
  std::mutex Mutex;
  bool Running = false;
  std::atomic<bool> Requested{ false };
  std::atomic<std::size_t> Done{ 0 };
};

} // namespace amrdm
