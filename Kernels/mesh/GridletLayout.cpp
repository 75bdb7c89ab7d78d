// See GridletLayout.h.
#include "mesh/GridletLayout.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace amrdm
{

std::vector<glm::ivec3> gridletBlockOrigins(const AmrHierarchy& amr)
{
  const GridBox domain = amr.domainBox();
  std::vector<glm::ivec3> origin(static_cast<std::size_t>(amr.numLevels()));
  for (int l = 0; l < amr.numLevels(); ++l)
  {
    origin[static_cast<std::size_t>(l)] =
      domain.lower / static_cast<int>(amr.levelWidth(l)) - glm::ivec3(1);
  }
  return origin;
}

std::int64_t alignedBlocksTouched(const glm::ivec3& origin,
  int gridletSize,
  const glm::ivec3& lo,
  const glm::ivec3& hi)
{
  std::int64_t n = 1;
  for (int axis = 0; axis < 3; ++axis)
  {
    n *= floorDiv(hi[axis] - origin[axis], gridletSize) -
         floorDiv(lo[axis] - origin[axis], gridletSize) + 1;
  }
  return n;
}

void ItemGridletPieces::begin(int level_,
  const glm::ivec3& origin_,
  int gridletSize,
  glm::ivec3 lo,
  glm::ivec3 hi)
{
  this->level = level_;
  this->size = gridletSize;
  this->origin = origin_;
  this->cubes = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    this->first[axis] = floorDiv(lo[axis] - origin_[axis], gridletSize);
    this->count[axis] = floorDiv(hi[axis] - origin_[axis], gridletSize) - this->first[axis] + 1;
  }
  const Range empty{ glm::ivec3(std::numeric_limits<int>::max()),
    glm::ivec3(std::numeric_limits<int>::min()) };
  this->table.assign(
    static_cast<std::size_t>(alignedBlocksTouched(origin_, gridletSize, lo, hi)), empty);
}

void ItemGridletPieces::addRun(const glm::ivec3& lower, int length)
{
  const int G = this->size;
  const glm::ivec3 o = this->origin;
  const int ky = floorDiv(lower.y - o.y, G) - this->first.y;
  const int kz = floorDiv(lower.z - o.z, G) - this->first.z;
  if (length < 1 || ky < 0 || kz < 0 || ky >= this->count.y || kz >= this->count.z)
  {
    throw std::out_of_range("a perfect-cube run at (" + std::to_string(lower.x) + ", " +
                            std::to_string(lower.y) + ", " + std::to_string(lower.z) +
                            ") of length " + std::to_string(length) +
                            " lies outside its work item's range");
  }
  const std::size_t row = (static_cast<std::size_t>(kz) * static_cast<std::size_t>(this->count.y) +
                            static_cast<std::size_t>(ky)) *
                          static_cast<std::size_t>(this->count.x);
  for (int x = lower.x; x < lower.x + length;)
  {
    const int kxGlobal = floorDiv(x - o.x, G);
    const int kx = kxGlobal - this->first.x;
    if (kx < 0 || kx >= this->count.x)
    {
      throw std::out_of_range(
        "a perfect-cube run reaches x = " + std::to_string(x) + ", outside its work item's range");
    }
    const int xEnd = std::min(lower.x + length, o.x + (kxGlobal + 1) * G); // exclusive
    Range& r = this->table[row + static_cast<std::size_t>(kx)];
    r.lo = glm::min(r.lo, glm::ivec3(x, lower.y, lower.z));
    r.hi = glm::max(r.hi, glm::ivec3(xEnd - 1, lower.y, lower.z));
    x = xEnd;
  }
  this->cubes += length;
}

std::int64_t ItemGridletPieces::finish(std::vector<GridletPiece>& out)
{
  std::size_t i = 0;
  for (int z = 0; z < this->count.z; ++z)
    for (int y = 0; y < this->count.y; ++y)
      for (int x = 0; x < this->count.x; ++x, ++i)
      {
        const Range& r = this->table[i];
        if (r.lo.x <= r.hi.x)
        {
          out.push_back({ this->level, this->first + glm::ivec3(x, y, z), r.lo, r.hi });
        }
      }
  return this->cubes;
}

std::vector<GridletRange> gridletLayout(std::vector<GridletPiece> pieces)
{
  std::sort(pieces.begin(),
    pieces.end(),
    [](const GridletPiece& a, const GridletPiece& b)
    {
      if (a.level != b.level)
        return a.level < b.level;
      if (a.key.z != b.key.z)
        return a.key.z < b.key.z;
      if (a.key.y != b.key.y)
        return a.key.y < b.key.y;
      return a.key.x < b.key.x;
    });
  std::vector<GridletRange> out;
  for (std::size_t g = 0; g < pieces.size(); ++g)
  {
    if (g > 0 && pieces[g].level == pieces[g - 1].level && pieces[g].key == pieces[g - 1].key)
    {
      out.back().lo = glm::min(out.back().lo, pieces[g].lo);
      out.back().hi = glm::max(out.back().hi, pieces[g].hi);
      continue;
    }
    out.push_back({ pieces[g].level, pieces[g].lo, pieces[g].hi });
  }
  return out;
}

} // namespace amrdm
