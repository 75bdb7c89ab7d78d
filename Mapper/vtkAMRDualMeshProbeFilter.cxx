#include "vtkAMRDualMeshProbeFilter.h"

#include "vtkAMRDualMesh.h"
#include "vtkCharArray.h"
#include "vtkDoubleArray.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkOverlappingAMR.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <string>

vtkStandardNewMacro(vtkAMRDualMeshProbeFilter);

vtkAMRDualMeshProbeFilter::vtkAMRDualMeshProbeFilter()
{
  this->SetNumberOfInputPorts(2);
  this->SetValidPointMaskArrayName("vtkValidPointMask");
}

vtkAMRDualMeshProbeFilter::~vtkAMRDualMeshProbeFilter()
{
  this->SetArrayName(nullptr);
  this->SetValidPointMaskArrayName(nullptr);
}

void vtkAMRDualMeshProbeFilter::SetSourceConnection(vtkAlgorithmOutput* algOutput)
{
  this->SetInputConnection(1, algOutput);
}

void vtkAMRDualMeshProbeFilter::SetSourceData(vtkOverlappingAMR* source)
{
  this->SetInputData(1, source);
}

vtkAMRDualMesh* vtkAMRDualMeshProbeFilter::GetDualMesh()
{
  return this->Field;
}

int vtkAMRDualMeshProbeFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOverlappingAMR");
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

int vtkAMRDualMeshProbeFilter::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // The whole AMR hierarchy is needed, whatever piece of the points is asked for.
  vtkInformation* sourceInfo = inputVector[1]->GetInformationObject(0);
  if (sourceInfo)
  {
    sourceInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    sourceInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  }
  return 1;
}

int vtkAMRDualMeshProbeFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkOverlappingAMR* source = vtkOverlappingAMR::GetData(inputVector[1], 0);
  vtkDataSet* output = vtkDataSet::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("No input points: expected a vtkDataSet on port 0");
    return 0;
  }
  if (!source)
  {
    vtkErrorMacro("No source: expected a vtkOverlappingAMR on port 1 (SetSourceConnection)");
    return 0;
  }
  output->ShallowCopy(input);
  this->Field->SetInputData(source);
  // SetInputArrayToProcess(0, 1, 0, association, name) when given, else ArrayName (a cell
  // array of that name, else a point array).
  std::string name = this->ArrayName ? this->ArrayName : "";
  int association = -1;
  vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
  if (arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_NAME()))
  {
    name = arrayInfo->Get(vtkDataObject::FIELD_NAME());
    association = arrayInfo->Has(vtkDataObject::FIELD_ASSOCIATION())
                    ? arrayInfo->Get(vtkDataObject::FIELD_ASSOCIATION())
                    : -1;
    if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS &&
        association != vtkDataObject::FIELD_ASSOCIATION_CELLS)
    {
      vtkErrorMacro(
        "SetInputArrayToProcess: association "
        << association << " for '" << name
        << "'; expected vtkDataObject::FIELD_ASSOCIATION_POINTS or FIELD_ASSOCIATION_CELLS");
      return 0;
    }
  }
  this->Field->SetArrayName(name.c_str());
  this->Field->SetArrayAssociation(association);
  this->Field->SetComponent(this->Component);
  this->Field->SetGridletSize(this->GridletSize);
  this->Field->SetBVHLeafSize(this->BVHLeafSize);
  this->Field->SetElementTest(this->ElementTest);
  this->Field->SetMaxNewtonIterations(this->MaxNewtonIterations);
  this->Field->SetNumberOfThreads(this->NumberOfThreads);
  if (!this->Field->Update())
  {
    vtkErrorMacro("Cannot build the dual mesh of the source (see the previous error)");
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> points;
  points->SetNumberOfComponents(3);
  points->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    points->SetTypedTuple(i, x);
  }
  vtkNew<vtkFloatArray> values;
  values->SetName(name.c_str());
  vtkNew<vtkUnsignedCharArray> found;
  if (this->Field->SamplePoints(points, values, found) < 0)
  {
    return 0;
  }
  vtkNew<vtkCharArray> mask;
  mask->SetName(this->ValidPointMaskArrayName);
  mask->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    mask->SetValue(i, static_cast<char>(found->GetValue(i)));
  }
  output->GetPointData()->AddArray(values);
  output->GetPointData()->AddArray(mask);
  output->GetPointData()->SetActiveScalars(name.c_str());
  return 1;
}

void vtkAMRDualMeshProbeFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  // BEGIN GENERATED field-print (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  os << indent << "ElementTest: " << this->ElementTest << "\n";
  os << indent << "MaxNewtonIterations: " << this->MaxNewtonIterations << "\n";
  os << indent << "GridletSize: " << this->GridletSize << "\n";
  os << indent << "BVHLeafSize: " << this->BVHLeafSize << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Component: " << this->Component << "\n";
  // clang-format on
  // END GENERATED field-print
  os << indent << "ValidPointMaskArrayName: "
     << (this->ValidPointMaskArrayName ? this->ValidPointMaskArrayName : "(none)") << "\n";
  os << indent << "DualMesh:\n";
  this->Field->PrintSelf(os, indent.GetNextIndent());
}
