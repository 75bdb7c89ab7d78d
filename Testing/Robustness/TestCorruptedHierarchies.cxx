// Randomly corrupted AMR hierarchies through vtkAMRDualMesh (intake, validation, build) and the
// CPU renderer: every case must give a clear error (vtkErrorMacro text naming what was wrong and
// what was expected) or a correct render (every claimed probe of a linear field within 1e-5 of
// its range, a finite image with alpha in [0, 1]); never a crash, never a hang (a watchdog aborts
// a case that takes more than 60 s). Corruptions: overlapping same-level boxes, improper nesting,
// misaligned boxes, grid dims that disagree with their boxes, missing blocks, wrong array sizes,
// wrong block spacing or origin, wrong level spacing, boxes outside the domain, empty boxes,
// NaN values, a missing array, and two or three of these at once.
// Usage: TestCorruptedHierarchies [COUNT] (ctest runs 1000; COUNT = 10000 for the full sweep).
#include "vtkAMRDualMesh.h"

#include "render/CpuRenderer.h"
#include "mesh/DualMesh.h"

#include "vtkAMRBox.h"
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkOverlappingAMR.h"
#include "vtkUniformGrid.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
/// Whether world point p lies within half a level-0 cell of a face of the mesh's domain box: the
/// clamped boundary layer, where the field is held constant along the normal, not linear.
bool inBoundaryLayer(const amrdm::DualMesh* mesh, const double* p)
{
  if (!mesh || mesh->levelWidth.empty())
    return false;
  const glm::dvec3 g = mesh->gridFromWorld(glm::dvec3(p[0], p[1], p[2]));
  const double half = 0.5 * double(mesh->levelWidth.front());
  for (int d = 0; d < 3; ++d)
    if (g[d] < mesh->domainLower[d] + half || g[d] > mesh->domainUpper[d] - half)
      return true;
  return false;
}
struct Box
{
  int lo[3], hi[3]; ///< inclusive cells in the level's index space
};

struct Block
{
  Box box;
  int dimsDelta[3] = { 0, 0, 0 }; ///< grid cells minus box cells
  double spacingScale = 1.0, originShift = 0.0;
  bool missing = false, noArray = false, nanValue = false;
  long tupleDelta = 0;
};

struct Spec
{
  double origin[3] = { 0, 0, 0 };
  double h0 = 1.0;
  std::vector<double> levelSpacingScale;
  std::vector<std::vector<Block>> levels;
  double gradient[3] = { 1, 0, 0 };
};

const char* kNames[] = { "overlap",
  "improper nesting",
  "misaligned box",
  "dims vs box",
  "missing block",
  "wrong array size",
  "block spacing/origin",
  "level spacing",
  "outside the domain",
  "empty box",
  "NaN values",
  "missing array",
  "several at once" };
constexpr int kKinds = 13;

bool intersects(const Box& a, const Box& b)
{
  for (int d = 0; d < 3; ++d)
    if (a.hi[d] < b.lo[d] || b.hi[d] < a.lo[d])
      return false;
  return true;
}

/// A valid random hierarchy: 1-4 levels, ratio 2, properly nested, aligned, no overlaps.
Spec makeValid(std::mt19937& rng)
{
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  Spec s;
  for (int d = 0; d < 3; ++d)
  {
    s.origin[d] = std::uniform_real_distribution<double>(-10, 10)(rng);
    s.gradient[d] = std::uniform_real_distribution<double>(-1, 1)(rng);
  }
  s.h0 = std::pow(2.0, uni(-3, 3));
  const int n[3] = { uni(3, 8), uni(3, 8), uni(3, 8) };
  s.levels.emplace_back();
  if (n[0] >= 4 && uni(0, 1))
  {
    const int cut = uni(1, n[0] - 2);
    s.levels[0].push_back({ { { 0, 0, 0 }, { cut, n[1] - 1, n[2] - 1 } } });
    s.levels[0].push_back({ { { cut + 1, 0, 0 }, { n[0] - 1, n[1] - 1, n[2] - 1 } } });
  }
  else
    s.levels[0].push_back({ { { 0, 0, 0 }, { n[0] - 1, n[1] - 1, n[2] - 1 } } });
  const int numLevels = uni(1, 4);
  for (int l = 1; l < numLevels; ++l)
  {
    std::vector<Block> boxes;
    const int want = uni(1, 3);
    for (int attempt = 0; attempt < 20 && int(boxes.size()) < want; ++attempt)
    {
      const Box& parent = s.levels[l - 1][std::size_t(uni(0, int(s.levels[l - 1].size()) - 1))].box;
      Box b;
      for (int d = 0; d < 3; ++d)
      {
        const int size = uni(1, std::min(3, parent.hi[d] - parent.lo[d] + 1));
        const int lo = uni(parent.lo[d], parent.hi[d] - size + 1);
        b.lo[d] = 2 * lo;
        b.hi[d] = 2 * (lo + size) - 1;
      }
      bool free = true;
      for (const Block& o : boxes)
        free = free && !intersects(o.box, b);
      if (free)
        boxes.push_back({ b });
    }
    s.levels.push_back(boxes);
  }
  s.levelSpacingScale.assign(s.levels.size(), 1.0);
  return s;
}

