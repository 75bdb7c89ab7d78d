// An independent, slow construction of the dual mesh for small inputs: for every lattice cell
// of every level, the 8 neighbouring centres are located by scanning all leaf cells. A corner
// beyond a face of the domain box is the leaf at the corner clamped into the domain, with its
// centre moved onto that face (the clamped boundary layer): a dual cell whose corners are all
// level-L leaves, ghosts included, is perfect (a boundary cube: the builder puts it in a gridlet).
#pragma once

#include "mesh/AmrHierarchy.h"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace amrdm_test
{

/// A dual cell as the sorted list of its distinct corner positions (doubled grid coordinates,
/// which are integers).
using CornerSet = std::vector<std::array<long long, 3>>;

struct BruteForceResult
{
  std::vector<long long> perfectPerLevel;
  std::vector<CornerSet> stitching; ///< non-perfect, non-flat dual cells
};

inline BruteForceResult bruteForceDual(const amrdm::AmrHierarchy& amr)
{
  struct Leaf
  {
    int level;
    glm::ivec3 c;
    long long w;
  };
  std::vector<Leaf> leaves;
  for (const auto& b : amr.blocks)
  {
    for (int z = 0; z < b.dims.z; ++z)
      for (int y = 0; y < b.dims.y; ++y)
        for (int x = 0; x < b.dims.x; ++x)
        {
          const glm::ivec3 c = b.lower + glm::ivec3(x, y, z);
          if (b.state[static_cast<std::size_t>(b.cellIndex(c))] == amrdm::CellLeaf)
            leaves.push_back({ b.level, c, amr.levelWidth(b.level) });
        }
  }
  // Locate by scanning: point given in doubled finest units (to keep centres integral).
  auto locate = [&](const std::array<long long, 3>& p2) -> const Leaf*
  {
    for (const Leaf& leaf : leaves)
    {
      bool in = true;
      for (int d = 0; d < 3 && in; ++d)
      {
        const long long lo = 2 * leaf.c[d] * leaf.w, hi = 2 * (leaf.c[d] + 1) * leaf.w;
        in = p2[d] >= lo && p2[d] < hi;
      }
      if (in)
        return &leaf;
    }
    return nullptr;
  };
  const amrdm::GridBox domain = amr.domainBox();
  BruteForceResult result;
  result.perfectPerLevel.assign(static_cast<std::size_t>(amr.numLevels()), 0);
  for (int L = 0; L < amr.numLevels(); ++L)
  {
    const long long w = amr.levelWidth(L);
    glm::ivec3 lo(1 << 30), hi(-(1 << 30));
    for (const auto& b : amr.blocks)
    {
      // Lattice range of level L covering this block's extent (in level-L cells).
      const long long bw = amr.levelWidth(b.level);
      for (int d = 0; d < 3; ++d)
      {
        lo[d] = std::min<long long>(lo[d], (b.lower[d] * bw) / w - 1);
        hi[d] = std::max<long long>(hi[d], ((b.lower[d] + b.dims[d]) * bw) / w + 1);
      }
    }
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x)
        {
          const Leaf* corner[8];
          std::array<long long, 3> position[8]; // doubled; ghosts on the domain faces
          bool ok = true, anyAtL = false, allAtL = true, anyCell = false;
          for (int k = 0; k < 8 && ok; ++k)
          {
            const glm::ivec3 c(x + (k & 1), y + ((k >> 1) & 1), z + ((k >> 2) & 1));
            std::array<long long, 3> p2{
              (2LL * c.x + 1) * w, (2LL * c.y + 1) * w, (2LL * c.z + 1) * w
            };
            bool ghost = false;
            std::array<long long, 3> face{ 0, 0, 0 };
            std::array<bool, 3> onFace{ false, false, false };
            for (int d = 0; d < 3; ++d)
            {
              const long long lo = 2LL * domain.lower[d], hi = 2LL * domain.upper[d];
              if (p2[d] < lo || p2[d] > hi)
              {
                ghost = true;
                face[d] = p2[d] < lo ? lo : hi;
                onFace[d] = true;
                p2[d] = p2[d] < lo ? lo + w : hi - w; // the first / last level-L cell's centre
              }
            }
            corner[k] = locate(p2);
            ok = corner[k] && corner[k]->level <= L;
            if (ok)
            {
              const Leaf& leaf = *corner[k];
              for (int d = 0; d < 3; ++d)
                position[k][static_cast<std::size_t>(d)] =
                  onFace[d] ? face[d] : (2LL * leaf.c[d] + 1) * leaf.w;
              anyCell = anyCell || !ghost;
              anyAtL = anyAtL || leaf.level == L;
              allAtL = allAtL && leaf.level == L;
            }
          }
          if (!ok || !anyAtL || !anyCell)
            continue;
          if (allAtL)
          {
            ++result.perfectPerLevel[static_cast<std::size_t>(L)];
            continue;
          }
          CornerSet set(position, position + 8);
          std::sort(set.begin(), set.end());
          set.erase(std::unique(set.begin(), set.end()), set.end());
          if (set.size() < 4)
            continue;
          // Flat when every distinct corner lies in the plane of the first three that span one.
          bool flat = true;
          const glm::dvec3 p0(set[0][0], set[0][1], set[0][2]);
          glm::dvec3 normal(0.0);
          for (std::size_t a = 1; a < set.size() && glm::length(normal) == 0.0; ++a)
            for (std::size_t b = a + 1; b < set.size() && glm::length(normal) == 0.0; ++b)
              normal = glm::cross(glm::dvec3(set[a][0], set[a][1], set[a][2]) - p0,
                glm::dvec3(set[b][0], set[b][1], set[b][2]) - p0);
          for (const auto& q : set)
            flat = flat && std::abs(glm::dot(glm::dvec3(q[0], q[1], q[2]) - p0, normal)) == 0.0;
          if (!flat)
            result.stitching.push_back(set);
        }
  }
  std::sort(result.stitching.begin(), result.stitching.end());
  return result;
}

} // namespace amrdm_test
