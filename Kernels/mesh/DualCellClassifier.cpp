// Classification of non-perfect dual cells into stitching elements (see DualMeshBuilder.h).
#include "mesh/DualMeshBuilder.h"

#include <algorithm>
#include <cmath>

namespace amrdm
{

namespace
{
/// Bit-order corner index of VTK hexahedron corner v.
constexpr int kHexVtkToBit[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };

/// A dual cell is dropped as flat when its volume is below this fraction of its bounding box.
constexpr double kFlatVolumeFraction = 1e-9;

int bit(int n, int nValue, int a, int aValue, int c, int cValue)
{
  return (nValue << n) | (aValue << a) | (cValue << c);
}

/// Volume of the (possibly degenerate) trilinear hex, from its 5-tet decomposition magnitudes.
double absVolume(const glm::dvec3* p /* bit order */)
{
  auto tet = [&](int a, int b, int c, int d)
  { return std::abs(glm::dot(p[b] - p[a], glm::cross(p[c] - p[a], p[d] - p[a]))) / 6.0; };
  return tet(0, 1, 2, 4) + tet(1, 3, 2, 7) + tet(1, 2, 4, 7) + tet(1, 4, 5, 7) + tet(2, 4, 6, 7);
}
} // namespace

ClassifiedElement classifyDualCell(const DualCellCorners& cell, const glm::dvec3 (&p)[8])
{
  ClassifiedElement out;
  const std::int64_t* id = cell.id;
  std::int64_t sorted[8];
  std::copy(id, id + 8, sorted);
  std::sort(sorted, sorted + 8);
  const int unique = static_cast<int>(std::unique(sorted, sorted + 8) - sorted);
  if (unique < 4)
  {
    return out; // dropped
  }
  glm::dvec3 lo = p[0], hi = p[0];
  for (int k = 1; k < 8; ++k)
  {
    lo = glm::min(lo, p[k]);
    hi = glm::max(hi, p[k]);
  }
  const glm::dvec3 ext = hi - lo;
  if (absVolume(p) <= kFlatVolumeFraction * ext.x * ext.y * ext.z)
  {
    return out; // dropped: flat
  }
  if (unique == 8)
  {
    out.type = PrimHex;
    out.numCorners = 8;
    for (int v = 0; v < 8; ++v)
    {
      out.corner.set(v, id[kHexVtkToBit[v]]);
    }
    return out;
  }
  // Faces: normal axis n, side s; in-face axes a < c; cyclic corner order (0,0) (1,0) (1,1) (0,1).
  for (int n = 0; n < 3; ++n)
  {
    const int a = n == 0 ? 1 : 0;
    const int c = n == 2 ? 1 : 2;
    for (int s = 0; s < 2; ++s)
    {
      const int f[4] = {
        bit(n, s, a, 0, c, 0), bit(n, s, a, 1, c, 0), bit(n, s, a, 1, c, 1), bit(n, s, a, 0, c, 1)
      };
      const int o[4] = { bit(n, 1 - s, a, 0, c, 0),
        bit(n, 1 - s, a, 1, c, 0),
        bit(n, 1 - s, a, 1, c, 1),
        bit(n, 1 - s, a, 0, c, 1) };
      const bool pointFace = id[f[0]] == id[f[1]] && id[f[1]] == id[f[2]] && id[f[2]] == id[f[3]];
      if (pointFace)
      {
        if (unique == 5)
        {
          out.type = PrimPyramid;
          out.numCorners = 5;
          for (int v = 0; v < 4; ++v)
          {
            out.corner.set(v, id[o[v]]);
          }
          out.corner.set(4, id[f[0]]);
          return out;
        }
        if (unique == 4)
        {
          // The base lost one edge (adjacent pair equal): a tet. A lost diagonal is flat and was
          // dropped above.
          for (int e = 0; e < 4; ++e)
          {
            if (id[o[e]] == id[o[(e + 1) % 4]])
            {
              out.type = PrimTet;
              out.numCorners = 4;
              out.corner.set(0, id[o[(e + 1) % 4]]);
              out.corner.set(1, id[o[(e + 2) % 4]]);
              out.corner.set(2, id[o[(e + 3) % 4]]);
              out.corner.set(3, id[f[0]]);
              return out;
            }
          }
        }
      }
      if (unique == 6)
      {
        // Two opposite edges of this face collapsed: the face became a segment, the cell a wedge
        // whose triangles lie across the other in-face axis.
        const bool alongA = id[f[0]] == id[f[1]] && id[f[3]] == id[f[2]] && id[f[0]] != id[f[3]];
        const bool alongC = id[f[0]] == id[f[3]] && id[f[1]] == id[f[2]] && id[f[0]] != id[f[1]];
        if (alongA || alongC)
        {
          const int seg = alongA ? a : c; // collapsed direction
          const int tri = alongA ? c : a; // triangles at tri = 0 and tri = 1
          out.type = PrimWedge;
          out.numCorners = 6;
          for (int t = 0; t < 2; ++t)
          {
            out.corner.set(3 * t + 0, id[bit(n, 1 - s, seg, 0, tri, t)]);
            out.corner.set(3 * t + 1, id[bit(n, 1 - s, seg, 1, tri, t)]);
            out.corner.set(3 * t + 2, id[bit(n, s, seg, 0, tri, t)]);
          }
          return out;
        }
      }
    }
  }
  out.type = PrimHex;
  out.numCorners = 8;
  out.degenerateHex = true;
  for (int v = 0; v < 8; ++v)
  {
    out.corner.set(v, id[kHexVtkToBit[v]]);
  }
  return out;
}

} // namespace amrdm
