// Data-parallel rendering, mapper side: the region (one axis-aligned box of the AMR's data
// frame) this process draws when N MPI ranks render one AMR together (the ParaView
// representation sets it), and the whole domain's bounds, so that what must be the same on
// every rank (the automatic step size) does not follow the local data. The kernel clips every
// camera ray (after its sub-pixel jitter) to the region (RenderParams::clipToBox); secondary
// rays are not clipped. Not wrapped.
#ifndef AMRDualMeshRegion_h
#define AMRDualMeshRegion_h

namespace amrdm_vtk
{
class RegionClip
{
public:
  /// Region `index` >= 0 with its bounds and the domain's (xmin, xmax, ymin, ...), data frame.
  /// Returns whether the region changed.
  bool Set(int index, const double regionBounds[6], const double domainBounds[6]);
  /// No region (all of the input); returns whether there was one.
  bool Clear()
  {
    const bool was = this->Active();
    this->Index = -1;
    return was;
  }
  bool Active() const { return this->Index >= 0; }
  int Index = -1;
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  double Domain[6] = { 0, 0, 0, 0, 0, 0 };

  /// Seed of this region: `seed` itself without a region or for a deterministic integrator
  /// (`independent` false: ray marching, whose only randomness, the sub-pixel position and
  /// the step's jitter, then matches the one-rank image sample for sample), else a different
  /// stream per region: the front region's alpha and the back region's colour must be
  /// independent estimates, or the blend of their means is biased (of order 1/samples).
  unsigned SeedFor(unsigned seed, bool independent) const;
};
}

#endif
