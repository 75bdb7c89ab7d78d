// Majorant grid: uniform macrocells over the world bounds of the dual mesh. Per macrocell the
// host keeps the value range of every primitive overlapping it and the width of the finest cell
// among them (both built once per mesh), and the extinction majorant derived from the range
// through the transfer function (rebuilt on every transfer-function change, ranges untouched).
// Kernels read MajorantGridView; the builder is MajorantGridBuilder.cpp.
#pragma once

#include "mesh/DualMesh.h"
#include "sampling/TransferFunction.h"

#include <cstdint>
#include <vector>

namespace amrdm
{

/// Default macrocell edge, in finest-level cells (grid units): 16 finest cells per macrocell
/// per axis, two gridlets of the finest level. At 8 the walks spent more time stepping from
/// macrocell to macrocell than the tighter bound saved on the 6.7M-cell set (docs/BENCHMARKS.md,
/// "Majorant resolution, 2026-12-05"; the images of ray marching do not depend on it).
constexpr float kDefaultMacrocellCells = 16.0f;
/// ... but a set with fewer than kDefaultMinMacrocells macrocells at that size gets smaller ones,
/// down to one finest-level gridlet (the 32^3 flame set: 4^3, not 2^3, which was 14-19 % slower
/// with the command line's transfer function, whose transparent bulk the grid skips).
constexpr float kMinDefaultMacrocellCells = 8.0f;
/// Default cap on macrocells per axis (128^3 * 16 B = 33.6 MB).
constexpr int kDefaultMaxMacrocellsPerAxis = 128;
/// Default cap on the macrocell count relative to the data: at most one macrocell per this many
/// leaf cells (16 B per macrocell: at most 0.25 B per leaf cell), but at least
/// kDefaultMinMacrocells. The floor is small so that it never dominates a small deep set: on the
/// Enzo set (27k leaf cells, 8 levels) the grid is 7^3 (5.5 kB, 0.20 B per leaf cell; the floor of
/// 4096 macrocells before cost 2.42 B per leaf cell). A coarser grid than one macrocell per 8
/// finest cells was not slower on the real sets: CPU time at fixed spp, side by side, is in
/// docs/BENCHMARKS.md ("Majorant resolution").
constexpr int kDefaultLeafCellsPerMacrocell = 64;
constexpr int kDefaultMinMacrocells = 64;

struct MajorantGridView
{
  glm::ivec3 res{ 0 };  ///< macrocells per axis; 0 = no grid (everything empty)
  glm::vec3 lo{ 0.0f }; ///< world bounds
  glm::vec3 hi{ 0.0f };
  const float* majorant = nullptr; ///< res.x*res.y*res.z extinctions (world units^-1), x fastest
  /// Per macrocell, the smallest world-space edge of the finest primitive overlapping it (+inf
  /// where none does); the ray marcher's level-adaptive step reads it per segment. May be null
  /// (analytic grids: the adaptive step takes one stratum per segment).
  const float* cellWidth = nullptr;
  /// Per macrocell, the field's value range (min, max) over the primitives overlapping it
  /// (min > max where none does; MajorantGrid::range). The blend modes skip macrocells whose
  /// range cannot hold an isosurface value, or has no data. May be null (analytic and
  /// composite grids: nothing is skipped by value).
  const glm::vec2* range = nullptr;
};

AMRDM_HD int macrocellIndex(const MajorantGridView& g, const glm::ivec3& c)
{
  return (c.z * g.res.y + c.y) * g.res.x + c.x;
}

/// Macrocell containing world point p (clamped to the grid).
AMRDM_HD glm::ivec3 macrocellOf(const MajorantGridView& g, const glm::vec3& p)
{
  const glm::vec3 rel = (p - g.lo) / (g.hi - g.lo) * glm::vec3(g.res);
  return glm::clamp(glm::ivec3(glm::floor(rel)), glm::ivec3(0), g.res - 1);
}

/// Majorant at world point p; 0 outside the grid bounds.
AMRDM_HD float majorantAt(const MajorantGridView& g, const glm::vec3& p)
{
  if (g.res.x <= 0 || glm::any(glm::lessThan(p, g.lo)) || glm::any(glm::greaterThan(p, g.hi)))
  {
    return 0.0f;
  }
  return g.majorant[macrocellIndex(g, macrocellOf(g, p))];
}

/// Host-owned grid. `range[i]` = (min, max) of the field over primitives overlapping macrocell i
/// ((+inf, -inf) when none does); `cellWidth[i]` = the smallest world-space edge of the finest
/// of those primitives (+inf when none; empty for analytic grids); `majorant[i]` =
/// transfer-function maximum extinction over the range.
struct MajorantGrid
{
  glm::ivec3 res{ 0 };
  glm::vec3 lo{ 0.0f }, hi{ 0.0f };
  std::vector<glm::vec2> range;
  std::vector<float> cellWidth;
  std::vector<float> majorant;

  /// Host bytes: range, cell width and majorant, 16 B per macrocell.
  std::uint64_t bytes() const
  {
    return std::uint64_t(this->range.size()) * sizeof(glm::vec2) +
           std::uint64_t(this->cellWidth.size() + this->majorant.size()) * sizeof(float);
  }

  MajorantGridView view() const
  {
    MajorantGridView v;
    v.res = this->res;
    v.lo = this->lo;
    v.hi = this->hi;
    v.majorant = this->majorant.data();
    v.cellWidth = this->cellWidth.empty() ? nullptr : this->cellWidth.data();
    v.range = !this->range.empty() && this->range.size() == std::size_t(this->res.x) *
                                                              std::size_t(this->res.y) *
                                                              std::size_t(this->res.z)
                ? this->range.data()
                : nullptr;
    return v;
  }
};

/// Default resolution: one macrocell per kDefaultMacrocellCells finest cells per axis (for a
/// grid of fewer than kDefaultMinMacrocells: scaled up to that many, macrocells of at least
/// kMinDefaultMacrocellCells finest cells), scaled down to at most max(kDefaultMinMacrocells, leaf
/// cells / kDefaultLeafCellsPerMacrocell) macrocells (each axis rounded down), at most
/// kDefaultMaxMacrocellsPerAxis per axis, at least 1.
glm::ivec3 defaultMajorantResolution(const DualMesh& mesh);

/// Builds the per-macrocell value ranges over the mesh's bounds in the scene frame (mesh.origin +
/// mesh.finestSpacing * grid bounds; world - mesh.sceneOrigin, where the renderers' rays live). res
/// with any component <= 0 means the default. Gridlets contribute the range of each perfect dual
/// cell (8 non-NaN corners) to the macrocells its box overlaps; stitching elements their vertex
/// range over their (padded) box. Cell widths: a gridlet's level width, an element's smallest box
/// extent, times the smallest spacing. Parallel; the result does not depend on `threads`. Majorants
/// are left empty: call updateMajorants().
MajorantGrid buildMajorantRanges(const DualMesh& mesh,
  glm::ivec3 res = glm::ivec3(0),
  int threads = 0);

/// Recomputes every majorant from the stored ranges (call on every transfer-function change).
void updateMajorants(MajorantGrid& grid, const TransferFunctionView& tf, int threads = 0);

/// Test/analytic helper: a grid over [lo, hi] whose every macrocell has the same majorant (and
/// the range (-FLT_MAX, FLT_MAX): any value may occur).
MajorantGrid makeConstantMajorantGrid(const glm::vec3& lo,
  const glm::vec3& hi,
  float majorant,
  glm::ivec3 res = glm::ivec3(1));

} // namespace amrdm
