// Host construction of the majorant grid: per-macrocell value ranges and finest cell widths from
// gridlet dual cells and stitching elements, then majorants = transfer-function maximum
// extinction over each range.
#include "accel/MajorantGrid.h"

#include "core/ParallelFor.h"
#include "core/Tolerances.h"

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>

namespace amrdm
{
namespace
{
// Box pads (kMacrocellPad, kMajorantElementBoxPad) and value-range pads (kRangePadRelative,
// kRangePadUlps): core/Tolerances.h.
/// Primitives per parallel work item.
constexpr std::size_t kPrimitivesPerChunk = 64;

/// Lock-free min/max on float slots; min and max are order independent, so the result does not
/// depend on the thread count or schedule.
void atomicMin(std::atomic<float>& slot, float v)
{
  float cur = slot.load(std::memory_order_relaxed);
  while (v < cur && !slot.compare_exchange_weak(cur, v, std::memory_order_relaxed))
  {
  }
}
void atomicMax(std::atomic<float>& slot, float v)
{
  float cur = slot.load(std::memory_order_relaxed);
  while (v > cur && !slot.compare_exchange_weak(cur, v, std::memory_order_relaxed))
  {
  }
}

struct Binner
{
  glm::dvec3 origin, spacing; // world = origin + spacing * grid
  glm::dvec3 lo, cell;        // grid lower corner and macrocell size, world units
  glm::ivec3 res;
  double minSpacing; // smallest |spacing| component: grid -> world cell widths
  std::atomic<float>* lo_;
  std::atomic<float>* hi_;
  std::atomic<float>* width_;

  /// Macrocell index range [c0, c1] overlapping the grid-space box [a, b] grown by `pad`
  /// (grid units) plus kMacrocellPad.
  void cells(const glm::dvec3& a,
    const glm::dvec3& b,
    const glm::dvec3& pad,
    glm::ivec3& c0,
    glm::ivec3& c1) const
  {
    for (int d = 0; d < 3; ++d)
    {
      const double wa = origin[d] + spacing[d] * (a[d] - pad[d]);
      const double wb = origin[d] + spacing[d] * (b[d] + pad[d]);
      const double x0 = (std::min(wa, wb) - lo[d]) / cell[d] - kMacrocellPad;
      const double x1 = (std::max(wa, wb) - lo[d]) / cell[d] + kMacrocellPad;
      c0[d] = std::clamp(static_cast<int>(std::floor(x0)), 0, res[d] - 1);
      c1[d] = std::clamp(static_cast<int>(std::floor(x1)), 0, res[d] - 1);
    }
  }
  /// Merges a primitive's value range [vmin, vmax] and its cell width (grid units) into the
  /// macrocells [c0, c1].
  void merge(const glm::ivec3& c0, const glm::ivec3& c1, float vmin, float vmax, double width) const
  {
    const float worldWidth = static_cast<float>(width * minSpacing);
    const float pad = kRangePadRelative * (vmax - vmin) +
                      kRangePadUlps * std::max(std::fabs(vmin), std::fabs(vmax));
    vmin -= pad;
    vmax += pad;
    for (int z = c0.z; z <= c1.z; ++z)
      for (int y = c0.y; y <= c1.y; ++y)
        for (int x = c0.x; x <= c1.x; ++x)
        {
          const std::size_t i = (static_cast<std::size_t>(z) * res.y + y) * res.x + x;
          atomicMin(lo_[i], vmin);
          atomicMax(hi_[i], vmax);
          atomicMin(width_[i], worldWidth);
        }
  }
};

void binGridlet(const Binner& b, const DualMesh& mesh, std::size_t index)
{
  const GridletHeader& g = mesh.gridlets[index];
  const double w = mesh.levelWidth[static_cast<std::size_t>(g.level)];
  const int nx = g.dims.x + 1, ny = g.dims.y + 1;
  const float* s = mesh.gridletScalars.data() + g.begin;
  // Consecutive cells of a row that overlap the same macrocells are merged once, with their
  // united range (a padded union contains each cell's padded range): one atomic update per
  // macrocell run instead of per dual cell.
  glm::ivec3 runC0{ -1 }, runC1{ -1 };
  float runMin = 0.0f, runMax = 0.0f;
  auto flush = [&]()
  {
    if (runC0.x >= 0)
    {
      b.merge(runC0, runC1, runMin, runMax, w);
    }
    runC0 = glm::ivec3(-1);
  };
  for (int k = 0; k < g.dims.z; ++k)
    for (int j = 0; j < g.dims.y; ++j, flush())
      for (int i = 0; i < g.dims.x; ++i)
      {
        const float* c = s + (k * ny + j) * nx + i;
        const float v[8] = { c[0],
          c[1],
          c[nx],
          c[nx + 1],
          c[nx * ny],
          c[nx * ny + 1],
          c[nx * ny + nx],
          c[nx * ny + nx + 1] };
        float vmin = v[0], vmax = v[0];
        bool perfect = true;
        for (float x : v)
        {
          perfect = perfect && x == x; // NaN corner: not a dual cell of this gridlet
          vmin = std::min(vmin, x);
          vmax = std::max(vmax, x);
        }
        if (!perfect)
        {
          continue;
        }
        // Boundary cubes end at the domain faces (GridletBuilder.h).
        const glm::dvec3 a =
          (glm::dvec3(g.lower + glm::ivec3(i, j, k)) + double(mesh.gridletOrigin)) * w;
        glm::ivec3 c0, c1;
        b.cells(glm::max(a, glm::dvec3(mesh.domainLower)),
          glm::min(a + w, glm::dvec3(mesh.domainUpper)),
          glm::dvec3(0.0),
          c0,
          c1);
        if (c0 == runC0 && c1 == runC1)
        {
          runMin = std::min(runMin, vmin);
          runMax = std::max(runMax, vmax);
          continue;
        }
        flush();
        runC0 = c0;
        runC1 = c1;
        runMin = vmin;
        runMax = vmax;
      }
}

void binElement(const Binner& b, const DualMesh& mesh, int kind, std::size_t index)
{
  const int n = elementCorners(kind);
  const std::uint32_t* idx = mesh.elementIndices[kind].data() + index * static_cast<std::size_t>(n);
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  float vmin = std::numeric_limits<float>::max(), vmax = -vmin;
  for (int i = 0; i < n; ++i)
  {
    const ElementVertex& v = mesh.vertices[idx[i]];
    lo = glm::min(lo, 0.5 * glm::dvec3(v.pos2));
    hi = glm::max(hi, 0.5 * glm::dvec3(v.pos2));
    vmin = std::min(vmin, v.value);
    vmax = std::max(vmax, v.value);
  }
  glm::ivec3 c0, c1;
  b.cells(lo, hi, (hi - lo) * kMajorantElementBoxPad, c0, c1);
  // An element spans two levels; its smallest box extent is at least the finer level's width
  // (its corners include two distinct cell centres of that level along every axis it spans).
  // A boundary-layer element reaches a domain face from cell centres half a cell away: its
  // extent along that axis counts twice. (Zero extents cannot occur, zero-volume cells are
  // dropped, but are skipped all the same.)
  glm::dvec3 extent = hi - lo;
  double width = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 3; ++d)
  {
    const bool onFace =
      lo[d] == double(mesh.domainLower[d]) || hi[d] == double(mesh.domainUpper[d]);
    extent[d] *= onFace ? 2.0 : 1.0;
    width = extent[d] > 0.0 ? std::min(width, extent[d]) : width;
  }
  b.merge(c0, c1, vmin, vmax, width);
}
} // namespace