/// Applies one corruption of kind `k` (kKinds - 1: two or three others).
void corrupt(Spec& s, int k, std::mt19937& rng)
{
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  if (k == kKinds - 1)
  {
    const int m = uni(2, 3);
    for (int i = 0; i < m; ++i)
      corrupt(s, uni(0, kKinds - 2), rng);
    return;
  }
  const int l = uni(0, int(s.levels.size()) - 1);
  std::vector<Block>& level = s.levels[std::size_t(l)];
  Block& b = level[std::size_t(uni(0, int(level.size()) - 1))];
  const int d = uni(0, 2);
  const int fine = s.levels.size() > 1 ? uni(1, int(s.levels.size()) - 1) : 0;
  Block& f =
    s.levels[std::size_t(fine)][std::size_t(uni(0, int(s.levels[std::size_t(fine)].size()) - 1))];
  switch (k)
  {
    case 0: // a copy of a box, shifted by 0..1 cells: overlaps the original
    {
      Block copy = b;
      copy.box.lo[d] += uni(0, 1);
      copy.box.hi[d] += copy.box.lo[d] - b.box.lo[d];
      level.push_back(copy);
      break;
    }
    case 1: // moved by an even number of its cells: aligned, but (partly) outside its parents
    {
      const int shift = 2 * uni(2, 6) * (uni(0, 1) ? 1 : -1);
      f.box.lo[d] += shift;
      f.box.hi[d] += shift;
      break;
    }
    case 2: // moved by one cell: no longer aligned with the coarser cells
      f.box.lo[d] += 1;
      f.box.hi[d] += 1;
      break;
    case 3:
      b.dimsDelta[d] = uni(0, 1) ? 1 : -1;
      break;
    case 4:
      b.missing = true;
      break;
    case 5:
      b.tupleDelta = uni(0, 1) ? -1 : 3;
      break;
    case 6:
      if (uni(0, 1))
        b.spacingScale = uni(0, 1) ? 1.5 : 0.5;
      else
        b.originShift = 0.5;
      break;
    case 7:
      s.levelSpacingScale[std::size_t(l)] = uni(0, 1) ? 0.7 : 1.3;
      break;
    case 8: // beyond level 0's extent
      b.box.lo[d] -= 40;
      b.box.hi[d] -= 40;
      break;
    case 9: // empty (hi = lo - 1; VTK's vtkAMRBox asserts on anything more inverted)
      b.box.hi[d] = b.box.lo[d] - 1;
      break;
    case 10:
      b.nanValue = true;
      break;
    case 11:
      b.noArray = true;
      break;
  }
}

double linear(const Spec& s, const double p[3])
{
  return 1.0 + s.gradient[0] * (p[0] - s.origin[0]) + s.gradient[1] * (p[1] - s.origin[1]) +
         s.gradient[2] * (p[2] - s.origin[2]);
}

