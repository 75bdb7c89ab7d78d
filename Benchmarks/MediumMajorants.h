// Majorant grids for the benchmark's alternative media (NearestCellMedium, UniformGridMedium):
// the same MajorantGrid the kernels read (Kernels/accel/MajorantGrid.h), with the per-macrocell
// value ranges accumulated from boxes that carry a value range (leaf cells, or uniform-grid cells
// with the range of their 8 corner values). Boxes are padded by a small fraction of a macrocell so
// rounding can never leave a point outside the macrocells its value counted for. The majorants
// then come from Kernels' updateMajorants(), as for the dual mesh.
#pragma once

#include "accel/MajorantGrid.h"
#include "NearestCellMedium.h"
#include "UniformGridMedium.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amrdm_bench
{

class MajorantRangeBuilder
{
public:
  MajorantRangeBuilder(const glm::vec3& lo, const glm::vec3& hi, glm::ivec3 res)
  {
    this->Grid.res = glm::max(res, glm::ivec3(1));
    this->Grid.lo = lo;
    this->Grid.hi = hi;
    const std::size_t n = std::size_t(this->Grid.res.x) * this->Grid.res.y * this->Grid.res.z;
    const float inf = std::numeric_limits<float>::infinity();
    this->Grid.range.assign(n, glm::vec2(inf, -inf));
    this->Scale = glm::vec3(this->Grid.res) / (hi - lo);
  }

  /// Adds value range [a, b] over the world box [blo, bhi].
  void add(const glm::vec3& blo, const glm::vec3& bhi, float a, float b)
  {
    const float pad = 1e-3f;
    const glm::ivec3 c0 =
      glm::clamp(glm::ivec3(glm::floor((blo - this->Grid.lo) * this->Scale - pad)),
        glm::ivec3(0),
        this->Grid.res - 1);
    const glm::ivec3 c1 =
      glm::clamp(glm::ivec3(glm::floor((bhi - this->Grid.lo) * this->Scale + pad)),
        glm::ivec3(0),
        this->Grid.res - 1);
    for (int z = c0.z; z <= c1.z; ++z)
      for (int y = c0.y; y <= c1.y; ++y)
        for (int x = c0.x; x <= c1.x; ++x)
        {
          glm::vec2& r =
            this->Grid.range[(std::size_t(z) * this->Grid.res.y + y) * this->Grid.res.x + x];
          r.x = std::min(r.x, a);
          r.y = std::max(r.y, b);
        }
  }

  /// The grid with majorants for `tf`.
  amrdm::MajorantGrid finish(const amrdm::TransferFunctionView& tf)
  {
    amrdm::updateMajorants(this->Grid, tf);
    return this->Grid;
  }

private:
  amrdm::MajorantGrid Grid;
  glm::vec3 Scale{ 1.0f };
};

/// Every visible leaf cell as a box with its value.
inline amrdm::MajorantGrid buildNearestCellMajorants(const NearestCellField& f,
  glm::ivec3 res,
  const amrdm::TransferFunctionView& tf)
{
  MajorantRangeBuilder builder(f.lo, f.hi, res);
  const glm::vec3 spacing(f.amr.finestSpacing);
  for (const amrdm::AmrBlock& b : f.amr.blocks)
  {
    const float w = float(f.amr.levelWidth(b.level));
    for (int k = 0; k < b.dims.z; ++k)
      for (int j = 0; j < b.dims.y; ++j)
        for (int i = 0; i < b.dims.x; ++i)
        {
          const std::size_t id = (std::size_t(k) * b.dims.y + j) * b.dims.x + i;
          if (b.state[id] != amrdm::CellLeaf)
            continue;
          const glm::vec3 c = glm::vec3(b.lower + glm::ivec3(i, j, k)) * w;
          builder.add(
            f.origin + c * spacing, f.origin + (c + w) * spacing, b.values[id], b.values[id]);
        }
  }
  return builder.finish(tf);
}

/// Every cell between 8 grid values as a box with their range.
inline amrdm::MajorantGrid buildUniformGridMajorants(const UniformGrid& g,
  glm::ivec3 res,
  const amrdm::TransferFunctionView& tf)
{
  MajorantRangeBuilder builder(g.lo, g.hi, res);
  const int nx = g.dims.x, nxy = g.dims.x * g.dims.y;
  for (int k = 0; k + 1 < g.dims.z; ++k)
    for (int j = 0; j + 1 < g.dims.y; ++j)
      for (int i = 0; i + 1 < g.dims.x; ++i)
      {
        const float* s = g.values.data() + std::size_t(k) * nxy + std::size_t(j) * nx + i;
        const float v[8] = {
          s[0], s[1], s[nx], s[nx + 1], s[nxy], s[nxy + 1], s[nxy + nx], s[nxy + nx + 1]
        };
        float a = v[0], b = v[0];
        bool nan = false;
        for (float x : v)
        {
          nan |= std::isnan(x);
          a = std::min(a, x);
          b = std::max(b, x);
        }
        if (nan)
          continue; // no data in this cell: value() returns false there
        builder.add(g.point(i, j, k), g.point(i + 1, j + 1, k + 1), a, b);
      }
  return builder.finish(tf);
}

} // namespace amrdm_bench
