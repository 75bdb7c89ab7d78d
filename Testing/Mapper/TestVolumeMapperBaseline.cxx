// Baseline image of vtkAMRDualMeshVolumeMapper on a real AMR set (AMReX advection, phi, three
// levels): two viewports of one window, the path tracer (left, 16 samples) and gradient-shaded
// ray marching (right, 2 samples), each with an opaque sphere half inside the volume (depth
// compositing: the sphere hides the volume behind it, the volume tints the sphere where it is in
// front) and two clipping planes (the region x > 0.76 and y < 0.42 is empty). Fixed seed and
// sample counts; the right viewport also checks depth reads and compositing at a viewport
// origin other than (0, 0).
#include "VolumeMapperScene.h"

#include "vtkAMRDualMesh.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <chrono>
#include <cstdio>

int main(int argc, char* argv[])
{
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readAdvection();
  if (!amr)
  {
    std::printf("SKIP: the AMReX advection set is missing\n");
    return 125;
  }
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 200);
  window->SetMultiSamples(4); // exercises the multisampled depth read
  vtkSmartPointer<vtkPlaneCollection> planes = amrdm_test::advectionPlanes();
  vtkSmartPointer<vtkActor> sphere = amrdm_test::advectionSphere();

  vtkNew<vtkAMRDualMeshVolumeMapper> pathTracer, rayMarcher;
  vtkAMRDualMeshVolumeMapper* mappers[2] = { pathTracer, rayMarcher };
  const int samples[2] = { 16, 2 };
  for (int i = 0; i < 2; ++i)
  {
    vtkAMRDualMeshVolumeMapper* mapper = mappers[i];
    mapper->SetInputData(amr);
    mapper->SelectScalarArray("phi");
    mapper->SetClippingPlanes(planes);
    mapper->SetSeed(7);
    mapper->SetMaximumSamples(samples[i]);
    mapper->SetIntegrator(
      i == 0 ? vtkAMRDualMeshVolumeMapper::PATH_TRACER : vtkAMRDualMeshVolumeMapper::RAY_MARCH);
    vtkSmartPointer<vtkVolumeProperty> property = amrdm_test::advectionProperty();
    property->SetShade(i == 1);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    vtkNew<vtkRenderer> ren;
    ren->SetViewport(0.5 * i, 0.0, 0.5 * (i + 1), 1.0);
    ren->SetBackground(0.1, 0.1, 0.12);
    ren->AddActor(sphere);
    ren->AddVolume(volume);
    amrdm_test::advectionCamera(ren);
    window->AddRenderer(ren);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const int reached = pathTracer->RenderUntil(window, samples[0]);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("path tracer: %d samples in %.2f s (last render %.1f ms); ray marcher: %d samples "
              "(last render %.1f ms)\n",
    reached,
    seconds,
    1e3 * pathTracer->GetLastRenderSeconds(),
    rayMarcher->GetNumberOfSamples(),
    1e3 * rayMarcher->GetLastRenderSeconds());
  if (reached != samples[0] || rayMarcher->GetNumberOfSamples() != samples[1])
  {
    std::printf("FAIL: expected %d and %d samples\n", samples[0], samples[1]);
    return 1;
  }
  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  return result == vtkTesting::FAILED ? 1 : 0;
}
