#include "vtkAMRDualMesh.h"

#include "AMRDualMeshArraySelection.h"
#include "AMRDualMeshPointSampling.h"
#include "AMRIntake.h"
#include "vtkDataObject.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkOverlappingAMR.h"
#include "vtkUnsignedCharArray.h"

#include "mesh/DualMeshBuilder.h"
#include "mesh/PrepareHierarchy.h"
#include "sampling/FieldSampler.h"
#include "core/ParallelFor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <utility>

vtkStandardNewMacro(vtkAMRDualMesh);

struct vtkAMRDualMesh::Internals
{
  std::unique_ptr<amrdm::DualMesh> Mesh;
  // What the current mesh was built from.
  vtkOverlappingAMR* BuiltInput = nullptr;
  std::string BuiltArray;
  int BuiltRequestedAssociation = -1;
  int BuiltComponent = 0;
  int BuiltGridletSize = 0;
  int BuiltBVHLeafSize = 0;
  int BuiltLogScale = 0;
};

vtkAMRDualMesh::vtkAMRDualMesh()
  : Internal(new Internals)
{
}

int vtkAMRDualMesh::ResolveNumberOfThreads(int requested)
{
  if (requested > 0)
  {
    return requested;
  }
  // The application's limit is VTK_SMP_MAX_THREADS (the variable VTK's SMP tools read) when
  // set, else all cores. The Mapper layer does not call vtkSMPTools (.ci/check-layers.sh).
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const char* env = std::getenv("VTK_SMP_MAX_THREADS");
  const int wanted = env ? std::atoi(env) : 0;
  return wanted > 0 ? std::min(wanted, cores) : cores;
}

int vtkAMRDualMesh::GetEffectiveNumberOfThreads() const
{
  return ResolveNumberOfThreads(this->NumberOfThreads);
}

vtkAMRDualMesh::~vtkAMRDualMesh()
{
  this->SetInputData(nullptr);
  this->SetArrayName(nullptr);
}

void vtkAMRDualMesh::SetInputData(vtkOverlappingAMR* amr)
{
  vtkSetObjectBodyMacro(Input, vtkOverlappingAMR, amr);
}

void vtkAMRDualMesh::SetInputArrayToProcess(int idx,
  int port,
  int connection,
  int association,
  const char* name)
{
  if (idx != 0 || port != 0 || connection != 0)
  {
    vtkErrorMacro("SetInputArrayToProcess(" << idx << ", " << port << ", " << connection
                                            << ", ...): expected 0, 0, 0 (one array of the one "
                                               "input); nothing changed.");
    return;
  }
  this->SetArrayName(name);
  this->SetArrayAssociation(association);
}

vtkOverlappingAMR* vtkAMRDualMesh::GetInputData()
{
  return this->Input;
}

bool vtkAMRDualMesh::IsValid() const
{
  return this->Internal->Mesh != nullptr;
}

const amrdm::DualMesh* vtkAMRDualMesh::GetDualMesh() const
{
  return this->Internal->Mesh.get();
}

