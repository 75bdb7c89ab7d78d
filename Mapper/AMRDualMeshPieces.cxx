#include "AMRDualMeshPieces.h"
#include "AMRDualMeshVTKCompat.h"

#include "vtkCellData.h"
#include "vtkAMRBox.h"
#include "vtkDataArray.h"
#include "vtkOverlappingAMR.h"
#include "vtkImageData.h"

#include <cstdint>
#include <string>

namespace amrdm_vtk
{
namespace
{
template<typename T>
void Put(std::vector<char>& buffer, const T& value)
{
  const char* p = reinterpret_cast<const char*>(&value);
  buffer.insert(buffer.end(), p, p + sizeof(T));
}

}

bool LoadedBlock(vtkOverlappingAMR* amr,
  unsigned level,
  unsigned id,
  int blo[3],
  int bdims[3],
  std::string& error)
{
  error.clear();
  vtkImageData* grid = nullptr;
  if (amrcompat::BlockAt(amr, level, id, grid) == amrcompat::BlockState::Unsupported)
  {
    error = amrcompat::UnsupportedBlockMessage(amr, level, id);
    return false;
  }
  const vtkAMRBox& box = amrcompat::Box(amr, level, id);
  if (!grid || box.IsInvalid())
  {
    return false;
  }
  int gdims[3];
  grid->GetDimensions(gdims);
  for (int d = 0; d < 3; ++d)
  {
    blo[d] = box.GetLoCorner()[d];
    bdims[d] = box.GetHiCorner()[d] - blo[d] + 1;
    if (gdims[d] - 1 != bdims[d])
    {
      error = "level " + std::to_string(level) + " block " + std::to_string(id) + " has " +
              std::to_string(gdims[d] - 1) + " cells on axis " + std::to_string(d) +
              " but its AMR box says " + std::to_string(bdims[d]) +
              "; expected a 3D grid that matches its box";
      return false;
    }
  }
  return true;
}

void PackPiece(std::vector<char>& buffer,
  unsigned level,
  vtkImageData* grid,
  const int blo[3],
  const int bdims[3],
  const int lo[3],
  const int hi[3])
{
  vtkCellData* cd = grid->GetCellData();
  std::vector<vtkDataArray*> arrays;
  for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = cd->GetArray(a);
    if (array && array->GetName() && array->GetNumberOfTuples() == grid->GetNumberOfCells())
    {
      arrays.push_back(array);
    }
  }
  Put<std::int32_t>(buffer, static_cast<std::int32_t>(level));
  for (int d = 0; d < 3; ++d)
  {
    Put<std::int32_t>(buffer, lo[d]);
  }
  for (int d = 0; d < 3; ++d)
  {
    Put<std::int32_t>(buffer, hi[d] - lo[d]);
  }
  Put<std::int32_t>(buffer, static_cast<std::int32_t>(arrays.size()));
  for (vtkDataArray* array : arrays)
  {
    const std::string name = array->GetName();
    Put<std::int32_t>(buffer, static_cast<std::int32_t>(name.size()));
    buffer.insert(buffer.end(), name.begin(), name.end());
    const int comps = array->GetNumberOfComponents();
    const std::size_t elem = static_cast<std::size_t>(array->GetDataTypeSize()) * comps;
    Put<std::int32_t>(buffer, array->GetDataType());
    Put<std::int32_t>(buffer, comps);
    const std::size_t row = elem * static_cast<std::size_t>(hi[0] - lo[0]);
    Put<std::uint64_t>(buffer, row * (hi[1] - lo[1]) * (hi[2] - lo[2]));
    const char* src = static_cast<const char*>(array->GetVoidPointer(0));
    for (int z = lo[2]; z < hi[2]; ++z)
    {
      for (int y = lo[1]; y < hi[1]; ++y)
      {
        const std::size_t cell =
          (static_cast<std::size_t>(z - blo[2]) * bdims[1] + (y - blo[1])) * bdims[0] +
          (lo[0] - blo[0]);
        buffer.insert(buffer.end(), src + cell * elem, src + cell * elem + row);
      }
    }
  }
}
}
