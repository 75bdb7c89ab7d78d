#include "BoxIndex.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace amrdm
{

BoxIndex::BoxIndex(std::vector<CellBox> boxes)
  : boxes_(std::move(boxes))
{
  if (this->boxes_.size() >= std::numeric_limits<std::uint32_t>::max())
  {
    throw std::length_error(
      "BoxIndex: " + std::to_string(this->boxes_.size()) + " boxes; expected fewer than 2^32");
  }
  glm::i64vec3 lo(std::numeric_limits<std::int64_t>::max());
  glm::i64vec3 hi(std::numeric_limits<std::int64_t>::min());
  glm::dvec3 extent(0.0);
  std::size_t valid = 0;
  for (const CellBox& box : this->boxes_)
  {
    if (box.upper.x < box.lower.x || box.upper.y < box.lower.y || box.upper.z < box.lower.z)
    {
      continue;
    }
    lo = glm::min(lo, box.lower);
    hi = glm::max(hi, box.upper);
    extent += glm::dvec3(box.upper - box.lower + glm::i64vec3(1));
    ++valid;
  }
  if (valid == 0)
  {
    return; // nothing to find: forEachOverlap() reports nothing
  }
  // Bins about the mean box extent: a typical box touches at most 2 bins per axis.
  this->origin_ = lo;
  for (int d = 0; d < 3; ++d)
  {
    this->binSize_[d] = std::max<std::int64_t>(1, std::int64_t(extent[d] / double(valid)));
  }
  const auto countBins = [&]()
  {
    double n = 1.0;
    for (int d = 0; d < 3; ++d)
    {
      this->dims_[d] = (hi[d] - lo[d]) / this->binSize_[d] + 1;
      n *= double(this->dims_[d]);
    }
    return n;
  };
  const double maxBins = double(kBinsPerBox) * double(valid) + 64.0;
  while (countBins() > maxBins)
  {
    this->binSize_ *= std::int64_t(2); // sparse boxes over a wide domain: coarser bins
  }
  // Counting pass, prefix sum, filling pass (CSR).
  const std::size_t numBins =
    static_cast<std::size_t>(this->dims_.x * this->dims_.y * this->dims_.z);
  this->offsets_.assign(numBins + 1, 0);
  const auto forEachBin = [&](const CellBox& box, auto&& g)
  {
    const glm::i64vec3 a = this->bin(box.lower);
    const glm::i64vec3 b = this->bin(box.upper);
    for (std::int64_t z = a.z; z <= b.z; ++z)
      for (std::int64_t y = a.y; y <= b.y; ++y)
        for (std::int64_t x = a.x; x <= b.x; ++x)
        {
          g(static_cast<std::size_t>(this->binIndex({ x, y, z })));
        }
  };
  for (const CellBox& box : this->boxes_)
  {
    if (box.upper.x >= box.lower.x && box.upper.y >= box.lower.y && box.upper.z >= box.lower.z)
    {
      forEachBin(box, [&](std::size_t b) { ++this->offsets_[b + 1]; });
    }
  }
  for (std::size_t b = 0; b < numBins; ++b)
  {
    this->offsets_[b + 1] += this->offsets_[b];
  }
  this->entries_.resize(this->offsets_[numBins]);
  std::vector<std::size_t> fill(this->offsets_.begin(), this->offsets_.end() - 1);
  for (std::size_t i = 0; i < this->boxes_.size(); ++i)
  {
    const CellBox& box = this->boxes_[i];
    if (box.upper.x >= box.lower.x && box.upper.y >= box.lower.y && box.upper.z >= box.lower.z)
    {
      forEachBin(box, [&](std::size_t b) { this->entries_[fill[b]++] = std::uint32_t(i); });
    }
  }
}

} // namespace amrdm
