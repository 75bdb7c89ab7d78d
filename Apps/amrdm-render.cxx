// amrdm-render: path-traces (or ray-marches) an AMR file through its dual mesh and writes PNG +
// EXR, or prints the dual mesh's statistics. See `amrdm-render --help`.
#include "AMRDualMeshImageIO.h"
#include "AMRFileReader.h"
#include "RenderCommandLine.h"
#include "SceneExport.h"
#include "TransferFunctionPresets.h"

#include "vtkAMRDualMesh.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkOverlappingAMR.h"
#include "vtkUniformGrid.h"

#include "DualMesh.h"
#include "RendererFactory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace
{
int fail(const std::string& message)
{
  std::cerr << "amrdm-render: " << message << "\n";
  return 1;
}

vtkUniformGrid* firstGrid(vtkOverlappingAMR* amr)
{
  for (unsigned l = 0; l < amr->GetNumberOfLevels(); ++l)
    for (unsigned i = 0; i < amr->GetNumberOfDataSets(l); ++i)
      if (vtkUniformGrid* g = amr->GetDataSet(l, i))
        return g;
  return nullptr;
}

/// Range of the selected values over all blocks (magnitude for component -1 on vectors).
bool arrayRange(vtkOverlappingAMR* amr, const std::string& name, int component, double range[2])
{
  range[0] = 1e300;
  range[1] = -1e300;
  for (unsigned l = 0; l < amr->GetNumberOfLevels(); ++l)
    for (unsigned i = 0; i < amr->GetNumberOfDataSets(l); ++i)
    {
      vtkUniformGrid* g = amr->GetDataSet(l, i);
      vtkDataArray* a = g ? g->GetCellData()->GetArray(name.c_str()) : nullptr;
      if (!a)
        continue;
      double r[2];
      a->GetRange(r, a->GetNumberOfComponents() == 1 ? 0 : component);
      range[0] = std::min(range[0], r[0]);
      range[1] = std::max(range[1], r[1]);
    }
  return range[0] <= range[1];
}
}

