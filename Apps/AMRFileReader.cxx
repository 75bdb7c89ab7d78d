#include "AMRFileReader.h"

#include "AMRDualMeshVTKCompat.h"

#include "vtkAMRDualMeshFileCheck.h"
#include "vtkAMREnzoReader.h"
#include "vtkAMReXGridReader.h"
#include "vtkDataArraySelection.h"
#include "vtkNew.h"
#include "vtkOverlappingAMR.h"
#include "vtkXMLUniformGridAMRReader.h"

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <errno.h> // program_invocation_short_name (GNU)
#include <exception>
#include <mutex>
#include <thread>
#include <unistd.h>

namespace amrdm_app
{
namespace
{
bool endsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Enzo and AMReX readers load level 0 and no arrays by default: ask for everything.
template<typename Reader>
vtkSmartPointer<vtkOverlappingAMR> readAll(const std::string& path)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->SetMaxLevel(1 << 20);
  reader->GetCellDataArraySelection()->EnableAllArrays();
  reader->Update();
  return vtkOverlappingAMR::SafeDownCast(reader->GetOutputDataObject(0));
}

vtkSmartPointer<vtkOverlappingAMR> readWithVTK(const std::string& path, bool folder)
{
  if (folder)
    return readAll<vtkAMReXGridReader>(path);
  if (endsWith(path, ".hierarchy") || endsWith(path, ".boundary"))
    return readAll<vtkAMREnzoReader>(path);
  vtkNew<vtkXMLUniformGridAMRReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetMaximumLevelsToReadByDefault(0); // 0 = all levels
  reader->Update();
  return vtkOverlappingAMR::SafeDownCast(reader->GetOutputDataObject(0));
}

// --- The last guards: a fatal signal inside the reader ----------------------------------------
char crashMessage[4096];
std::size_t crashSplit = 0; // where the signal number goes
const int guardedSignals[] = { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT };
struct sigaction previous[sizeof(guardedSignals) / sizeof(int)];

void onFatalSignal(int sig)
{
  // Only async-signal-safe calls: write(2) and _exit(2).
  char digits[4] = { char('0' + (sig / 10) % 10), char('0' + sig % 10), ')', ' ' };
  ssize_t ignored = write(2, crashMessage, crashSplit);
  ignored = write(2, digits, 4);
  ignored = write(2, crashMessage + crashSplit, std::strlen(crashMessage + crashSplit));
  (void)ignored;
  _exit(1);
}

class CrashGuard
{
public:
  explicit CrashGuard(const std::string& path)
  {
    const std::string head = std::string(program_invocation_short_name) + ": '" + path +
                             "': VTK's reader crashed (signal ";
    const std::string tail = "while reading it: the file is damaged in a way the file check "
                             "does not detect\n";
    std::snprintf(crashMessage, sizeof(crashMessage), "%s%s", head.c_str(), tail.c_str());
    crashSplit = std::min(head.size(), sizeof(crashMessage) - 1);
    static char altStack[1 << 16];
    stack_t ss{};
    ss.ss_sp = altStack;
    ss.ss_size = sizeof(altStack);
    sigaltstack(&ss, nullptr);
    struct sigaction sa
    {
    };
    sa.sa_handler = onFatalSignal;
    sa.sa_flags = SA_ONSTACK | SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    for (std::size_t i = 0; i < sizeof(guardedSignals) / sizeof(int); ++i)
      sigaction(guardedSignals[i], &sa, &previous[i]);
  }
  ~CrashGuard()
  {
    for (std::size_t i = 0; i < sizeof(guardedSignals) / sizeof(int); ++i)
      sigaction(guardedSignals[i], &previous[i], nullptr);
  }
  CrashGuard(const CrashGuard&) = delete;
  CrashGuard& operator=(const CrashGuard&) = delete;
};

// --- The watchdog: a reader that does not return --------------------------------------------
class Watchdog
{
public:
  Watchdog(const std::string& path, double seconds)
    : Thread(
        [this, path, seconds]
        {
          std::unique_lock<std::mutex> lock(this->Mutex);
          if (this->Done.wait_for(
                lock, std::chrono::duration<double>(seconds), [this] { return this->Finished; }))
            return;
          std::fprintf(stderr,
            "%s: '%s': VTK's reader did not finish within %g s (the file may be damaged; set "
            "AMRDM_READ_TIMEOUT=seconds to allow longer)\n",
            program_invocation_short_name,
            path.c_str(),
            seconds);
          std::fflush(stderr);
          _exit(1);
        })
  {
  }
  ~Watchdog()
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Finished = true;
    }
    this->Done.notify_all();
    this->Thread.join();
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

private:
  std::mutex Mutex;
  std::condition_variable Done;
  bool Finished = false;
  std::thread Thread;
};
}

vtkSmartPointer<vtkOverlappingAMR> ReadAMRFile(const std::string& path, std::string& error)
{
  vtkNew<vtkAMRDualMeshFileCheck> check;
  if (!check->CheckFile(path))
  {
    error = check->GetError();
    return nullptr;
  }
  vtkSmartPointer<vtkOverlappingAMR> amr;
  {
    Watchdog watchdog(path, check->GetReadTimeoutSeconds());
    CrashGuard guard(path);
    try
    {
      amr = readWithVTK(path, check->GetFormat() == "amrex");
    }
    catch (const std::exception& e)
    {
      error = "'" + path + "': VTK's reader failed: " + e.what();
      return nullptr;
    }
  }
  if (!amr || amrdm_vtk::amrcompat::NumberOfLevels(amr) == 0)
  {
    error = "'" + path + "' could not be read as a vtkOverlappingAMR with at least one level";
    return nullptr;
  }
  error = check->CheckOutput(amr);
  if (!error.empty())
    return nullptr;
  if (!check->GetWarning().empty())
    std::fprintf(
      stderr, "%s: warning: %s\n", program_invocation_short_name, check->GetWarning().c_str());
  return amr;
}
}