bool vtkAMRDualMesh::Update()
{
  Internals& in = *this->Internal;
  const std::string array = this->ArrayName ? this->ArrayName : "";
  const bool current =
    in.Mesh && in.BuiltInput == this->Input && this->Input &&
    this->Input->GetMTime() <= this->BuildTime.GetMTime() && in.BuiltArray == array &&
    in.BuiltComponent == this->Component && in.BuiltGridletSize == this->GridletSize &&
    in.BuiltBVHLeafSize == this->BVHLeafSize && in.BuiltLogScale == this->LogScale &&
    in.BuiltRequestedAssociation == this->ArrayAssociation;
  if (current)
  {
    return true;
  }
  in.Mesh.reset();
  in.BuiltInput = nullptr;
  const auto start = std::chrono::steady_clock::now();
  amrdm::AmrHierarchy amr;
  amrdm::LevelBoxes metadata;
  std::string error;
  const int threads = this->GetEffectiveNumberOfThreads();
  const int association = amrdm_vtk::ResolveAssociation(this->Input, array, this->ArrayAssociation);
  if (association == -2)
  {
    vtkErrorMacro(
      "Cannot build the dual mesh: ArrayAssociation is "
      << this->ArrayAssociation
      << "; expected vtkDataObject::FIELD_ASSOCIATION_POINTS (0), FIELD_ASSOCIATION_CELLS (1) "
         "or -1 (cells, else points, by name)");
    return false;
  }
  const bool points = association == vtkDataObject::FIELD_ASSOCIATION_POINTS;
  if (!amrdm_vtk::ConvertAMR(this->Input,
        this->ArrayName,
        this->Component,
        this->LogScale != 0,
        amr,
        error,
        threads,
        points ? amrdm::FieldAssociation::Points : amrdm::FieldAssociation::Cells,
        &metadata))
  {
    vtkErrorMacro("Cannot build the dual mesh: " << error);
    return false;
  }
  const auto converted = std::chrono::steady_clock::now();
  this->IntakeSeconds = std::chrono::duration<double>(converted - start).count();
  try
  {
    // The one hierarchy pipeline (mesh/PrepareHierarchy.h): checks, cell states, value range.
    const amrdm::HierarchySummary prepared = amrdm::prepareHierarchy(amr, threads, &metadata);
    const std::int64_t nonFinite = prepared.nonFiniteValues;
    if (nonFinite > 0)
    {
      vtkWarningMacro(
        "Array '" << array << "' has " << nonFinite
                  << (this->LogScale ? " non-positive, NaN or infinite" : " NaN or infinite")
                  << (points ? " vertex values; the cells around them are treated as empty."
                             : " leaf values; they are treated as empty."));
    }
    this->ValueRange[0] = prepared.valueRange[0];
    this->ValueRange[1] = prepared.valueRange[1];
    amrdm::DualMeshBuildOptions options;
    options.gridletSize = this->GridletSize;
    options.bvhLeafSize = this->BVHLeafSize;
    options.threads = threads;
    options.memoryLimit = static_cast<std::uint64_t>(this->MemoryLimit) * 1024 * 1024;
    options.progress = [this](double f)
    {
      double progress = f;
      this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
    };
    in.Mesh.reset(new amrdm::DualMesh(amrdm::buildDualMesh(std::move(amr), options)));
    in.Mesh->counts.nonFiniteValues = nonFinite;
    const amrdm::DualMeshCounts& c = in.Mesh->counts;
    if (c.leafCells > 0 && c.gridlets + c.tets + c.pyramids + c.wedges + c.hexes == 0)
    {
      vtkWarningMacro(
        "The dual mesh of '"
        << array << "' is empty: its " << c.leafCells
        << " leaf cells have no 2x2x2 neighbourhood of leaf-cell centres (is the data one cell "
           "thick, e.g. 2D?); the field spans the cell centres, so nothing can be sampled or "
           "rendered. Expected at least two cells per axis.");
    }
  }
  catch (const std::exception& e)
  {
    in.Mesh.reset();
    vtkErrorMacro("Cannot build the dual mesh: " << e.what());
    return false;
  }
  this->BuildSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++this->BuildCount;
  in.BuiltInput = this->Input;
  in.BuiltArray = array;
  in.BuiltComponent = this->Component;
  in.BuiltGridletSize = this->GridletSize;
  in.BuiltBVHLeafSize = this->BVHLeafSize;
  in.BuiltLogScale = this->LogScale;
  in.BuiltRequestedAssociation = this->ArrayAssociation;
  this->BuiltAssociation = association;
  this->BuildTime.Modified();
  return true;
}

