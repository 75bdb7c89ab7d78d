#include "vtkAMRDualMeshToUnstructuredGrid.h"

#include "AMRDualMeshVtkCells.h"
#include "vtkAMRDualMesh.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkOverlappingAMR.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "mesh/DualMesh.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace
{

/// Points merged on their exact grid position (twice the finest-grid coordinates, integers).
class PointTable
{
public:
  explicit PointTable(const amrdm::DualMesh& mesh)
    : Mesh(mesh)
  {
  }

  vtkIdType Id(const glm::ivec3& pos2, float value)
  {
    const std::uint64_t key = (std::uint64_t(std::uint32_t(pos2.x) & 0x1FFFFFu) << 42) |
                              (std::uint64_t(std::uint32_t(pos2.y) & 0x1FFFFFu) << 21) |
                              std::uint64_t(std::uint32_t(pos2.z) & 0x1FFFFFu);
    const auto found = this->Ids.find(key);
    if (found != this->Ids.end())
    {
      return found->second;
    }
    const vtkIdType id = static_cast<vtkIdType>(this->Values.size());
    this->Ids.emplace(key, id);
    const glm::dvec3 world = this->Mesh.worldFromGrid(0.5 * glm::dvec3(pos2));
    this->Coordinates.insert(this->Coordinates.end(), { world.x, world.y, world.z });
    this->Values.push_back(value);
    return id;
  }

  std::vector<double> Coordinates;
  std::vector<float> Values;

private:
  const amrdm::DualMesh& Mesh;
  std::unordered_map<std::uint64_t, vtkIdType> Ids;
};

/// Largest |2 * grid coordinate| the 21-bit keys of PointTable hold.
constexpr int kMaxKeyCoordinate = (1 << 20) - 1;

bool FitsKeys(const amrdm::DualMesh& mesh)
{
  if (mesh.bvh.nodes.empty())
  {
    return true; // nothing to export
  }
  glm::vec3 lo, hi;
  mesh.gridBounds(lo, hi);
  const float m = std::fmax(std::fmax(std::fabs(lo.x), std::fabs(lo.y)),
    std::fmax(
      std::fmax(std::fabs(lo.z), std::fabs(hi.x)), std::fmax(std::fabs(hi.y), std::fabs(hi.z))));
  return 2.0f * m + 2.0f < float(kMaxKeyCoordinate);
}

/// True when element `c` (corner positions, VTK order, kind t of mesh/ElementList.h) is inverted
/// for VTK (AMRDualMeshVtkCells.h: the first face's right-hand normal, Newell's, so repeated
/// corners are harmless). Our kernels accept either orientation; VTK's volume, and the mappers
/// that split cells into tets, do not.
bool Inverted(int t, const glm::dvec3* c)
{
  const amrdm_vtk::VtkElementCell& cell = amrdm_vtk::kVtkElementCells[t];
  const int corners = amrdm::elementCorners(t);
  glm::dvec3 normal(0.0), face(0.0), opposite(0.0);
  for (int i = 0; i < cell.faceCorners; ++i)
  {
    normal += glm::cross(c[i], c[(i + 1) % cell.faceCorners]);
    face += c[i] / double(cell.faceCorners);
  }
  for (int i = cell.faceCorners; i < corners; ++i)
  {
    opposite += c[i] / double(corners - cell.faceCorners);
  }
  const double side = glm::dot(normal, opposite - face);
  return cell.normalAwayFromRest ? side > 0.0 : side < 0.0;
}

} // namespace

vtkStandardNewMacro(vtkAMRDualMeshToUnstructuredGrid);

vtkAMRDualMeshToUnstructuredGrid::vtkAMRDualMeshToUnstructuredGrid() = default;

vtkAMRDualMeshToUnstructuredGrid::~vtkAMRDualMeshToUnstructuredGrid()
{
  this->SetArrayName(nullptr);
}

vtkAMRDualMesh* vtkAMRDualMeshToUnstructuredGrid::GetDualMesh()
{
  return this->Field;
}

int vtkAMRDualMeshToUnstructuredGrid::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOverlappingAMR");
  return 1;
}

