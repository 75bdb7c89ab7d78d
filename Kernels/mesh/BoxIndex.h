#pragma once
/// Finds which of many integer boxes overlap a query box without testing them all: a uniform
/// grid of bins over the boxes' bounds, each bin listing the boxes that touch it (CSR arrays).
/// The AMR checks that pair every block of one level with those of another (nesting, refined
/// cells, same-level overlap) use it, so they grow with the blocks, not with their square.
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace amrdm
{

/// An integer box with inclusive corners (cells lower..upper).
struct CellBox
{
  glm::i64vec3 lower{ 0 };
  glm::i64vec3 upper{ -1 };
};

class BoxIndex
{
public:
  /// Indexes `boxes` (inverted ones are never reported). Bins are about the boxes' mean extent
  /// per axis, widened until there are at most kBinsPerBox bins per box.
  explicit BoxIndex(std::vector<CellBox> boxes);

  /// Calls f(i) once for each indexed box i that shares at least one cell with `query`.
  template<class F>
  void forEachOverlap(const CellBox& query, F&& f) const;

  std::size_t size() const { return this->boxes_.size(); }
  const CellBox& box(std::size_t i) const { return this->boxes_[i]; }

  /// Whether two boxes share at least one cell.
  static bool overlaps(const CellBox& a, const CellBox& b);

  /// The most bins per indexed box before bins are widened.
  static constexpr std::int64_t kBinsPerBox = 4;

private:
  glm::i64vec3 bin(const glm::i64vec3& cell) const;
  std::int64_t binIndex(const glm::i64vec3& b) const
  {
    return (b.z * this->dims_.y + b.y) * this->dims_.x + b.x;
  }

  std::vector<CellBox> boxes_;
  glm::i64vec3 origin_{ 0 };
  glm::i64vec3 binSize_{ 1 };
  glm::i64vec3 dims_{ 0 };
  std::vector<std::size_t> offsets_;   ///< per bin: first entry in entries_ (CSR)
  std::vector<std::uint32_t> entries_; ///< box indices, grouped by bin
};

inline bool BoxIndex::overlaps(const CellBox& a, const CellBox& b)
{
  for (int d = 0; d < 3; ++d)
  {
    if (a.upper[d] < b.lower[d] || b.upper[d] < a.lower[d])
    {
      return false;
    }
  }
  return true;
}

inline glm::i64vec3 BoxIndex::bin(const glm::i64vec3& cell) const
{
  glm::i64vec3 b;
  for (int d = 0; d < 3; ++d)
  {
    const std::int64_t v = (cell[d] - this->origin_[d]) / this->binSize_[d];
    b[d] = v < 0 ? 0 : (v >= this->dims_[d] ? this->dims_[d] - 1 : v);
  }
  return b;
}

template<class F>
void BoxIndex::forEachOverlap(const CellBox& query, F&& f) const
{
  if (this->offsets_.empty() || query.upper.x < query.lower.x || query.upper.y < query.lower.y ||
      query.upper.z < query.lower.z)
  {
    return;
  }
  const glm::i64vec3 lo = this->bin(query.lower);
  const glm::i64vec3 hi = this->bin(query.upper);
  for (std::int64_t z = lo.z; z <= hi.z; ++z)
    for (std::int64_t y = lo.y; y <= hi.y; ++y)
      for (std::int64_t x = lo.x; x <= hi.x; ++x)
      {
        const glm::i64vec3 here(x, y, z);
        const std::int64_t b = this->binIndex(here);
        for (std::size_t e = this->offsets_[b]; e < this->offsets_[b + 1]; ++e)
        {
          const std::uint32_t i = this->entries_[e];
          const CellBox& box = this->boxes_[i];
          // A box in several bins is reported only from the bin holding the overlap's lower corner.
          if (overlaps(box, query) && this->bin(glm::max(box.lower, query.lower)) == here)
          {
            f(static_cast<std::size_t>(i));
          }
        }
      }
}

} // namespace amrdm