double vtkAMRDualMesh::Sample(double x, double y, double z)
{
  const amrdm::DualMesh* mesh = this->Internal->Mesh.get();
  if (!mesh)
  {
    vtkErrorMacro("Sample() called before a successful Update()");
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double p[3] = { x, y, z };
  return amrdm_vtk::SampleAt(
    *mesh, amrdm_vtk::MakeElementTestParams(this->ElementTest, this->MaxNewtonIterations), p);
}

vtkIdType vtkAMRDualMesh::SamplePoints(vtkDataArray* points,
  vtkDataArray* values,
  vtkUnsignedCharArray* mask)
{
  const amrdm::DualMesh* mesh = this->Internal->Mesh.get();
  if (!mesh)
  {
    vtkErrorMacro("SamplePoints() called before a successful Update()");
    return -1;
  }
  if (!points || points->GetNumberOfComponents() != 3 || !values || !mask)
  {
    vtkErrorMacro("SamplePoints() needs a 3-component point array, a value array and a mask");
    return -1;
  }
  return amrdm_vtk::SamplePointArray(*mesh,
    amrdm_vtk::MakeElementTestParams(this->ElementTest, this->MaxNewtonIterations),
    this->GetEffectiveNumberOfThreads(),
    points,
    values,
    mask);
}

#define AMRDM_COUNT_GETTER(Name, field)                                                            \
  vtkIdType vtkAMRDualMesh::GetNumberOf##Name() const                                              \
  {                                                                                                \
    return this->Internal->Mesh ? static_cast<vtkIdType>(this->Internal->Mesh->counts.field) : 0;  \
  }
AMRDM_COUNT_GETTER(LeafCells, leafCells)
AMRDM_COUNT_GETTER(Gridlets, gridlets)
AMRDM_COUNT_GETTER(PerfectCubes, perfectCubes)
AMRDM_COUNT_GETTER(Tets, tets)
AMRDM_COUNT_GETTER(Pyramids, pyramids)
AMRDM_COUNT_GETTER(Wedges, wedges)
AMRDM_COUNT_GETTER(Hexes, hexes)
AMRDM_COUNT_GETTER(DegenerateHexes, degenerateHexes)
AMRDM_COUNT_GETTER(StitchingVertices, vertices)
AMRDM_COUNT_GETTER(NonFiniteValues, nonFiniteValues)
#undef AMRDM_COUNT_GETTER

#define AMRDM_MEMORY_GETTER(Name, expr)                                                            \
  vtkTypeUInt64 vtkAMRDualMesh::Get##Name() const                                                  \
  {                                                                                                \
    return this->Internal->Mesh ? this->Internal->Mesh->memoryReport().expr : 0;                   \
  }
AMRDM_MEMORY_GETTER(GridletScalarBytes, gridletScalars)
AMRDM_MEMORY_GETTER(GridletHeaderBytes, gridletHeaders)
AMRDM_MEMORY_GETTER(ElementVertexBytes, elementVertices)
AMRDM_MEMORY_GETTER(ElementIndexBytes, elementIndices)
AMRDM_MEMORY_GETTER(BVHBytes, bvh)
AMRDM_MEMORY_GETTER(TotalBytes, total())
#undef AMRDM_MEMORY_GETTER

double vtkAMRDualMesh::GetBytesPerLeafCell() const
{
  return this->Internal->Mesh ? this->Internal->Mesh->memoryReport().bytesPerLeafCell() : 0.0;
}

std::string vtkAMRDualMesh::GetReportJSON() const
{
  if (!this->Internal->Mesh)
  {
    return "{}";
  }
  std::ostringstream s;
  s << "{\"counts\": " << this->Internal->Mesh->counts.toJson()
    << ", \"memory\": " << this->Internal->Mesh->memoryReport().toJson()
    << ", \"buildSeconds\": " << this->BuildSeconds
    << ", \"intakeSeconds\": " << this->IntakeSeconds << ", \"association\": \""
    << (this->BuiltAssociation == vtkDataObject::FIELD_ASSOCIATION_POINTS ? "points" : "cells")
    << "\"}";
  return s.str();
}

void vtkAMRDualMesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Input: " << this->Input << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "ArrayAssociation: " << this->ArrayAssociation << " (built: "
     << (this->BuiltAssociation == vtkDataObject::FIELD_ASSOCIATION_POINTS ? "points" : "cells")
     << ")\n";
  // BEGIN GENERATED field-print (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  os << indent << "ElementTest: " << this->ElementTest << "\n";
  os << indent << "MaxNewtonIterations: " << this->MaxNewtonIterations << "\n";
  os << indent << "GridletSize: " << this->GridletSize << "\n";
  os << indent << "BVHLeafSize: " << this->BVHLeafSize << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "LogScale: " << this->LogScale << "\n";
  // clang-format on
  // END GENERATED field-print
  os << indent << "EffectiveNumberOfThreads: " << this->GetEffectiveNumberOfThreads() << "\n";
  os << indent << "MemoryLimit (MiB): " << this->MemoryLimit << "\n";
  os << indent << "BuildSeconds: " << this->BuildSeconds << "\n";
  os << indent << "IntakeSeconds: " << this->IntakeSeconds << "\n";
  os << indent << "BuildCount: " << this->BuildCount << "\n";
  os << indent << "Report: " << this->GetReportJSON() << "\n";
}
