// Alternative sampler for the benchmark: the piecewise-constant value of the finest leaf cell
// that contains the point ("nearest finest cell", like OpenVKL's `current` method without its
// in-level interpolation: discontinuous at every cell face and at level boundaries). It covers
// the whole cell domain (the dual mesh stops at the hull of the cell centres). Host-only: the
// lookup is Kernels/accel/CellLocator (a bin grid of blocks per level, walked finest to coarsest).
#pragma once

#include "FieldMedium.h"

#include "mesh/AmrHierarchy.h"
#include "accel/CellLocator.h"
#include "transport/DeltaTracking.h"
#include "sampling/TransferFunction.h"

#include <cstdint>
#include <memory>

namespace amrdm_bench
{

/// Owns the hierarchy (values + cell states) and its locator.
struct NearestCellField
{
  amrdm::AmrHierarchy amr;
  std::unique_ptr<amrdm::CellLocator> locator;
  int finestLevel = 0;
  glm::vec3 origin{ 0.0f }, invSpacing{ 1.0f };
  glm::vec3 lo{ 0.0f }, hi{ 0.0f }; ///< world bounds of all blocks

  /// Call after amr is filled and finalized.
  void init()
  {
    this->locator.reset(new amrdm::CellLocator(this->amr));
    this->finestLevel = this->amr.numLevels() - 1;
    this->origin = glm::vec3(this->amr.origin);
    this->invSpacing = glm::vec3(1.0 / this->amr.finestSpacing);
    glm::dvec3 glo(1e300), ghi(-1e300);
    for (const amrdm::AmrBlock& b : this->amr.blocks)
    {
      const double w = double(this->amr.levelWidth(b.level));
      glo = glm::min(glo, glm::dvec3(b.lower) * w);
      ghi = glm::max(ghi, glm::dvec3(b.lower + b.dims) * w);
    }
    this->lo = glm::vec3(this->amr.origin + glo * this->amr.finestSpacing);
    this->hi = glm::vec3(this->amr.origin + ghi * this->amr.finestSpacing);
  }

  /// Leaf value at world point p; false outside every block or in a hidden cell.
  bool value(const glm::vec3& p, float& v) const
  {
    const glm::vec3 g = (p - this->origin) * this->invSpacing;
    const glm::ivec3 c(glm::floor(g));
    const amrdm::CellRef ref = this->locator->locate(this->finestLevel, c);
    if (ref.kind != amrdm::CellRef::Leaf)
    {
      return false;
    }
    v = this->amr.blocks[ref.block].values[static_cast<std::size_t>(ref.cell)];
    return true;
  }

  /// Bytes a renderer would need: one float per cell of every block (refined cells included,
  /// as the AMR arrays hold them) plus a 32-byte box per block. The locator's bins are left out
  /// (a kd-tree or bin grid of comparable size would be needed by any implementation).
  std::uint64_t bytes() const
  {
    std::uint64_t b = 0;
    for (const amrdm::AmrBlock& block : this->amr.blocks)
    {
      b += 4u * std::uint64_t(block.numCells()) + 32u;
    }
    return b;
  }
};

/// The medium interface of Kernels/sampling/Media.h over a NearestCellField.
using NearestCellMedium = FieldMedium<NearestCellField>;

} // namespace amrdm_bench