int vtkAMRDualMeshToUnstructuredGrid::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkOverlappingAMR* input = vtkOverlappingAMR::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("No input: expected a vtkOverlappingAMR on port 0");
    return 0;
  }
  this->Field->SetInputData(input);
  this->Field->SetArrayName(this->ArrayName);
  this->Field->SetComponent(this->Component);
  this->Field->SetLogScale(this->LogScale);
  if (!this->Field->Update())
  {
    vtkErrorMacro("Cannot build the dual mesh of the input (see the previous error)");
    return 0;
  }
  const amrdm::DualMesh& mesh = *this->Field->GetDualMesh();
  if (!FitsKeys(mesh))
  {
    vtkErrorMacro("The dual mesh spans more than 2^19 finest cells a side; expected at most "
                  << (kMaxKeyCoordinate / 2) << " for the unstructured-grid export");
    return 0;
  }
  PointTable points(mesh);
  std::vector<vtkIdType> offsets{ 0 };
  std::vector<vtkIdType> connectivity;
  std::vector<unsigned char> types;
  std::vector<unsigned char> sources;

  // Gridlets: every dual cell whose eight corners hold values, as a hexahedron.
  for (const amrdm::GridletHeader& g : mesh.gridlets)
  {
    const int width = static_cast<int>(mesh.levelWidth[g.level]);
    const int nx = g.dims.x + 1;
    const int ny = g.dims.y + 1;
    const float* s = mesh.gridletScalars.data() + g.begin;
    const int order[8][3] = { { 0, 0, 0 },
      { 1, 0, 0 },
      { 1, 1, 0 },
      { 0, 1, 0 },
      { 0, 0, 1 },
      { 1, 0, 1 },
      { 1, 1, 1 },
      { 0, 1, 1 } };
    for (int k = 0; k < g.dims.z; ++k)
    {
      for (int j = 0; j < g.dims.y; ++j)
      {
        for (int i = 0; i < g.dims.x; ++i)
        {
          float v[8];
          bool full = true;
          for (int c = 0; c < 8; ++c)
          {
            v[c] = s[((k + order[c][2]) * ny + j + order[c][1]) * nx + i + order[c][0]];
            full = full && std::isfinite(v[c]);
          }
          if (!full)
          {
            continue;
          }
          for (int c = 0; c < 8; ++c)
          {
            const glm::ivec3 cell =
              g.lower + glm::ivec3(i + order[c][0], j + order[c][1], k + order[c][2]);
            // A vertex beyond a domain face is a ghost: on the face (mesh/BoundaryLayer.h).
            // Vertex-centred meshes (gridletOrigin 0) store cell corners, not centres.
            const int half = mesh.gridletOrigin == 0.0f ? 0 : 1;
            const glm::ivec3 pos2 =
              glm::clamp((2 * cell + half) * width, 2 * mesh.domainLower, 2 * mesh.domainUpper);
            connectivity.push_back(points.Id(pos2, v[c]));
          }
          offsets.push_back(static_cast<vtkIdType>(connectivity.size()));
          types.push_back(VTK_HEXAHEDRON);
          sources.push_back(0);
        }
      }
    }
  }
  // Stitching elements, in VTK corner order, turned to VTK's orientation where inverted.
  for (int t = 0; t < amrdm::kElementKindCount; ++t)
  {
    const int corners = amrdm::elementCorners(t);
    const auto& idx = mesh.elementIndices[t];
    for (std::size_t e = 0; e + corners <= idx.size(); e += corners)
    {
      glm::dvec3 corner[8];
      for (int c = 0; c < corners; ++c)
      {
        corner[c] = glm::dvec3(mesh.vertices[idx[e + c]].pos2);
      }
      const int* order = amrdm_vtk::kVtkElementCells[t].mirror;
      const bool flip = Inverted(t, corner);
      for (int c = 0; c < corners; ++c)
      {
        const amrdm::ElementVertex& ev = mesh.vertices[idx[e + (flip ? order[c] : c)]];
        connectivity.push_back(points.Id(ev.pos2, ev.value));
      }
      offsets.push_back(static_cast<vtkIdType>(connectivity.size()));
      types.push_back(amrdm_vtk::kVtkElementCells[t].vtkType);
      sources.push_back(static_cast<unsigned char>(t + 1));
    }
  }

  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(points.Values.size()));
  vtkNew<vtkFloatArray> values;
  values->SetName(this->ArrayName);
  values->SetNumberOfTuples(static_cast<vtkIdType>(points.Values.size()));
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(points.Values.size()); ++p)
  {
    pts->SetPoint(p, &points.Coordinates[3 * p]);
    values->SetValue(p, points.Values[p]);
  }
  auto toIds = [](const std::vector<vtkIdType>& v)
  {
    vtkNew<vtkIdTypeArray> a;
    a->SetNumberOfTuples(static_cast<vtkIdType>(v.size()));
    std::copy(v.begin(), v.end(), a->GetPointer(0));
    return a;
  };
  vtkNew<vtkCellArray> cells;
  cells->SetData(toIds(offsets), toIds(connectivity));
  vtkNew<vtkUnsignedCharArray> cellTypes;
  cellTypes->SetNumberOfTuples(static_cast<vtkIdType>(types.size()));
  std::copy(types.begin(), types.end(), cellTypes->GetPointer(0));
  vtkNew<vtkUnsignedCharArray> cellSources;
  cellSources->SetName("vtkDualCellSource");
  cellSources->SetNumberOfTuples(static_cast<vtkIdType>(sources.size()));
  std::copy(sources.begin(), sources.end(), cellSources->GetPointer(0));

  output->Initialize();
  output->SetPoints(pts);
  output->SetCells(cellTypes, cells);
  output->GetPointData()->SetScalars(values);
  output->GetCellData()->AddArray(cellSources);
  return 1;
}

void vtkAMRDualMeshToUnstructuredGrid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  // BEGIN GENERATED field-print (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "LogScale: " << this->LogScale << "\n";
  // clang-format on
  // END GENERATED field-print
}
