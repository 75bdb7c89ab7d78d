// Alternative sampler for the benchmark: the field resampled to a uniform grid, then trilinear.
// Layout as ParaView's AMR "Volume" representation (vtkResampledAMRImageSource): the data bounds
// are cut into dims cells, each cell gets one value, and the renderer interpolates trilinearly
// between the cell centres (the "dual grid" it hands to the volume mapper), so the outer half cell
// is empty. The value of a cell comes from
//   - Donor: the leaf cell containing the cell centre (ParaView's donor-cell copy), or
//   - DualMesh: the exact dual-mesh interpolant at the cell centre (donor where the dual mesh
//     has no value, i.e. in the outer half of the boundary cells).
// Host-only. Memory: 4 bytes per grid value.
#pragma once

#include "FieldMedium.h"

#include "transport/DeltaTracking.h"
#include "core/ParallelFor.h"
#include "sampling/TransferFunction.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace amrdm_bench
{

struct UniformGrid
{
  glm::ivec3 dims{ 0 };             ///< values per axis
  glm::vec3 lo{ 0.0f }, hi{ 0.0f }; ///< data bounds (world)
  glm::vec3 spacing{ 1.0f };
  std::vector<float> values; ///< x fastest; NaN = no data

  /// Cell centre of value (i, j, k).
  glm::vec3 point(int i, int j, int k) const
  {
    return this->lo + (glm::vec3(i, j, k) + 0.5f) * this->spacing;
  }

  /// Fills dims.x*dims.y*dims.z values from source(p, v) -> bool, in parallel.
  template<typename Source>
  void fill(const glm::vec3& boundsLo,
    const glm::vec3& boundsHi,
    glm::ivec3 n,
    Source&& source,
    int threads = 0)
  {
    this->dims = glm::max(n, glm::ivec3(2));
    this->lo = boundsLo;
    this->hi = boundsHi;
    this->spacing = (boundsHi - boundsLo) / glm::vec3(this->dims);
    this->values.assign(std::size_t(this->dims.x) * this->dims.y * this->dims.z,
      std::numeric_limits<float>::quiet_NaN());
    amrdm::parallelFor(std::size_t(this->dims.z) * this->dims.y,
      threads,
      [&](std::size_t row)
      {
        const int j = int(row % std::size_t(this->dims.y)),
                  k = int(row / std::size_t(this->dims.y));
        float* out = this->values.data() + row * std::size_t(this->dims.x);
        for (int i = 0; i < this->dims.x; ++i)
        {
          float v;
          if (source(this->point(i, j, k), v))
          {
            out[i] = v;
          }
        }
      });
  }

  std::uint64_t bytes() const { return 4u * std::uint64_t(this->values.size()); }

  /// Trilinear value at world point p; false outside the hull of the cell centres or next to a
  /// NaN value.
  bool value(const glm::vec3& p, float& v) const
  {
    const glm::vec3 x = (p - this->lo) / this->spacing - 0.5f;
    const glm::vec3 top = glm::vec3(this->dims - 1);
    if (!(x.x >= 0.0f && x.y >= 0.0f && x.z >= 0.0f && x.x <= top.x && x.y <= top.y &&
          x.z <= top.z))
    {
      return false;
    }
    const glm::ivec3 c = glm::min(glm::ivec3(x), this->dims - 2);
    const glm::vec3 f = x - glm::vec3(c);
    const int nx = this->dims.x, nxy = this->dims.x * this->dims.y;
    const float* s = this->values.data() + std::size_t(c.z) * nxy + std::size_t(c.y) * nx + c.x;
    const float v000 = s[0], v100 = s[1], v010 = s[nx], v110 = s[nx + 1];
    const float v001 = s[nxy], v101 = s[nxy + 1], v011 = s[nxy + nx], v111 = s[nxy + nx + 1];
    if (std::isnan(v000 + v100 + v010 + v110 + v001 + v101 + v011 + v111))
    {
      return false;
    }
    const float x00 = v000 + f.x * (v100 - v000), x10 = v010 + f.x * (v110 - v010);
    const float x01 = v001 + f.x * (v101 - v001), x11 = v011 + f.x * (v111 - v011);
    const float y0 = x00 + f.y * (x10 - x00), y1 = x01 + f.y * (x11 - x01);
    v = y0 + f.z * (y1 - y0);
    return true;
  }
};

/// The medium interface of Kernels/sampling/Media.h over a UniformGrid.
using UniformGridMedium = FieldMedium<UniformGrid>;

} // namespace amrdm_bench