glm::ivec3 defaultMajorantResolution(const DualMesh& mesh)
{
  glm::vec3 lo, hi;
  mesh.gridBounds(lo, hi);
  if (mesh.bvh.nodes.empty())
  {
    return glm::ivec3(1);
  }
  glm::dvec3 cells = glm::ceil(glm::dvec3(hi - lo) / double(kDefaultMacrocellCells));
  // A small set keeps at least kDefaultMinMacrocells (all axes scaled up together), but no
  // macrocell smaller than kMinDefaultMacrocellCells finest cells: its empty space stays skipped.
  if (cells.x * cells.y * cells.z < double(kDefaultMinMacrocells))
  {
    const glm::dvec3 finest = glm::ceil(glm::dvec3(hi - lo) / double(kMinDefaultMacrocellCells));
    cells = glm::min(finest,
      glm::ceil(cells * std::cbrt(double(kDefaultMinMacrocells) / (cells.x * cells.y * cells.z))));
  }
  // Deep hierarchies have far more finest-cell blocks over their bounds than leaf cells: scale
  // all axes down together until the grid has at most one macrocell per
  // kDefaultLeafCellsPerMacrocell leaf cells (a finer grid there costs memory and DDA steps
  // without tightening the bound where the data is).
  const double budget = std::max(double(kDefaultMinMacrocells),
    double(mesh.counts.leafCells) / double(kDefaultLeafCellsPerMacrocell));
  const double count = cells.x * cells.y * cells.z;
  if (count > budget)
  {
    // Rounded down: the grid never exceeds the budget (16 B per macrocell per
    // kDefaultLeafCellsPerMacrocell leaf cells), so no floor dominates a small deep set.
    cells = glm::max(glm::floor(cells * std::cbrt(budget / count)), glm::dvec3(1.0));
  }
  return glm::clamp(glm::ivec3(cells), glm::ivec3(1), glm::ivec3(kDefaultMaxMacrocellsPerAxis));
}

