// SetBenchmark: the path tracer's knobs (element test, gridlet size, BVH leaf size, majorant grid,
// bounces)
// and the rows of its spp curve.
#include "SetBenchmark.h"

#include "mesh/DualMeshBuilder.h"

#include <cstdio>

namespace amrdm_bench
{

namespace
{

std::string dimsText(const glm::ivec3& d)
{
  return std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z);
}

} // namespace

void SetBenchmark::elementTest()
{
  std::printf("-- element test (path tracer)\n");
  this->addBase("element test", "bilinear, 10 Newton it.", this->dualBytes);
  const amrdm::DualMesh& mesh = *this->scene.field->GetDualMesh();
  auto measure = [&](const amrdm::ElementTestParams& e, const std::string& label)
  {
    const DualSetup s(mesh, this->scene.tf, e, glm::ivec3(0), this->threads);
    this->addPtRow("element test",
      label,
      runFrames(s.medium, s.majorants, this->pt, this->K),
      this->dualBytes,
      kNaN);
  };
  for (int it : this->mode.newton)
  {
    amrdm::ElementTestParams e;
    e.maxNewtonIterations = it;
    measure(e, "bilinear, " + std::to_string(it) + " Newton it.");
  }
  amrdm::ElementTestParams planar;
  planar.test = amrdm::ElementTest::PlanarFaces;
  measure(planar, "planar faces");
}

void SetBenchmark::gridletSize()
{
  std::printf("-- gridlet size (path tracer; memory, build time)\n");
  for (int g : this->mode.gridlets)
  {
    this->meshKnob("gridlet size", g, amrdm::DualMeshBuildOptions().bvhLeafSize);
  }
  std::printf("-- BVH leaf size (path tracer; memory, build time)\n");
  for (int leaf : this->mode.bvhLeaves)
  {
    this->meshKnob("bvh leaf size", amrdm::DualMeshBuildOptions().gridletSize, leaf);
  }
}

void SetBenchmark::meshKnob(const std::string& knob, int gridletSize, int bvhLeafSize)
{
  vtkNew<vtkAMRDualMesh> f;
  f->SetInputData(this->scene.amr);
  f->SetArrayName(this->spec.array.c_str());
  f->SetLogScale(this->spec.logScale);
  f->SetGridletSize(gridletSize);
  f->SetBVHLeafSize(bvhLeafSize);
  f->SetNumberOfThreads(this->threads);
  if (!f->Update())
    return;
  const DualSetup s(*f->GetDualMesh(), this->scene.tf, this->exact, glm::ivec3(0), this->threads);
  const RunOutput r = runFrames(s.medium, s.majorants, this->pt, this->K);
  const amrdm::DualMeshBuildOptions defaults;
  const std::uint64_t allIn = f->GetTotalBytes() + s.majorants.bytes() + s.cullingBytes();
  Row row;
  row.knob = knob;
  row.setting = std::to_string(knob == "gridlet size" ? gridletSize : bvhLeafSize);
  row.integrator = "pt";
  row.msPerFrame = median(r.frameMs);
  row.frames = this->K;
  row.bytes = double(allIn);
  row.buildSeconds = f->GetBuildSeconds();
  row.baseline = gridletSize == defaults.gridletSize && bvhLeafSize == defaults.bvhLeafSize;
  this->addRow(row, r.image, this->ptRef, &this->baseImage);
  nlohmann::ordered_json j;
  j["gridlet_size"] = gridletSize;
  j["bvh_leaf_size"] = bvhLeafSize;
  j["gridlets"] = f->GetNumberOfGridlets();
  j["gridlet_scalars"] = f->GetGridletScalarBytes();
  j["gridlet_headers"] = f->GetGridletHeaderBytes();
  j["element_vertices"] = f->GetElementVertexBytes();
  j["element_indices"] = f->GetElementIndexBytes();
  j["bvh"] = f->GetBVHBytes();
  j["total"] = f->GetTotalBytes();
  j["majorant_grid"] = s.majorants.bytes();
  j["culling"] = s.cullingBytes();
  j["all_in"] = allIn;
  j["bytes_per_leaf_cell"] = jsonValue(f->GetBytesPerLeafCell());
  j["all_in_per_leaf_cell"] =
    jsonValue(double(allIn) / double(std::max<vtkIdType>(1, f->GetNumberOfLeafCells())));
  j["build_s"] = jsonValue(f->GetBuildSeconds());
  j["ms_per_frame"] = jsonValue(row.msPerFrame);
  (knob == "gridlet size" ? this->gridlets : this->bvhLeaves).push_back(j);
}

void SetBenchmark::majorantGrid()
{
  std::printf("-- majorant grid (path tracer)\n");
  this->addBase("majorant grid",
    "default " + dimsText(this->defaultRes),
    double(this->base->majorants.bytes()));
  const amrdm::DualMesh& mesh = *this->scene.field->GetDualMesh();
  for (int cells : this->mode.majorantCells)
  {
    const glm::ivec3 res = this->fineRes(cells);
    if (res == this->defaultRes)
      continue;
    const DualSetup s(mesh, this->scene.tf, this->exact, res, this->threads);
    this->addPtRow("majorant grid",
      dimsText(res) + " (" + std::to_string(cells) + " cells)",
      runFrames(s.medium, s.majorants, this->pt, this->K),
      double(s.majorants.bytes()),
      kNaN);
  }
}

void SetBenchmark::maxBounces()
{
  std::printf("-- maximum bounces (path tracer)\n");
  this->addBase("max bounces", "64", this->dualBytes);
  for (int b : this->mode.bounces)
  {
    amrdm::RenderParams p = this->pt;
    p.maxBounces = b;
    p.rouletteStartBounce = std::min(p.rouletteStartBounce, b);
    this->addPtRow("max bounces",
      std::to_string(b),
      runFrames(this->base->medium, this->base->majorants, p, this->K),
      this->dualBytes,
      kNaN);
  }
}

void SetBenchmark::sppRows()
{
  for (const CurvePoint& c : this->o.curves)
  {
    if (c.set != this->spec.name || c.knob != "spp" || c.spp > 1024)
      continue;
    Row r;
    r.set = c.set;
    r.knob = "spp";
    r.setting = std::to_string(c.spp);
    r.integrator = "pt";
    r.msPerFrame = c.seconds * 1e3;
    r.frames = c.spp;
    r.rmse = c.rmse;
    r.psnr = psnr(c.rmse);
    r.bytes = this->dualBytes;
    this->o.rows.push_back(r);
  }
}

} // namespace amrdm_bench
