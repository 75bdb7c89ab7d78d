// amrdm-render: path-traces (or ray-marches) an AMR file through its dual mesh and writes PNG +
// EXR, or prints the dual mesh's statistics. See `amrdm-render --help`.
#include "AMRFileReader.h"
#include "FieldDefaults.h"
#include "DefaultView.h"
#include "FrameProgress.h"
#include "ImageOutput.h"
#include "RenderCommandLine.h"
#include "SceneExport.h"
#include "TransferFunctionPresets.h"

#include "vtkAMRDualMesh.h"
#include "vtkDataObject.h"
#include "vtkOverlappingAMR.h"

#include "mesh/DualMesh.h"
#include "render/RendererFactory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace
{
int fail(const std::string& message)
{
  std::cerr << "amrdm-render: " << message << "\n";
  return 1;
}

void note(const std::string& message)
{
  std::cerr << "amrdm-render: " << message << "\n";
}

std::string fixed(double v, int digits = 3)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, v);
  return buffer;
}
}

int main(int argc, char* argv[])
{
  amrdm_app::RenderOptions opt;
  std::string error;
  if (!amrdm_app::ParseCommandLine(argc, argv, opt, error))
    return fail(error + " (see amrdm-render --help)");
  if (opt.help)
  {
    std::cout << amrdm_app::Usage();
    return 0;
  }
  // Blend modes (render/BlendModeList.h): what each needs, and the integrator that draws them.
  const amrdm::BlendMode blend = opt.params.blendMode;
  if (blend == amrdm::BlendMode::Isosurface && opt.params.numIsoValues == 0)
    return fail("--blend iso needs --iso V[,V...] (the isosurface values)");
  if (blend == amrdm::BlendMode::Slice && !opt.hasSlice)
    return fail("--blend slice needs --slice OX OY OZ NX NY NZ (the plane)");
  // The blend mode asked for is what renders (as in the mapper): the ray marcher draws it, also
  // without --integrator (VTK's look, and fast); the path tracer, named, path traces isosurfaces.
  if (blend != amrdm::BlendMode::Composite &&
      (!opt.hasIntegrator || amrdm::blendModeLimitation(opt.params.integrator, blend)))
  {
    note(std::string("--blend ") + amrdm::blendModeInfo(blend).name + ": " +
         (opt.hasIntegrator ? amrdm::blendModeLimitation(opt.params.integrator, blend)
           : blend == amrdm::BlendMode::Isosurface
             ? "ray marching draws it (--integrator pt path traces the surfaces, lit and shadowed)"
             : "ray marching draws it"));
    opt.params.integrator = amrdm::IntegratorType::RayMarch;
  }
  if (opt.params.embedIsosurfaces && opt.params.numIsoValues == 0)
    return fail("--embed-iso needs --iso V[,V...] (the isosurface values)");
  if (const char* embed = amrdm::embedIsosurfacesLimitation(
        opt.params.integrator, opt.params.embedIsosurfaces && blend == amrdm::BlendMode::Composite))
    note(std::string("--embed-iso: ") + embed);
  // --threads 0: vtkSMPTools' count (VTK_SMP_MAX_THREADS), the same for the build and the render.
  opt.params.threads = vtkAMRDualMesh::ResolveNumberOfThreads(opt.params.threads);
  // The output's folder and format before anything is read or rendered.
  amrdm_app::ImageTarget target;
  if (!opt.output.empty() && !amrdm_app::CheckImageTarget(opt.output, target, error))
    return fail(error);
  if (opt.file.empty())
    opt.file = AMRDM_DEMO_DATA;
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_app::ReadAMRFile(opt.file, error);
  if (!amr)
    return fail(error);

  // The array: named, or chosen (density first; FieldDefaults.h); its arrays listed on request.
  const std::vector<amrdm_app::CellArrayInfo> arrays =
    amrdm_app::ListCellArrays(amr, opt.component);
  if (opt.listArrays)
  {
    for (const amrdm_app::CellArrayInfo& a : arrays)
      std::cout << a.name << "\t" << a.components << " component(s)\t[" << a.range[0] << ", "
                << a.range[1] << "]" << (a.point ? "\tpoints" : "") << "\n";
    return 0;
  }
  if (arrays.empty())
    return fail("'" + opt.file + "' has no numeric cell or point arrays; expected at least one");
  if (opt.array.empty())
  {
    std::string reason;
    const int chosen = amrdm_app::ChooseArray(arrays, reason);
    if (chosen < 0)
      return fail("every cell array of '" + opt.file +
                  "' is constant: " + amrdm_app::DescribeArrays(arrays) +
                  "; pick one with --array NAME and set --range LO HI");
    opt.array = arrays[std::size_t(chosen)].name;
    note("array '" + opt.array + "' (" + reason + "; --array NAME to change, --list-arrays lists " +
         std::to_string(arrays.size()) + ")");
  }
  else if (std::none_of(arrays.begin(),
             arrays.end(),
             [&](const amrdm_app::CellArrayInfo& a) { return a.name == opt.array; }))
    return fail("no cell array named '" + opt.array + "' (nor a point array) in '" + opt.file +
                "'; the arrays are " + amrdm_app::DescribeArrays(arrays));
  const bool pointData = std::any_of(arrays.begin(),
    arrays.end(),
    [&](const amrdm_app::CellArrayInfo& a) { return a.name == opt.array && a.point; });
  note("array '" + opt.array + "': " +
       (pointData ? "point data (vertex-centred: each level's cells trilinear over their corners)"
                  : "cell data (the dual mesh of the cell centres)"));

  // Scale and range from the leaf cells: log10 when the positive values span > 3 decades (cells
  // <= 0 map below the range instead of becoming holes), from the bulk to a robust maximum.
  amrdm_app::FieldSummary summary;
  if (!amrdm_app::SummarizeField(amr, opt.array, opt.component, opt.logScale, summary))
    return fail("array '" + opt.array + "' has no finite " +
                std::string(opt.logScale == 1 ? "positive " : "") +
                "values; expected some to render");
  std::string fieldArray = opt.array;
  int fieldComponent = opt.component;
  if (summary.logScale)
  {
    fieldArray = amrdm_app::AddLogArray(amr, opt.array, opt.component, summary);
    fieldComponent = -1;
    std::string how = opt.logScale == 1 ? "--log"
                                        : "positive values span " + fixed(summary.decades, 2) +
                                            " decades; --linear to change";
    if (summary.nonPositive > 0)
      how += "; " + std::to_string(summary.nonPositive) + " leaf cells <= 0 set to " +
             fixed(summary.logFloor) + ", below the range";
    note("log10 scale (" + how + ")");
  }
  else if (opt.logScale < 0 && summary.decades > 3.0)
    note(
      "linear scale: the positive values span " + fixed(summary.decades, 2) +
      " decades but more than 10 % of the volume is negative (--log maps those below the range)");
  double tfRange[2];
  if (opt.hasRange)
  {
    tfRange[0] = opt.range[0];
    tfRange[1] = opt.range[1];
  }
  else
  {
    std::string how;
    amrdm_app::DefaultRange(summary, tfRange, how);
    note("range [" + fixed(tfRange[0], 4) + ", " + fixed(tfRange[1], 4) + "] of " + fieldArray +
         ": " + how + " (leaf cells span [" + fixed(summary.min, 4) + ", " + fixed(summary.max, 4) +
         "]; --range LO HI to change)");
  }

  vtkNew<vtkAMRDualMesh> field;
  field->SetInputData(amr);
  field->SetInputArrayToProcess(0,
    0,
    0,
    pointData ? vtkDataObject::FIELD_ASSOCIATION_POINTS : vtkDataObject::FIELD_ASSOCIATION_CELLS,
    fieldArray.c_str());
  field->SetComponent(fieldComponent);
  field->SetLogScale(false); // log10 is the array AddLogArray made
  field->SetGridletSize(opt.gridletSize);
  field->SetBVHLeafSize(opt.bvhLeafSize);
  field->SetNumberOfThreads(opt.params.threads);
  if (!field->Update())
    return fail("cannot build the dual mesh of '" + opt.file + "' (see the error above)");
  if (opt.stats)
  {
    // nlohmann-json escapes the names (quotes, backslashes, control characters) and writes
    // ASCII; bytes that are not UTF-8 (a Latin-1 file name) become U+FFFD.
    nlohmann::ordered_json stats;
    stats["file"] = opt.file;
    stats["array"] = opt.array;
    stats["logScale"] = summary.logScale;
    const nlohmann::ordered_json report = nlohmann::ordered_json::parse(field->GetReportJSON());
    for (const auto& item : report.items())
      stats[item.key()] = item.value();
    std::cout << stats.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace) << "\n";
    return 0;
  }
  const amrdm::DualMesh& mesh = *field->GetDualMesh();

  // Scene defaults: camera framing the bounds, transfer function over the field's range.
  // The default camera frames the visible region: the leaf cells above a tenth of the range,
  // where the ramp reaches a tenth of its opacity (the whole data when their bounding box fills
  // half of its bounding box or more).
  double b[6];
  amr->GetBounds(b);
  double visible[6];
  if (!opt.hasEye && !opt.hasFocal &&
      amrdm_app::VisibleBounds(amr,
        opt.array,
        opt.component,
        summary,
        tfRange[0] + 0.1 * (tfRange[1] - tfRange[0]),
        visible))
  {
    double fraction = 1.0;
    for (int d = 0; d < 3; ++d)
      fraction *= (visible[2 * d + 1] - visible[2 * d]) / std::max(b[2 * d + 1] - b[2 * d], 1e-300);
    if (fraction < 0.5)
    {
      note("the camera frames the cells above a tenth of the range (" + fixed(100 * fraction, 2) +
           " % of the domain's volume; --zoom, --eye or --focal to change)");
      std::copy(visible, visible + 6, b);
    }
  }
  const glm::dvec3 lo(b[0], b[2], b[4]), hi(b[1], b[3], b[5]);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = 0.5 * glm::length(hi - lo);
  amrdm::RenderParams params = opt.params;
  amrdm::CameraParams& cam = params.camera;
  const glm::dvec3 focal =
    opt.hasFocal ? glm::dvec3(opt.focal[0], opt.focal[1], opt.focal[2]) : centre;
  glm::dvec3 eye;
  if (opt.hasEye)
    eye = glm::dvec3(opt.eye[0], opt.eye[1], opt.eye[2]);
  else
    eye = amrdm_app::DefaultEye(
      focal, radius, opt.azimuth, opt.elevation, cam.viewAngle, opt.zoom); // Apps/DefaultView.h
  // The renderer works in the dual mesh's scene frame (world - sceneOrigin, in double first).
  cam.position = glm::vec3(mesh.sceneFromWorld(eye));
  cam.direction = glm::vec3(glm::normalize(focal - eye));
  for (int l = 0; l < params.numLights; ++l)
  {
    if (params.lights[l].type == amrdm::LightType::Point)
    {
      params.lights[l].position =
        glm::vec3(mesh.sceneFromWorld(glm::dvec3(params.lights[l].position)));
    }
  }
  params.sliceOrigin = glm::vec3(
    mesh.sceneFromWorld(glm::dvec3(opt.sliceOrigin[0], opt.sliceOrigin[1], opt.sliceOrigin[2])));
  params.sliceNormal = glm::vec3(
    glm::normalize(glm::dvec3(opt.sliceNormal[0], opt.sliceNormal[1], opt.sliceNormal[2])));
  cam.up = glm::vec3(opt.up[0], opt.up[1], opt.up[2]);
  cam.parallelScale = float(radius / opt.zoom);
  if (params.numLights == 0 && opt.headlight)
    params.lights[params.numLights++] = amrdm_app::DefaultKeyLight(cam);
  // Integrator defaults: the cost view renders with a scale above every cost (no clamping) and is
  // rescaled to its own range afterwards.
  constexpr double kUnclampedCostScale = 1e9;
  const amrdm::IntegratorInfo& integrator = amrdm::integratorInfo(params.integrator);
  const bool costView = integrator.costHeatMap;
  if (costView)
    params.heatMapScale = float(kUnclampedCostScale);
  const double exposure =
    opt.hasExposure ? opt.exposure : (integrator.scatters ? amrdm_app::kPathTracedExposure : 0.0);
  if (!opt.hasExposure && exposure != 0.0 && !opt.output.empty())
    note(
      "exposure " + std::string(exposure > 0 ? "+" : "") + fixed(exposure) +
      " stops (the path tracer's default, as bright as ray marching; --exposure STOPS to change)");

  amrdm::TransferFunction tf;
  const double unitDistance =
    opt.unitDistance > 0 ? opt.unitDistance : amrdm_app::DefaultUnitDistance(radius);
  std::vector<float> weights;
  if (amrdm_app::IsPreset(opt.tf) && !opt.opaqueBulk)
  {
    int damped = 0;
    weights =
      amrdm_app::BulkOpacityWeights(summary, tfRange[0], tfRange[1], amrdm_app::kBulkBins, damped);
    if (damped > 0)
      note("opacity ramp 0 .. " + fixed(opt.maxOpacity) + " over the range, faded in " +
           std::to_string(damped) + " of " + std::to_string(amrdm_app::kBulkBins) +
           " bins whose values fill more than " + fixed(100 * amrdm_app::kBulkFraction) +
           " % of the volume each (--opaque-bulk to keep them)");
  }
  if (!amrdm_app::MakeTransferFunction(
        opt.tf, tfRange[0], tfRange[1], opt.maxOpacity, unitDistance, tf, error, weights))
    return fail(error);

  if (!opt.exportScene.empty() && params.blendMode != amrdm::BlendMode::Composite)
    note("scene files do not store the blend mode: the exported scene renders composite");
  if (!opt.exportScene.empty())
    return amrdm_app::ExportScene(opt.exportScene,
             opt.file + " (" + opt.array + ")",
             amr,
             opt.array,
             opt.component,
             summary.logScale,
             opt.gridletSize,
             opt.bvhLeafSize,
             params,
             tf,
             error)
             ? 0
             : fail(error);

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
    amrdm_app::FrameProgress progress(opt.spp, isatty(2) != 0);
    for (int s = 0; s < opt.spp; ++s)
    {
      const auto t0 = std::chrono::steady_clock::now();
      renderer->renderPass(params);
      frameMs.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      progress.Frame(s + 1, frameMs.back());
    }
    progress.Finish();
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
  std::printf(
    "%s: array %s%s, %lld leaf cells, dual mesh %.2f MB (%.2f B/leaf cell), built in "
    "%.3f s\n%s: %dx%d, %d spp: median %.1f ms per frame (1 spp), %.2f s total; "
    "%llu walks cut at the step limit; %.1f medium evaluations per camera sample\n",
    opt.file.c_str(),
    opt.array.c_str(),
    summary.logScale ? " (log10)" : "",
    (long long)field->GetNumberOfLeafCells(),
    field->GetTotalBytes() / 1e6,
    field->GetBytesPerLeafCell(),
    field->GetBuildSeconds(),
    amrdm::renderDeviceName(renderer->device()),
    params.width,
    params.height,
    opt.spp,
    sorted[sorted.size() / 2],
    [&]
    {
      double t = 0;
      for (double m : frameMs)
        t += m;
      return t / 1e3;
    }(),
    (unsigned long long)stats.stepLimitHits,
    double(stats.steps) / std::max<double>(double(stats.samples), 1.0));
  if (opt.fpsFrames > 0)
  {
    // The authors' protocol: the mean of frames 11..N (the first ten warm up caches and clocks).
    const std::size_t first = frameMs.size() > 10 ? 10 : 0;
    double total = 0.0;
    for (std::size_t f = first; f < frameMs.size(); ++f)
      total += frameMs[f];
    const double mean = total / double(frameMs.size() - first);
    std::printf("fps: %s %dx%d, mean of frames %zu..%zu: %.3f ms per frame, %.1f FPS\n",
      amrdm::renderDeviceName(renderer->device()),
      params.width,
      params.height,
      first + 1,
      frameMs.size(),
      mean,
      1000.0 / mean);
  }
  if (!gpuMemory.empty())
    std::printf("gpu memory: %s\n", gpuMemory.c_str());
  if (!opt.output.empty())
  {
    if (costView)
    {
      double white = 0.0;
      if (amrdm_app::RescaleCostImage(image, kUnclampedCostScale, white))
        note("cost view: black = 0, white = " + fixed(white) +
             " steps + primitive tests per sample (the 99.5th percentile of the image)");
      else
        note("cost view: no pixel has any cost (the rays miss the data)");
    }
    amrdm_app::ApplyExposure(image, exposure);
    std::vector<std::string> written;
    if (!amrdm_app::WriteImage(
          target, params.width, params.height, image, opt.background, written, error))
      return fail(error);
    std::printf("wrote %s%s%s\n",
      written[0].c_str(),
      written.size() > 1 ? " and " : "",
      written.size() > 1 ? written[1].c_str() : "");
  }
  return 0;
}
