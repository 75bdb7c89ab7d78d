// Gridlets: same-level dual cells clustered into aligned blocks of up to G^3 dual cells that store
// (dims+1)^3 vertex scalars. A NaN vertex means "no perfect dual cube here"; a cell with any NaN
// corner is not part of the gridlet and the point falls through to a stitching element.
#pragma once

#include "core/HostDevice.h"

#include <cstdint>

namespace amrdm
{

/// 32 bytes. Dual cell (i, j, k) of the gridlet spans the cell centres lower+(i,j,k) .. +1 on
/// `level`, i.e. grid space [(lower + (i,j,k) + 0.5) * width, (lower + (i,j,k) + 1.5) * width).
/// Vertex-centred meshes (DualMesh::gridletOrigin 0) store primal cells: cell (i, j, k) spans
/// [(lower + (i,j,k)) * width, (lower + (i,j,k) + 1) * width), trilinear over its corners.
struct GridletHeader
{
  glm::ivec3 lower;    ///< first dual cell = index of its lower corner cell on `level`
  std::int32_t level;  ///< AMR level (0 = coarsest)
  glm::ivec3 dims;     ///< dual cells per axis, 1..G
  std::uint32_t begin; ///< offset of the first scalar in the shared scalar array
};
static_assert(sizeof(GridletHeader) == 32, "GridletHeader must stay 32 bytes");

/// Trilinear sample of gridlet `g` at grid-space point p (float, or double for host queries in
/// deep hierarchies: the gridlet-local coordinates are formed in p's precision, then float).
/// `origin` is the mesh's gridletOrigin (0.5: dual cells; 0: primal cells of vertex data).
/// False when p is outside the gridlet's box or in a cell with a NaN corner (not a perfect dual
/// cube of this gridlet).
template<typename T>
AMRDM_HD bool sampleGridlet(const GridletHeader& g,
  const float* scalars,
  float width,
  float origin,
  const glm::vec<3, T>& p,
  float& value,
  int* cellId = nullptr)
{
  // The cell is chosen in p's precision (a double point just below a cell face must not round
  // into the next cell, whose corners may be NaN); only the fraction inside it becomes float.
  const glm::vec<3, T> local = p / T(width) - T(origin) - glm::vec<3, T>(g.lower);
  const glm::vec<3, T> dims(g.dims);
  if (!(local.x >= T(0) && local.y >= T(0) && local.z >= T(0) && local.x <= dims.x &&
        local.y <= dims.y && local.z <= dims.z))
  {
    return false;
  }
  const glm::ivec3 cell = glm::min(glm::ivec3(local), g.dims - 1);
  const glm::vec3 f(local - glm::vec<3, T>(cell));
  const int nx = g.dims.x + 1;
  const int ny = g.dims.y + 1;
  const float* s = scalars + g.begin + (cell.z * ny + cell.y) * nx + cell.x;
  const float v000 = s[0], v100 = s[1], v010 = s[nx], v110 = s[nx + 1];
  const float v001 = s[nx * ny], v101 = s[nx * ny + 1], v011 = s[nx * ny + nx],
              v111 = s[nx * ny + nx + 1];
  // NaN marks an empty vertex (x != x only for NaN).
  if ((v000 != v000) | (v100 != v100) | (v010 != v010) | (v110 != v110) | (v001 != v001) |
      (v101 != v101) | (v011 != v011) | (v111 != v111))
  {
    return false;
  }
  const float x00 = v000 + f.x * (v100 - v000), x10 = v010 + f.x * (v110 - v010);
  const float x01 = v001 + f.x * (v101 - v001), x11 = v011 + f.x * (v111 - v011);
  const float y0 = x00 + f.y * (x10 - x00), y1 = x01 + f.y * (x11 - x01);
  value = y0 + f.z * (y1 - y0);
  if (cellId)
  {
    *cellId = (cell.z * g.dims.y + cell.y) * g.dims.x + cell.x;
  }
  return true;
}

} // namespace amrdm
