// Random, properly nested AMR hierarchies for property tests (ratio 2 by default): every level's
// boxes lie at least one parent cell inside the parent level's region (except at the domain
// boundary), boxes of one level are disjoint, and boxes are split so that they touch.
#pragma once

#include "mesh/AmrHierarchy.h"

#include <algorithm>
#include <functional>
#include <random>
#include <vector>

namespace amrdm_test
{

struct SyntheticOptions
{
  int levels = 3; ///< 1..8
  int ratio = 2;
  glm::ivec3 rootCells{ 8 }; ///< level-0 domain in cells (one or more root blocks)
  int boxesPerLevel = 3;     ///< attempts per level
  int maxSplits = 2;         ///< split each box into up to 2^maxSplits touching boxes
  bool splitRoot = true;     ///< level 0 as several touching blocks
  int maxBoxCells = 6;       ///< largest refined box, in parent cells per axis
  int nestingBuffer = 1;     ///< parent cells between a level's boxes and the parent region's edge
};

/// Cell-centre field in grid space (finest units).
using Field = std::function<float(const glm::dvec3&)>;

inline void splitBox(std::mt19937& rng,
  glm::ivec3 lo,
  glm::ivec3 dims,
  int splits,
  std::vector<std::pair<glm::ivec3, glm::ivec3>>& out)
{
  if (splits <= 0)
  {
    out.push_back({ lo, dims });
    return;
  }
  const int axis = static_cast<int>(rng() % 3);
  if (dims[axis] < 2)
  {
    out.push_back({ lo, dims });
    return;
  }
  const int cut = 1 + static_cast<int>(rng() % static_cast<unsigned>(dims[axis] - 1));
  glm::ivec3 d0 = dims, d1 = dims, lo1 = lo;
  d0[axis] = cut;
  d1[axis] = dims[axis] - cut;
  lo1[axis] += cut;
  splitBox(rng, lo, d0, splits - 1, out);
  splitBox(rng, lo1, d1, splits - 1, out);
}

/// Builds the hierarchy and fills values with field(cell centre). Cell states are left empty
/// (computed by finalizeCellStates from coverage) unless `withStates`.
inline amrdm::AmrHierarchy makeSynthetic(unsigned seed,
  const SyntheticOptions& opt,
  const Field& field)
{
  std::mt19937 rng(seed);
  amrdm::AmrHierarchy amr;
  amr.ratio.assign(static_cast<std::size_t>(opt.levels), opt.ratio);
  amr.ratio[0] = 1;
  std::vector<std::pair<glm::ivec3, glm::ivec3>> boxes;
  splitBox(rng, glm::ivec3(0), opt.rootCells, opt.splitRoot ? 2 : 0, boxes);
  std::vector<std::pair<glm::ivec3, glm::ivec3>> levelBoxes[8];
  levelBoxes[0] = boxes;
  glm::ivec3 domain = opt.rootCells; // current level's domain in cells
  for (int l = 1; l < opt.levels; ++l)
  {
    // Coverage mask of level l-1 over its domain.
    const auto& parent = levelBoxes[l - 1];
    std::vector<char> covered(static_cast<std::size_t>(domain.x) * domain.y * domain.z, 0);
    auto at = [&](glm::ivec3 c) -> char&
    { return covered[(static_cast<std::size_t>(c.z) * domain.y + c.y) * domain.x + c.x]; };
    for (const auto& b : parent)
      for (int z = 0; z < b.second.z; ++z)
        for (int y = 0; y < b.second.y; ++y)
          for (int x = 0; x < b.second.x; ++x)
            at(b.first + glm::ivec3(x, y, z)) = 1;
    // Candidate: covered with a covered (or out-of-domain) 3x3x3 neighbourhood.
    auto candidate = [&](glm::ivec3 c)
    {
      const int b = opt.nestingBuffer;
      for (int dz = -b; dz <= b; ++dz)
        for (int dy = -b; dy <= b; ++dy)
          for (int dx = -b; dx <= b; ++dx)
          {
            const glm::ivec3 n = c + glm::ivec3(dx, dy, dz);
            if (glm::any(glm::lessThan(n, glm::ivec3(0))) ||
                glm::any(glm::greaterThanEqual(n, domain)))
              continue;
            if (!at(n))
              return false;
          }
      return at(c) != 0;
    };
    std::vector<char> taken(covered.size(), 0);
    std::vector<std::pair<glm::ivec3, glm::ivec3>> accepted;
    for (int attempt = 0;
         attempt < opt.boxesPerLevel * 8 && static_cast<int>(accepted.size()) < opt.boxesPerLevel;
         ++attempt)
    {
      glm::ivec3 dims, lo;
      for (int d = 0; d < 3; ++d)
      {
        dims[d] = 1 + static_cast<int>(rng() % static_cast<unsigned>(std::max(
                                                 1, std::min(opt.maxBoxCells, domain[d] / 2))));
        lo[d] = static_cast<int>(rng() % static_cast<unsigned>(domain[d] - dims[d] + 1));
      }
      bool ok = true;
      for (int z = 0; z < dims.z && ok; ++z)
        for (int y = 0; y < dims.y && ok; ++y)
          for (int x = 0; x < dims.x && ok; ++x)
          {
            const glm::ivec3 c = lo + glm::ivec3(x, y, z);
            ok = candidate(c) &&
                 !taken[(static_cast<std::size_t>(c.z) * domain.y + c.y) * domain.x + c.x];
          }
      if (!ok)
        continue;
      for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
          for (int x = 0; x < dims.x; ++x)
          {
            const glm::ivec3 c = lo + glm::ivec3(x, y, z);
            taken[(static_cast<std::size_t>(c.z) * domain.y + c.y) * domain.x + c.x] = 1;
          }
      accepted.push_back({ lo, dims });
    }
    domain *= opt.ratio;
    for (const auto& b : accepted)
    {
      splitBox(rng,
        b.first * opt.ratio,
        b.second * opt.ratio,
        static_cast<int>(rng() % static_cast<unsigned>(opt.maxSplits + 1)),
        levelBoxes[l]);
    }
    if (levelBoxes[l].empty())
    {
      amr.ratio.resize(static_cast<std::size_t>(l));
      break;
    }
  }
  for (int l = 0; l < amr.numLevels(); ++l)
  {
    const double w = static_cast<double>(amr.levelWidth(l));
    for (const auto& b : levelBoxes[l])
    {
      amrdm::AmrBlock block;
      block.level = l;
      block.lower = b.first;
      block.dims = b.second;
      block.values.resize(static_cast<std::size_t>(block.numCells()));
      std::size_t i = 0;
      for (int z = 0; z < block.dims.z; ++z)
        for (int y = 0; y < block.dims.y; ++y)
          for (int x = 0; x < block.dims.x; ++x)
            block.values[i++] = field((glm::dvec3(block.lower + glm::ivec3(x, y, z)) + 0.5) * w);
      amr.blocks.push_back(std::move(block));
    }
  }
  return amr;
}

/// Vertex field in grid space (finest units) and the level of the block being filled.
using VertexField = std::function<double(const glm::dvec3&, int level)>;

/// The hierarchy's box layout with point data: values = field(vertex position, level); the cell
/// states are cleared (finalizeCellStates() sets them again).
inline amrdm::AmrHierarchy withPointData(amrdm::AmrHierarchy amr, const VertexField& field)
{
  amr.association = amrdm::FieldAssociation::Points;
  for (amrdm::AmrBlock& block : amr.blocks)
  {
    const double w = double(amr.levelWidth(block.level));
    block.values.assign(static_cast<std::size_t>(block.numPoints()), 0.0f);
    block.state.clear();
    for (int z = 0; z <= block.dims.z; ++z)
      for (int y = 0; y <= block.dims.y; ++y)
        for (int x = 0; x <= block.dims.x; ++x)
        {
          const glm::ivec3 v = block.lower + glm::ivec3(x, y, z);
          block.values[static_cast<std::size_t>(block.pointIndex(v))] =
            static_cast<float>(field(glm::dvec3(v) * w, block.level));
        }
  }
  return amr;
}

} // namespace amrdm_test
