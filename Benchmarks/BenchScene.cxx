#include "BenchScene.h"

#include "AMRDualMeshVTKCompat.h"
#include "AMRFileReader.h"
#include "AMRIntake.h"
#include "DefaultView.h"
#include "mesh/DualMesh.h"
#include "mesh/PrepareHierarchy.h"
#include "TransferFunctionPresets.h"

#include <chrono>
#include <cmath>

namespace amrdm_bench
{

bool loadScene(const SetSpec& spec,
  int width,
  int height,
  int threads,
  Scene& scene,
  std::string& error)
{
  scene.spec = spec;
  const auto t0 = std::chrono::steady_clock::now();
  scene.amr = amrdm_app::ReadAMRFile(spec.path, error);
  if (!scene.amr)
    return false;
  scene.readSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  scene.field = vtkSmartPointer<vtkAMRDualMesh>::New();
  scene.field->SetInputData(scene.amr);
  scene.field->SetArrayName(spec.array.c_str());
  scene.field->SetLogScale(spec.logScale);
  scene.field->SetNumberOfThreads(threads);
  if (!scene.field->Update())
  {
    error = "cannot build the dual mesh of " + spec.path;
    return false;
  }

  double b[6];
  scene.amr->GetBounds(b);
  // Kernel cameras and samplers work in the dual mesh's scene frame (world - sceneOrigin).
  scene.sceneOrigin = scene.field->GetDualMesh()->sceneOrigin;
  scene.lo = glm::dvec3(b[0], b[2], b[4]) - scene.sceneOrigin;
  scene.hi = glm::dvec3(b[1], b[3], b[5]) - scene.sceneOrigin;
  double s[3];
  amrdm_vtk::amrcompat::Spacing(scene.amr, amrdm_vtk::amrcompat::NumberOfLevels(scene.amr) - 1, s);
  scene.finestSpacing = glm::dvec3(s[0], s[1], s[2]);
  for (int a = 0; a < 3; ++a)
    scene.finestDims[a] = int((scene.hi[a] - scene.lo[a]) / s[a] + 0.5);

  // amrdm-render's default camera, lights and transfer function.
  const glm::dvec3 centre = 0.5 * (scene.lo + scene.hi);
  const double radius = 0.5 * glm::length(scene.hi - scene.lo);
  amrdm::RenderParams& p = scene.params;
  p = amrdm::RenderParams();
  p.width = width;
  p.height = height;
  p.threads = threads;
  amrdm::CameraParams& cam = p.camera;
  const glm::dvec3 eye = amrdm_app::DefaultEye(centre,
    radius,
    amrdm_app::kDefaultAzimuth,
    amrdm_app::kDefaultElevation,
    cam.viewAngle); // Apps/DefaultView.h
  cam.position = glm::vec3(eye);
  cam.direction = glm::vec3(glm::normalize(centre - eye));
  cam.up = glm::vec3(0.0f, 0.0f, 1.0f);
  cam.parallelScale = float(radius);
  scene.focalPoint = glm::vec3(centre);
  p.lights[p.numLights++] = amrdm_app::DefaultKeyLight(cam);

  const double* range = scene.field->GetValueRange();
  if (!amrdm_app::MakeTransferFunction("cool-warm",
        range[0],
        range[1],
        0.5,
        amrdm_app::DefaultUnitDistance(radius),
        scene.tf,
        error))
    return false;
  return true;
}

bool convertHierarchy(const Scene& scene, amrdm::AmrHierarchy& out, std::string& error)
{
  amrdm::LevelBoxes metadata;
  if (!amrdm_vtk::ConvertAMR(scene.amr,
        scene.spec.array.c_str(),
        -1,
        scene.spec.logScale,
        out,
        error,
        0,
        amrdm::FieldAssociation::Cells,
        &metadata))
    return false;
  try
  {
    amrdm::prepareHierarchy(out, 1, &metadata);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  return true;
}

} // namespace amrdm_bench