vtkSmartPointer<vtkOverlappingAMR> toVTK(const Spec& s)
{
  std::vector<int> counts;
  for (const auto& level : s.levels)
    counts.push_back(int(level.size()));
  auto amr = vtkSmartPointer<vtkOverlappingAMR>::New();
  // vtkOverlappingAMR itself refuses some corrupt blocks (SetDataSet: "Inconsistent types of
  // vtkUniformGrid" for a grid flattened by wrong dims); they are then missing blocks. Quiet.
  vtkNew<vtkCallbackCommand> quiet;
  quiet->SetCallback([](vtkObject*, unsigned long, void*, void*) {});
  amr->AddObserver(vtkCommand::ErrorEvent, quiet);
  amr->Initialize(int(counts.size()), counts.data());
  amr->SetOrigin(s.origin);
  for (unsigned l = 0; l < s.levels.size(); ++l)
  {
    const double h = s.h0 / double(1 << l);
    const double lh = h * s.levelSpacingScale[l];
    const double spacing[3] = { lh, lh, lh };
    amr->SetSpacing(l, spacing);
    amr->SetRefinementRatio(l, 2);
    for (unsigned i = 0; i < s.levels[l].size(); ++i)
    {
      const Block& b = s.levels[l][i];
      vtkAMRBox box(b.box.lo, b.box.hi);
      amr->SetAMRBox(l, i, box);
      if (b.missing)
        continue;
      vtkNew<vtkUniformGrid> grid;
      int dims[3];
      double origin[3];
      for (int d = 0; d < 3; ++d)
      {
        dims[d] = std::max(1, b.box.hi[d] - b.box.lo[d] + 2 + b.dimsDelta[d]);
        origin[d] = s.origin[d] + b.box.lo[d] * h + b.originShift * h;
      }
      grid->SetDimensions(dims);
      grid->SetSpacing(h * b.spacingScale, h * b.spacingScale, h * b.spacingScale);
      grid->SetOrigin(origin);
      vtkNew<vtkDoubleArray> f;
      f->SetName(b.noArray ? "g" : "f");
      const vtkIdType n = grid->GetNumberOfCells();
      f->SetNumberOfTuples(std::max<vtkIdType>(0, n + b.tupleDelta));
      for (vtkIdType c = 0; c < f->GetNumberOfTuples(); ++c)
      {
        const int nx = std::max(1, dims[0] - 1), ny = std::max(1, dims[1] - 1);
        const int ijk[3] = { int(c % nx), int(c / nx % ny), int(c / (vtkIdType(nx) * ny)) };
        double p[3];
        for (int d = 0; d < 3; ++d)
          p[d] = s.origin[d] + (b.box.lo[d] + ijk[d] + 0.5) * h;
        f->SetValue(c, b.nanValue && c == n / 2 ? std::nan("") : linear(s, p));
      }
      grid->GetCellData()->AddArray(f);
      amr->SetDataSet(l, i, grid);
    }
  }
  return amr;
}

struct Messages
{
  std::string error;
  static void Record(vtkObject*, unsigned long event, void* client, void* call)
  {
    if (event == vtkCommand::ErrorEvent && call)
      static_cast<Messages*>(client)->error = static_cast<const char*>(call);
  }
};

std::atomic<int> gCurrent{ -1 };
std::atomic<bool> gDone{ false };
}