MajorantGrid buildMajorantRanges(const DualMesh& mesh, glm::ivec3 res, int threads)
{
  MajorantGrid grid;
  if (glm::any(glm::lessThanEqual(res, glm::ivec3(0))))
  {
    res = defaultMajorantResolution(mesh);
  }
  grid.res = res;
  glm::vec3 glo(0.0f), ghi(0.0f);
  mesh.gridBounds(glo, ghi);
  if (mesh.bvh.nodes.empty())
  {
    glo = ghi = glm::vec3(0.0f);
  }
  const glm::dvec3 w0 = mesh.origin + mesh.finestSpacing * glm::dvec3(glo);
  const glm::dvec3 w1 = mesh.origin + mesh.finestSpacing * glm::dvec3(ghi);
  grid.lo = glm::vec3(glm::min(w0, w1));
  grid.hi = glm::vec3(glm::max(w0, w1));
  const std::size_t n = static_cast<std::size_t>(res.x) * res.y * res.z;

  std::unique_ptr<std::atomic<float>[]> lo(new std::atomic<float>[n]);
  std::unique_ptr<std::atomic<float>[]> hi(new std::atomic<float>[n]);
  std::unique_ptr<std::atomic<float>[]> width(new std::atomic<float>[n]);
  for (std::size_t i = 0; i < n; ++i)
  {
    lo[i].store(std::numeric_limits<float>::infinity(), std::memory_order_relaxed);
    hi[i].store(-std::numeric_limits<float>::infinity(), std::memory_order_relaxed);
    width[i].store(std::numeric_limits<float>::infinity(), std::memory_order_relaxed);
  }
  Binner b;
  b.origin = mesh.origin;
  b.spacing = mesh.finestSpacing;
  b.lo = glm::dvec3(grid.lo);
  b.cell = glm::max(glm::dvec3(grid.hi - grid.lo) / glm::dvec3(res), glm::dvec3(1e-30));
  b.res = res;
  const glm::dvec3 spacing = glm::abs(mesh.finestSpacing);
  b.minSpacing = std::min(spacing.x, std::min(spacing.y, spacing.z));
  b.lo_ = lo.get();
  b.hi_ = hi.get();
  b.width_ = width.get();

  // Work items: chunks of gridlets, then chunks of each element kind (t = PrimType).
  std::size_t counts[PrimTypeCount] = { mesh.gridlets.size() };
  for (int k = 0; k < kElementKindCount; ++k)
  {
    counts[elementPrimType(k)] = static_cast<std::size_t>(mesh.numElements(k));
  }
  std::size_t chunkStart[PrimTypeCount + 1] = { 0 };
  for (std::uint32_t t = 0; t < PrimTypeCount; ++t)
  {
    chunkStart[t + 1] = chunkStart[t] + (counts[t] + kPrimitivesPerChunk - 1) / kPrimitivesPerChunk;
  }
  parallelFor(chunkStart[PrimTypeCount],
    threads,
    [&](std::size_t chunk)
    {
      int t = 0;
      while (chunk >= chunkStart[t + 1])
      {
        ++t;
      }
      const std::size_t first = (chunk - chunkStart[t]) * kPrimitivesPerChunk;
      const std::size_t last = std::min(counts[t], first + kPrimitivesPerChunk);
      for (std::size_t i = first; i < last; ++i)
      {
        if (t == PrimGridlet)
        {
          binGridlet(b, mesh, i);
        }
        else
        {
          binElement(b, mesh, primElementKind(std::uint32_t(t)), i);
        }
      }
    });

  grid.range.resize(n);
  grid.cellWidth.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    grid.range[i] = glm::vec2(lo[i].load(), hi[i].load());
    grid.cellWidth[i] = width[i].load();
  }
  return grid;
}

void updateMajorants(MajorantGrid& grid, const TransferFunctionView& tf, int threads)
{
  grid.majorant.resize(grid.range.size());
  constexpr std::size_t kCellsPerChunk = 4096;
  const std::size_t chunks = (grid.range.size() + kCellsPerChunk - 1) / kCellsPerChunk;
  parallelFor(chunks,
    threads,
    [&](std::size_t c)
    {
      const std::size_t last = std::min(grid.range.size(), (c + 1) * kCellsPerChunk);
      for (std::size_t i = c * kCellsPerChunk; i < last; ++i)
      {
        grid.majorant[i] = tfMaxExtinction(tf, grid.range[i].x, grid.range[i].y);
      }
    });
}

MajorantGrid makeConstantMajorantGrid(const glm::vec3& lo,
  const glm::vec3& hi,
  float majorant,
  glm::ivec3 res)
{
  MajorantGrid grid;
  grid.res = glm::max(res, glm::ivec3(1));
  grid.lo = lo;
  grid.hi = hi;
  const std::size_t n = static_cast<std::size_t>(grid.res.x) * grid.res.y * grid.res.z;
  // Any value may occur (the blend modes skip no macrocell of an analytic grid by its range).
  grid.range.assign(n, glm::vec2(-FLT_MAX, FLT_MAX));
  grid.majorant.assign(n, majorant);
  return grid;
}

} // namespace amrdm
