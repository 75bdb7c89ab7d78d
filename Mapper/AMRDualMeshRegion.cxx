#include "AMRDualMeshRegion.h"

namespace amrdm_vtk
{
bool RegionClip::Set(int index, const double regionBounds[6], const double domainBounds[6])
{
  bool same = this->Active() && this->Index == index;
  for (int i = 0; i < 6 && same; ++i)
  {
    same = this->Bounds[i] == regionBounds[i] && this->Domain[i] == domainBounds[i];
  }
  if (same)
  {
    return false;
  }
  this->Index = index < 0 ? 0 : index;
  for (int i = 0; i < 6; ++i)
  {
    this->Bounds[i] = regionBounds[i];
    this->Domain[i] = domainBounds[i];
  }
  return true;
}

unsigned RegionClip::SeedFor(unsigned seed, bool independent) const
{
  if (!this->Active() || !independent)
  {
    return seed;
  }
  unsigned h = static_cast<unsigned>(this->Index) + 1u;
  h *= 0x9E3779B9u;
  h ^= h >> 16;
  return seed ^ h;
}
}
