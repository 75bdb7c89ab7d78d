// vtkAMRDualMeshVolumeMapper's Device: CPU renders on the CPU silently; AUTO renders on CUDA
// when a device can be used, else on the CPU and says so (GetDeviceReport(), naming the reason);
// CUDA without a CUDA build or device is a clear error that draws nothing and does not crash,
// and switching back to CPU renders again. With a device, CUDA renders and AUTO picks it.
#include "VolumeMapperScene.h"

#include "render/RendererFactory.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkTestErrorObserver.h"
#include "vtkVolume.h"

#include <cstdio>
#include <sstream>
#include <string>

namespace
{
int failures = 0;
void check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
  failures += ok ? 0 : 1;
}
}

int main(int, char*[])
{
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readAdvection();
  if (!amr)
  {
    std::printf("SKIP: the AMReX advection set is missing\n");
    return 125;
  }
  vtkNew<vtkAMRDualMeshVolumeMapper> mapper;
  vtkNew<vtkTest::ErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->AddObserver(vtkCommand::WarningEvent, errors);
  mapper->SetInputData(amr);
  mapper->SelectScalarArray("phi");
  mapper->SetMaximumSamples(2);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(amrdm_test::advectionProperty());
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(48, 48);
  window->AddRenderer(ren);
  ren->ResetCamera();

  std::string reason;
  const bool haveCuda = amrdm::cudaRenderingAvailable(&reason);
  std::printf("CUDA here: %s%s\n", haveCuda ? "yes" : "no: ", haveCuda ? "" : reason.c_str());

  check(mapper->GetDevice() == vtkAMRDualMeshVolumeMapper::DEVICE_AUTO, "the default is AUTO");
  std::ostringstream printed;
  mapper->Print(printed);
  check(printed.str().find("(Device AUTO)") != std::string::npos, "PrintSelf shows the Device");

  // CPU: silent, renders on the CPU.
  mapper->SetDeviceToCPU();
  errors->Clear();
  window->Render();
  check(!errors->GetError() && !errors->GetWarning(), "CPU renders without a message");
  check(mapper->GetRenderingDevice() == vtkAMRDualMeshVolumeMapper::DEVICE_CPU &&
          mapper->GetNumberOfSamples() == 1,
    "CPU renders one sample on the CPU");

  // CUDA.
  mapper->SetDeviceToCUDA();
  errors->Clear();
  window->Render();
  if (haveCuda)
  {
    check(!errors->GetError() &&
            mapper->GetRenderingDevice() == vtkAMRDualMeshVolumeMapper::DEVICE_CUDA &&
            mapper->GetNumberOfSamples() == 1,
      "CUDA renders one sample on the device");
  }
  else
  {
    const std::string message = errors->GetError() ? errors->GetErrorMessage() : "";
    std::printf("  CUDA error: %s", message.c_str());
    check(
      message.find("CUDA") != std::string::npos && message.find("AUTO or CPU") != std::string::npos,
      "CUDA without a device is an error that names CUDA and the alternative");
    check(mapper->GetRenderingDevice() == -1, "CUDA without a device leaves no renderer");
    errors->Clear();
    window->Render();
    check(!errors->GetError(), "the same CUDA error is not repeated on every render");
  }

  // AUTO: says which device and why, once.
  mapper->SetDeviceToAuto();
  errors->Clear();
  window->Render();
  const std::string warning = mapper->GetDeviceReport();
  std::printf("  AUTO said: %s\n", warning.c_str());
  check(!errors->GetError() && !errors->GetWarning() &&
          warning.find("device auto") != std::string::npos,
    "AUTO renders and says which device (a report, not a warning)");
  check(mapper->GetRenderingDevice() == (haveCuda ? vtkAMRDualMeshVolumeMapper::DEVICE_CUDA
                                                  : vtkAMRDualMeshVolumeMapper::DEVICE_CPU),
    haveCuda ? "AUTO picks CUDA" : "AUTO falls back to the CPU");
  if (!haveCuda)
  {
    check(warning.find("CPU") != std::string::npos, "AUTO's message says the CPU renders");
  }
  errors->Clear();
  window->Render();
  check(!errors->GetWarning() && mapper->GetNumberOfSamples() == 2, "AUTO keeps accumulating");

  // Back to the CPU after whatever happened.
  mapper->SetDeviceToCPU();
  errors->Clear();
  window->Render();
  check(!errors->GetError() && mapper->GetNumberOfSamples() == 1 &&
          mapper->GetRenderingDevice() == vtkAMRDualMeshVolumeMapper::DEVICE_CPU,
    "switching to CPU restarts the accumulation on the CPU");
  return failures == 0 ? 0 : 1;
}