int main(int argc, char* argv[])
{
  const int count = argc > 1 ? std::atoi(argv[1]) : 1000;
  constexpr double kRelativeTolerance = 1e-5;
  constexpr int kCaseSeconds = 60;
  // Watchdog: a case that runs longer than kCaseSeconds is a hang.
  std::thread watchdog(
    [&]
    {
      int last = -2;
      auto since = std::chrono::steady_clock::now();
      while (!gDone)
      {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        const int now = gCurrent;
        if (now != last)
        {
          last = now;
          since = std::chrono::steady_clock::now();
        }
        else if (std::chrono::steady_clock::now() - since > std::chrono::seconds(kCaseSeconds))
        {
          std::printf("FAIL: case %d hangs (more than %d s)\n", now, kCaseSeconds);
          std::fflush(stdout);
          std::_Exit(1);
        }
      }
    });
  std::map<int, std::pair<int, int>> outcome; // kind -> (refused, rendered)
  int failures = 0;
  long probes = 0, claimed = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int c = 0; c < count; ++c)
  {
    gCurrent = c;
    std::mt19937 rng(static_cast<unsigned>(c) * 7919u + 17u);
    Spec spec = makeValid(rng);
    const int kind = c % kKinds;
    corrupt(spec, kind, rng);
    vtkSmartPointer<vtkOverlappingAMR> amr = toVTK(spec);
    vtkNew<vtkAMRDualMesh> field;
    Messages messages;
    vtkNew<vtkCallbackCommand> observer;
    observer->SetCallback(&Messages::Record);
    observer->SetClientData(&messages);
    field->AddObserver(vtkCommand::ErrorEvent, observer);
    field->AddObserver(vtkCommand::WarningEvent, observer); // quiet; warnings are allowed
    field->SetInputData(amr);
    field->SetArrayName("f");
    field->SetNumberOfThreads(1 + c % 2);
    if (!field->Update())
    {
      ++outcome[kind].first;
      const std::string& m = messages.error;
      // Clear: names what was expected (or, for the kernel's level-jump limit, the bound).
      if (m.find("expected") == std::string::npos && m.find("at most") == std::string::npos)
      {
        ++failures;
        std::printf("FAIL: case %d (%s): refused without a clear message: '%s'\n",
          c,
          kNames[kind],
          m.c_str());
      }
      else if (c < kKinds)
      {
        const std::size_t at = m.find("Cannot build");
        std::printf(
          "case %d (%s): %s", c, kNames[kind], m.substr(at == std::string::npos ? 0 : at).c_str());
      }
      continue;
    }
    ++outcome[kind].second;
    // A correct render: claimed probes reproduce the linear field; the image is finite.
    double extent[3], range = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      int hi = 0;
      for (const Block& b : spec.levels[0])
        hi = std::max(hi, b.box.hi[d] + 1);
      extent[d] = hi * spec.h0;
      range += std::abs(spec.gradient[d]) * extent[d];
    }
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 300; ++i)
    {
      double p[3];
      for (int d = 0; d < 3; ++d)
        p[d] = spec.origin[d] + u(rng) * extent[d];
      const double v = field->Sample(p[0], p[1], p[2]);
      ++probes;
      if (std::isnan(v) || inBoundaryLayer(field->GetDualMesh(), p))
        continue;
      ++claimed;
      worst = std::max(worst, std::abs(v - linear(spec, p)) / std::max(range, 1e-30));
    }
    bool imageOk = true;
    if (const amrdm::DualMesh* mesh = field->GetDualMesh())
    {
      amrdm::CpuRenderer renderer;
      renderer.setMesh(mesh, glm::ivec3(0), 1);
      amrdm::TransferFunction tf;
      tf.table = { glm::vec4(0.2f, 0.3f, 0.9f, 0.0f), glm::vec4(0.9f, 0.3f, 0.1f, 0.8f) };
      tf.lo = float(field->GetValueRange()[0]);
      tf.hi = float(field->GetValueRange()[1]) + 1e-3f;
      tf.unitDistance = float(spec.h0);
      renderer.setTransferFunction(tf, 1);
      amrdm::RenderParams p;
      p.width = p.height = 12;
      p.threads = 1;
      p.integrator = c % 2 ? amrdm::IntegratorType::RayMarch : amrdm::IntegratorType::PathTracer;
      const glm::dvec3 centre = glm::dvec3(0.5 * extent[0], 0.5 * extent[1], 0.5 * extent[2]);
      p.camera.position =
        glm::vec3(centre + glm::dvec3(3.0 * extent[0], -2.0 * extent[1], extent[2]));
      p.camera.direction = glm::normalize(glm::vec3(centre) - p.camera.position);
      renderer.renderPass(p);
      for (const float x : renderer.image())
        imageOk = imageOk && std::isfinite(x);
      const std::vector<float> image = renderer.image();
      for (std::size_t i = 3; i < image.size(); i += 4)
        imageOk = imageOk && image[i] >= 0.0f && image[i] <= 1.0f + 1e-6f;
    }
    if (worst > kRelativeTolerance || !imageOk)
    {
      ++failures;
      std::printf("FAIL: case %d (%s): accepted, but linear error %.3g of the range, image %s\n",
        c,
        kNames[kind],
        worst,
        imageOk ? "finite" : "NOT finite / alpha out of [0, 1]");
    }
  }
  gDone = true;
  watchdog.join();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%d corrupted hierarchies in %.1f s; per corruption (refused with a message / "
              "rendered correctly):\n",
    count,
    seconds);
  for (const auto& [kind, o] : outcome)
    std::printf("  %-22s %5d / %5d\n", kNames[kind], o.first, o.second);
  std::printf(
    "%ld probes of accepted hierarchies, %ld claimed; %d failure(s)\n", probes, claimed, failures);
  return failures ? 1 : 0;
}
