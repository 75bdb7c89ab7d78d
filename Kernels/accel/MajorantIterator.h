// 3D DDA (Amanatides-Woo) through the majorant grid, in the shape of pbrt-v4's
// DDAMajorantIterator: next() yields segments {t0, t1, sigmaMaj} that tile the ray interval
// clipped to the grid bounds exactly (each t0 equals the previous t1; the last t1 is the
// clipped tmax) and never step past it. Host/device code.
#pragma once

#include "accel/MajorantGrid.h"
#include "core/Ray.h"

namespace amrdm
{

struct MajorantSegment
{
  float t0 = 0.0f, t1 = 0.0f; ///< ray parameter interval (world units along a unit direction)
  float sigmaMaj = 0.0f;      ///< extinction majorant on it, world units^-1
  int cell = 0;               ///< macrocell index (macrocellIndex) the segment lies in
};

class DdaMajorantIterator
{
public:
  AMRDM_HD DdaMajorantIterator() = default;

  /// Walks `ray` over [tmin, tmax] ∩ grid bounds.
  AMRDM_HD DdaMajorantIterator(const MajorantGridView& grid, const Ray& ray, float tmin, float tmax)
    : Grid(grid)
  {
    this->TMin = tmin;
    this->TMax = tmax;
    if (grid.res.x <= 0 || !clipRayToBox(ray, grid.lo, grid.hi, this->TMin, this->TMax))
    {
      this->TMin = this->TMax = 0.0f;
      return;
    }
    // Set up the DDA in macrocell units (voxel size 1).
    const glm::vec3 scale = glm::vec3(grid.res) / (grid.hi - grid.lo);
    const glm::vec3 pEntry = (ray.at(this->TMin) - grid.lo) * scale;
    const glm::vec3 dGrid = ray.d * scale;
    for (int a = 0; a < 3; ++a)
    {
      this->Voxel[a] = glm::clamp(int(glm::floor(pEntry[a])), 0, grid.res[a] - 1);
      if (dGrid[a] == 0.0f)
      {
        this->NextCrossing[a] = kInfinity;
        this->DeltaT[a] = kInfinity;
        this->Step[a] = 0;
        this->Limit[a] = -2;
      }
      else if (dGrid[a] > 0.0f)
      {
        this->NextCrossing[a] = this->TMin + (float(this->Voxel[a] + 1) - pEntry[a]) / dGrid[a];
        this->DeltaT[a] = 1.0f / dGrid[a];
        this->Step[a] = 1;
        this->Limit[a] = grid.res[a];
      }
      else
      {
        this->NextCrossing[a] = this->TMin + (float(this->Voxel[a]) - pEntry[a]) / dGrid[a];
        this->DeltaT[a] = -1.0f / dGrid[a];
        this->Step[a] = -1;
        this->Limit[a] = -1;
      }
    }
  }

  /// The clipped interval the segments tile.
  AMRDM_HD float tEnter() const { return this->TMin; }

  /// The next segment; false when the interval is exhausted.
  AMRDM_HD AMRDM_FORCE_INLINE bool next(MajorantSegment& seg)
  {
    if (!(this->TMin < this->TMax))
    {
      return false;
    }
    // Axis whose macrocell face the ray crosses first.
    const int axis = this->NextCrossing[0] < this->NextCrossing[1]
                       ? (this->NextCrossing[0] < this->NextCrossing[2] ? 0 : 2)
                       : (this->NextCrossing[1] < this->NextCrossing[2] ? 1 : 2);
    seg.t0 = this->TMin;
    const int cell = macrocellIndex(this->Grid, this->Voxel);
    seg.sigmaMaj = this->Grid.majorant[cell];
    seg.cell = cell;
    const bool leaves = this->Voxel[axis] + this->Step[axis] == this->Limit[axis];
    if (leaves || !(this->NextCrossing[axis] < this->TMax))
    {
      // Last segment: ends exactly at tmax (also when rounding exits the grid a bit early).
      seg.t1 = this->TMax;
      this->TMin = this->TMax;
      return true;
    }
    seg.t1 = glm::max(this->TMin, this->NextCrossing[axis]);
    this->TMin = seg.t1;
    this->Voxel[axis] += this->Step[axis];
    this->NextCrossing[axis] += this->DeltaT[axis];
    return true;
  }

private:
  MajorantGridView Grid;
  float TMin = 0.0f, TMax = 0.0f;
  float NextCrossing[3] = { 0.0f, 0.0f, 0.0f };
  float DeltaT[3] = { 0.0f, 0.0f, 0.0f };
  int Step[3] = { 0, 0, 0 };
  int Limit[3] = { 0, 0, 0 };
  glm::ivec3 Voxel{ 0 };
};

} // namespace amrdm
