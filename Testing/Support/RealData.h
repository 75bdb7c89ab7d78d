// Opens the real AMR sets (Testing/Data, and ../shared/amr-data for the large one) with all
// levels and arrays, as the data README says the readers need.
#pragma once

#include "vtkAMREnzoReader.h"
#include "vtkAMReXGridReader.h"
#include "vtkDataArraySelection.h"
#include "vtkOverlappingAMR.h"
#include "vtkSmartPointer.h"

#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace amrdm_test
{

struct RealSet
{
  std::string name;
  std::string path; ///< file or plotfile folder
  bool enzo;
  std::string array; ///< a representative scalar array
};

inline bool exists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

/// The four sets; `path` is empty when a set is not available on this machine.
inline std::vector<RealSet> realSets()
{
  const char* test = std::getenv("AMRDM_TEST_DATA");
  const char* shared = std::getenv("AMRDM_SHARED_DATA");
  const std::string t = test ? test : "Testing/Data";
  const std::string s = shared ? shared : "../shared/amr-data";
  std::vector<RealSet> sets = {
    { "enzo-moving7", t + "/enzo-moving7_DD0010/moving7_0010.hierarchy", true, "Density" },
    { "amrex-flame3d", t + "/amrex-pelelmex-flame3d_plt", false, "temp" },
    { "amrex-advection", t + "/amrex-advection-amrcore3d/plt00040", false, "phi" },
    { "amrex-singlevortex-6.7M", s + "/amrex-singlevortex3d-128/plt00040", false, "phi" },
  };
  for (RealSet& set : sets)
  {
    if (!exists(set.path))
      set.path.clear();
  }
  return sets;
}

inline vtkSmartPointer<vtkOverlappingAMR> readSet(const RealSet& set)
{
  vtkSmartPointer<vtkOverlappingAMR> out;
  auto configure = [&](auto* reader)
  {
    reader->SetFileName(set.path.c_str());
    reader->UpdateInformation();
    reader->SetMaxLevel(1000);
    reader->GetCellDataArraySelection()->EnableAllArrays();
    reader->Update();
    out = vtkOverlappingAMR::SafeDownCast(reader->GetOutputDataObject(0));
  };
  if (set.enzo)
  {
    vtkNew<vtkAMREnzoReader> reader;
    configure(reader.Get());
  }
  else
  {
    vtkNew<vtkAMReXGridReader> reader;
    configure(reader.Get());
  }
  return out;
}

} // namespace amrdm_test
