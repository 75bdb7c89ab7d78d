#include "AMRFileReader.h"

#include "vtkAMREnzoReader.h"
#include "vtkAMReXGridReader.h"
#include "vtkDataArraySelection.h"
#include "vtkOverlappingAMR.h"
#include "vtkXMLUniformGridAMRReader.h"

#include <sys/stat.h>

namespace amrdm_app
{
namespace
{
bool endsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
bool isDirectory(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}
bool exists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0;
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
}

vtkSmartPointer<vtkOverlappingAMR> ReadAMRFile(const std::string& path, std::string& error)
{
  if (!exists(path))
  {
    error = "'" + path + "' does not exist";
    return nullptr;
  }
  vtkSmartPointer<vtkOverlappingAMR> amr;
  if (isDirectory(path))
  {
    if (!exists(path + "/Header"))
    {
      error = "'" + path + "' is a folder without a Header file; expected an AMReX plotfile";
      return nullptr;
    }
    amr = readAll<vtkAMReXGridReader>(path);
  }
  else if (endsWith(path, ".hierarchy") || endsWith(path, ".boundary"))
  {
    amr = readAll<vtkAMREnzoReader>(path);
  }
  else if (endsWith(path, ".vthb") || endsWith(path, ".vth"))
  {
    vtkNew<vtkXMLUniformGridAMRReader> reader;
    reader->SetFileName(path.c_str());
    reader->SetMaximumLevelsToReadByDefault(0); // 0 = all levels
    reader->Update();
    amr = vtkOverlappingAMR::SafeDownCast(reader->GetOutputDataObject(0));
  }
  else
  {
    error = "'" + path +
            "' is not a supported AMR file; expected an Enzo .hierarchy, an AMReX "
            "plotfile folder or a .vthb file";
    return nullptr;
  }
  if (!amr || amr->GetNumberOfLevels() == 0)
  {
    error = "'" + path + "' could not be read as a vtkOverlappingAMR with at least one level";
    return nullptr;
  }
  return amr;
}
}