int main(int argc, char* argv[])
{
  amrdm_app::RenderOptions opt;
  std::string error, exportScene;
  if (!amrdm_app::TakeExportSceneOption(argc, argv, exportScene, error))
    return fail(error);
  if (!amrdm_app::ParseCommandLine(argc, argv, opt, error))
    return fail(error + "\n" + amrdm_app::Usage());
  if (opt.help)
  {
    std::cout << amrdm_app::Usage() << amrdm_app::ExportSceneUsage();
    return 0;
  }
  if (opt.file.empty())
  {
    // The demo set's first array (Dark_Matter_Density) is zero in a third of the cells and
    // renders almost black over its linear range: show its gas density unless told otherwise.
    opt.file = AMRDM_DEMO_DATA;
    if (opt.array.empty())
      opt.array = AMRDM_DEMO_ARRAY;
  }
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_app::ReadAMRFile(opt.file, error);
  if (!amr)
    return fail(error);

  // Array: the first cell array unless named (or the demo set's).
  vtkUniformGrid* grid = firstGrid(amr);
  if (!grid)
    return fail("'" + opt.file + "' has no blocks with data");
  if (opt.array.empty())
  {
    for (int a = 0; a < grid->GetCellData()->GetNumberOfArrays() && opt.array.empty(); ++a)
    {
      const char* name = grid->GetCellData()->GetArrayName(a);
      if (name && std::string(name) != vtkDataSetAttributes::GhostArrayName() &&
        grid->GetCellData()->GetArray(a))
        opt.array = name;
    }
    if (opt.array.empty())
      return fail("'" + opt.file + "' has no numeric cell arrays");
  }
  double dataRange[2];
  if (!arrayRange(amr, opt.array, opt.component, dataRange))
    return fail("no cell array named '" + opt.array + "' in '" + opt.file + "'");
  const bool logScale = opt.logScale == 1 ||
    (opt.logScale < 0 && dataRange[0] > 0.0 && dataRange[1] > 1e3 * dataRange[0]);

  vtkNew<vtkAMRDualMesh> field;
  field->SetInputData(amr);
  field->SetArrayName(opt.array.c_str());
  field->SetComponent(opt.component);
  field->SetLogScale(logScale);
  field->SetGridletSize(opt.gridletSize);
  field->SetNumberOfThreads(opt.params.threads);
  if (!field->Update())
    return fail("cannot build the dual mesh (see the error above)");
  if (opt.stats)
  {
    std::cout << "{\"file\": \"" << opt.file << "\", \"array\": \"" << opt.array
              << "\", \"logScale\": " << (logScale ? "true" : "false") << ", "
              << field->GetReportJSON().substr(1) << "\n";
    return 0;
  }
  const amrdm::DualMesh& mesh = *field->GetDualMesh();

  // Scene defaults: camera framing the bounds, transfer function over the field's range.
  double b[6];
  amr->GetBounds(b);
  const glm::dvec3 lo(b[0], b[2], b[4]), hi(b[1], b[3], b[5]);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = 0.5 * glm::length(hi - lo);
  amrdm::RenderParams params = opt.params;
  amrdm::CameraParams& cam = params.camera;
  const glm::dvec3 focal = opt.hasFocal ? glm::dvec3(opt.focal[0], opt.focal[1], opt.focal[2]) : centre;
  glm::dvec3 eye;
  if (opt.hasEye)
    eye = glm::dvec3(opt.eye[0], opt.eye[1], opt.eye[2]);
  else
  {
    const double az = glm::radians(opt.azimuth), el = glm::radians(opt.elevation);
    const glm::dvec3 toEye(std::cos(el) * std::sin(az), -std::cos(el) * std::cos(az), std::sin(el));
    const double distance = radius / std::sin(glm::radians(0.5 * cam.viewAngle)) / opt.zoom;
    eye = focal + distance * toEye;
  }
  // The renderer works in the dual mesh's scene frame (world - sceneOrigin, in double first).
  cam.position = glm::vec3(mesh.sceneFromWorld(eye));
  cam.direction = glm::vec3(glm::normalize(focal - eye));
  for (int l = 0; l < params.numLights; ++l)
  {
    if (params.lights[l].type == amrdm::LightType::Point)
    {
      params.lights[l].position = glm::vec3(mesh.sceneFromWorld(glm::dvec3(params.lights[l].position)));
    }
  }
  cam.up = glm::vec3(opt.up[0], opt.up[1], opt.up[2]);
  cam.parallelScale = float(radius / opt.zoom);
  if (params.numLights == 0 && opt.headlight)
  {
    // A key light above and to the left of the camera (a light straight from the eye looks flat).
    const glm::vec3 w = cam.direction, u = glm::normalize(glm::cross(w, cam.up));
    const glm::vec3 v = glm::cross(u, w);
    amrdm::Light& key = params.lights[params.numLights++];
    key.type = amrdm::LightType::Directional;
    key.direction = glm::normalize(-w + 0.6f * v - 0.4f * u);
    key.intensity = 4.0f;
  }
  double tfRange[2] = { field->GetValueRange()[0], field->GetValueRange()[1] };
  if (opt.hasRange)
  {
    tfRange[0] = opt.range[0];
    tfRange[1] = opt.range[1];
  }
  amrdm::TransferFunction tf;
  const double unitDistance = opt.unitDistance > 0 ? opt.unitDistance : 0.25 * radius;
  if (!amrdm_app::MakeTransferFunction(opt.tf, tfRange[0], tfRange[1], opt.maxOpacity,
        unitDistance, tf, error))
    return fail(error);

  if (!exportScene.empty())
    return amrdm_app::ExportScene(exportScene, opt.file + " (" + opt.array + ")", amr, opt.array,
             opt.component, logScale, opt.gridletSize, params, tf, error) ? 0 : fail(error);

  // Device: auto (CUDA when present, else the CPU, said once), cpu or cuda (an error naming the
  // reason when impossible). Auto also falls back to the CPU when the GPU runs out of memory.
  std::unique_ptr<amrdm::Renderer> renderer;
  std::vector<double> frameMs;
  amrdm::RenderStats stats;
  std::vector<float> image;
  std::string gpuMemory;
  try
  {
    renderer = amrdm::createRenderer(
      opt.device, [](const std::string& line) { std::cerr << "amrdm-render: " << line << "\n"; });
    renderer->setMesh(&mesh, params.majorantResolution, params.threads);
    renderer->setTransferFunction(tf, params.threads);
    params.samplesPerPass = 1;
    for (int s = 0; s < opt.spp; ++s)
    {
      const auto t0 = std::chrono::steady_clock::now();
      renderer->renderPass(params);
      frameMs.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      std::fprintf(stderr, "\ramrdm-render: frame %d/%d (%.1f ms)", s + 1, opt.spp, frameMs.back());
    }
    std::fprintf(stderr, "\n");
    stats = renderer->stats();
    gpuMemory = renderer->deviceMemoryJson();
    if (!opt.output.empty())
      image = renderer->image();
  }
  catch (const std::exception& e)
  {
    return fail(e.what());
  }
  std::vector<double> sorted = frameMs;
  std::sort(sorted.begin(), sorted.end());
  std::printf("%s: array %s%s, %lld leaf cells, dual mesh %.2f MB (%.2f B/leaf cell), built in "
              "%.3f s\n%s: %dx%d, %d spp: median %.1f ms per frame (1 spp), %.2f s total; "
              "%llu walks cut at the step limit\n",
    opt.file.c_str(), opt.array.c_str(), logScale ? " (log10)" : "",
    (long long)field->GetNumberOfLeafCells(), field->GetTotalBytes() / 1e6,
    field->GetBytesPerLeafCell(), field->GetBuildSeconds(),
    amrdm::renderDeviceName(renderer->device()), params.width, params.height, opt.spp,
    sorted[sorted.size() / 2], [&] { double t = 0; for (double m : frameMs) t += m; return t / 1e3; }(),
    (unsigned long long)stats.stepLimitHits);
  if (opt.fpsFrames > 0)
  {
    // The authors' protocol: the mean of frames 11..N (the first ten warm up caches and clocks).
    const std::size_t first = frameMs.size() > 10 ? 10 : 0;
    double total = 0.0;
    for (std::size_t f = first; f < frameMs.size(); ++f)
      total += frameMs[f];
    const double mean = total / double(frameMs.size() - first);
    std::printf("fps: %s %dx%d, mean of frames %zu..%zu: %.3f ms per frame, %.1f FPS\n",
      amrdm::renderDeviceName(renderer->device()), params.width, params.height, first + 1,
      frameMs.size(), mean, 1000.0 / mean);
  }
  if (!gpuMemory.empty())
    std::printf("gpu memory: %s\n", gpuMemory.c_str());
  if (!opt.output.empty())
  {
    std::string base = opt.output;
    if (base.size() > 4 && base.compare(base.size() - 4, 4, ".png") == 0)
      base.resize(base.size() - 4);
    if (!amrdm_vtk::WritePNG(base + ".png", params.width, params.height, image.data(),
          opt.background, error) ||
      !amrdm_vtk::WriteEXR(base + ".exr", params.width, params.height, image.data(), error))
      return fail(error);
    std::printf("wrote %s.png and %s.exr\n", base.c_str(), base.c_str());
  }
  return 0;
}
