// See BoundaryLayer.h.
#include "mesh/BoundaryLayer.h"

namespace amrdm
{

BoundaryLayer::BoundaryLayer(const AmrHierarchy& amr, const CellLocator& locator)
  : Amr(amr)
  , Locator(locator)
  , Domain(amr.domainBox())
{
}

CellRef BoundaryLayer::locate(int level, const glm::ivec3& c, BlockHint* hint) const
{
  // The domain lies on level-0 cell faces (AmrHierarchy::validate), so on every level's.
  const int w = static_cast<int>(this->Locator.levelWidth(level));
  glm::ivec3 clamped = c;
  int code = 0, weight = 1;
  for (int d = 0; d < 3; ++d, weight *= 3)
  {
    const int lo = this->Domain.lower[d] / w, hi = this->Domain.upper[d] / w - 1;
    if (c[d] < lo)
    {
      clamped[d] = lo;
      code += weight;
    }
    else if (c[d] > hi)
    {
      clamped[d] = hi;
      code += 2 * weight;
    }
  }
  CellRef ref = this->Locator.locate(level, clamped, hint);
  if (code != 0 && ref.kind == CellRef::Leaf)
  {
    ref.kind = CellRef::Ghost;
    ref.sides = static_cast<std::uint8_t>(code);
  }
  return ref;
}

std::int64_t BoundaryLayer::globalId(const CellRef& ref) const
{
  const std::int64_t id = this->Locator.globalId(ref);
  if (ref.kind != CellRef::Ghost)
  {
    return id;
  }
  return this->Locator.totalCells() + id * kCodes + ref.sides;
}

glm::dvec3 BoundaryLayer::centre(std::int64_t id) const
{
  if (!this->isGhost(id))
  {
    return this->Locator.centre(id);
  }
  const std::int64_t g = id - this->Locator.totalCells();
  CellRef ref = this->Locator.fromGlobalId(g / kCodes);
  ref.kind = CellRef::Ghost;
  ref.sides = static_cast<std::uint8_t>(g % kCodes);
  return this->centre(ref);
}

glm::dvec3 BoundaryLayer::centre(const CellRef& ref) const
{
  glm::dvec3 p = this->Locator.centre(ref);
  if (ref.kind != CellRef::Ghost)
  {
    return p;
  }
  int code = ref.sides;
  for (int d = 0; d < 3; ++d, code /= 3)
  {
    if (code % 3 == 1)
    {
      p[d] = this->Domain.lower[d];
    }
    else if (code % 3 == 2)
    {
      p[d] = this->Domain.upper[d];
    }
  }
  return p;
}

float BoundaryLayer::value(std::int64_t id) const
{
  return this->Locator.value(this->isGhost(id) ? (id - this->Locator.totalCells()) / kCodes : id);
}

} // namespace amrdm
