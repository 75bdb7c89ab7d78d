// vtkAMRDualMeshVolumeMapper on bad input reports a clear vtkErrorMacro (seen by an observer on
// the mapper itself) and does not crash: no input, vtkImageData input (data and connection),
// a missing array, an empty AMR, point-data scalar mode, an empty opacity function. After the
// input is fixed, the same mapper renders.
#include "VolumeMapperScene.h"

#include "AMRDualMeshVTKCompat.h"

#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkTestErrorObserver.h"
#include "vtkVolume.h"

#include <cstdio>
#include <string>

namespace
{
int failures = 0;
}

int main(int, char*[])
{
  vtkNew<vtkAMRDualMeshVolumeMapper> mapper;
  vtkNew<vtkTest::ErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->AddObserver(vtkCommand::WarningEvent, errors);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(amrdm_test::advectionProperty());
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(64, 64);
  window->AddRenderer(ren);

  auto expect = [&](const char* what, const char* fragment)
  {
    errors->Clear();
    ren->ResetCamera();
    window->Render();
    const bool ok =
      errors->GetError() && errors->GetErrorMessage().find(fragment) != std::string::npos;
    std::printf("%s: %s -> %s\n",
      ok ? "ok  " : "FAIL",
      what,
      errors->GetError() ? errors->GetErrorMessage().c_str() : "(no error)");
    failures += ok ? 0 : 1;
  };

  expect("no input", "No input");
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 4);
  mapper->SetInputData(image);
  expect("vtkImageData input", "vtkImageData");
  vtkNew<vtkRTAnalyticSource> wavelet;
  mapper->SetInputConnection(wavelet->GetOutputPort());
  expect("vtkImageData connection", "vtkImageData");

  vtkNew<vtkOverlappingAMR> empty;
  mapper->SetInputData(empty);
  expect("empty AMR (no levels)", "empty");
  vtkNew<vtkOverlappingAMR> noBlocks;
  amrdm_vtk::amrcompat::InitializeLevels(noBlocks, { 1 });
  mapper->SetInputData(noBlocks);
  expect("empty AMR (no data sets)", "empty");

  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readAdvection();
  if (!amr)
  {
    std::printf("SKIP: the AMReX advection set is missing\n");
    return failures == 0 ? 125 : 1;
  }
  mapper->SetInputData(amr);
  mapper->SelectScalarArray("NoSuchArray");
  expect("missing array", "NoSuchArray");
  mapper->SelectScalarArray("phi");
  mapper->SetScalarModeToUsePointData();
  // Point data renders now (issue 35); a point mode with a cell array's name is refused.
  expect("point-data scalar mode with a cell array", "SetScalarModeToUseCellFieldData");
  mapper->SetScalarModeToDefault();
  vtkNew<vtkVolumeProperty> noPoints;
  volume->SetProperty(noPoints);
  noPoints->GetScalarOpacity()->RemoveAllPoints();
  expect("empty opacity function", "opacity function");

  volume->SetProperty(amrdm_test::advectionProperty());
  errors->Clear();
  mapper->SetMaximumSamples(1);
  window->Render();
  const bool rendered = !errors->GetError() && mapper->GetNumberOfSamples() == 1;
  std::printf("%s: renders once the input is fixed\n", rendered ? "ok  " : "FAIL");
  failures += rendered ? 0 : 1;
  return failures == 0 ? 0 : 1;
}
