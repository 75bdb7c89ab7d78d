// The composite majorant grid: see CompositeMajorantGrid.h.
#include "accel/CompositeMajorantGrid.h"

#include "core/Ray.h"
#include "core/Tolerances.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace amrdm
{
namespace
{
/// Macrocell index range [c0, c1] of `g` overlapping the world box [a, b] grown by
/// kMacrocellPad of a macrocell (a point rounded across a face still finds its range).
bool overlapped(const MajorantGrid& g,
  const glm::vec3& a,
  const glm::vec3& b,
  glm::ivec3& c0,
  glm::ivec3& c1)
{
  for (int d = 0; d < 3; ++d)
  {
    const double cell = double(g.hi[d] - g.lo[d]) / g.res[d];
    const double pad = kMacrocellPad * cell;
    if (!(double(b[d]) + pad >= g.lo[d] && double(a[d]) - pad <= g.hi[d]))
    {
      return false;
    }
    c0[d] = std::clamp(int(std::floor((double(a[d]) - pad - g.lo[d]) / cell)), 0, g.res[d] - 1);
    c1[d] = std::clamp(int(std::floor((double(b[d]) + pad - g.lo[d]) / cell)), 0, g.res[d] - 1);
  }
  return true;
}

void checkRanges(const MajorantGrid& g, const char* which)
{
  const std::size_t n =
    std::size_t(std::max(g.res.x, 0)) * std::max(g.res.y, 0) * std::max(g.res.z, 0);
  if (n == 0 || g.range.size() != n || g.cellWidth.size() != n)
  {
    throw std::invalid_argument(std::string("composite majorant grid: the ") + which +
                                " grid has no value ranges; expected buildMajorantRanges() output");
  }
}
}

glm::ivec3 compositeMajorantResolution(const MajorantGrid& inner,
  const glm::vec3& domainLo,
  const glm::vec3& domainHi)
{
  glm::ivec3 res(1);
  for (int d = 0; d < 3; ++d)
  {
    const float cell = inner.res[d] > 0 ? (inner.hi[d] - inner.lo[d]) / inner.res[d] : 0.0f;
    const float extent = domainHi[d] - domainLo[d];
    if (cell > 0.0f && extent > 0.0f)
    {
      res[d] = std::clamp(int(std::ceil(extent / cell)), 1, kDefaultMaxMacrocellsPerAxis);
    }
  }
  return res;
}

MajorantGrid compositeMajorantRanges(const MajorantGrid& outer,
  const MajorantGrid& inner,
  const glm::vec3& lo,
  const glm::vec3& hi)
{
  checkRanges(outer, "outer (proxy)");
  checkRanges(inner, "inner (region)");
  if (!glm::all(glm::lessThan(lo, hi)))
  {
    throw std::invalid_argument("composite majorant grid: the region's box is empty; expected "
                                "lo < hi on every axis");
  }
  MajorantGrid grid;
  grid.res = outer.res;
  grid.lo = outer.lo;
  grid.hi = outer.hi;
  const std::size_t n = outer.range.size();
  grid.range.assign(n, glm::vec2(kInfinity, -kInfinity));
  grid.cellWidth.assign(n, kInfinity);
  const MajorantGridView view = grid.view(), innerView = inner.view();
  const glm::vec3 cell = (grid.hi - grid.lo) / glm::vec3(grid.res);
  // Grown by the pad: a point rounded across the box's face is the proxy's.
  const glm::vec3 pad = float(kMacrocellPad) * cell;
  // The proxy answers wherever a macrocell reaches outside the box.
  for (int z = 0; z < grid.res.z; ++z)
    for (int y = 0; y < grid.res.y; ++y)
      for (int x = 0; x < grid.res.x; ++x)
      {
        const glm::ivec3 c(x, y, z);
        const glm::vec3 a = grid.lo + glm::vec3(c) * cell - pad, b = a + cell + 2.0f * pad;
        if (glm::all(glm::greaterThan(a, lo)) && glm::all(glm::lessThan(b, hi)))
        {
          continue; // wholly inside: only the region's mesh answers there
        }
        const std::size_t i = std::size_t(macrocellIndex(view, c));
        grid.range[i] = outer.range[i];
        grid.cellWidth[i] = outer.cellWidth[i];
      }
  // The region's mesh inside the box.
  const glm::vec3 icell = (inner.hi - inner.lo) / glm::vec3(inner.res);
  for (int z = 0; z < inner.res.z; ++z)
    for (int y = 0; y < inner.res.y; ++y)
      for (int x = 0; x < inner.res.x; ++x)
      {
        const glm::ivec3 ic(x, y, z);
        const std::size_t ii = std::size_t(macrocellIndex(innerView, ic));
        const glm::vec2 r = inner.range[ii];
        if (!(r.x <= r.y))
        {
          continue; // no primitive there
        }
        const glm::vec3 a = glm::max(inner.lo + glm::vec3(ic) * icell, lo);
        const glm::vec3 b = glm::min(inner.lo + glm::vec3(ic + 1) * icell, hi);
        glm::ivec3 c0, c1;
        if (glm::any(glm::greaterThan(a, b)) || !overlapped(grid, a, b, c0, c1))
        {
          continue; // the ghost band outside the box
        }
        for (int cz = c0.z; cz <= c1.z; ++cz)
          for (int cy = c0.y; cy <= c1.y; ++cy)
            for (int cx = c0.x; cx <= c1.x; ++cx)
            {
              const std::size_t i = std::size_t(macrocellIndex(view, glm::ivec3(cx, cy, cz)));
              grid.range[i].x = std::min(grid.range[i].x, r.x);
              grid.range[i].y = std::max(grid.range[i].y, r.y);
              grid.cellWidth[i] = std::min(grid.cellWidth[i], inner.cellWidth[ii]);
            }
      }
  return grid;
}

} // namespace amrdm
