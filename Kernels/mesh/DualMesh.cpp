#include "mesh/DualMesh.h"

#include <limits>
#include <sstream>
#include <stdexcept>

namespace amrdm
{

DualMeshView DualMesh::view() const
{
  DualMeshView v;
  v.levelWidth = this->levelWidth.data();
  v.numLevels = static_cast<int>(this->levelWidth.size());
  v.gridletOrigin = this->gridletOrigin;
  v.gridlets = this->gridlets.data();
  v.gridletScalars = this->gridletScalars.data();
  v.vertices = this->vertices.data();
  for (int k = 0; k < kElementKindCount; ++k)
  {
    v.elementIndices[k] = this->elementIndices[k].data();
  }
  v.bvh = this->bvh.view();
  return v;
}

MemoryReport DualMesh::memoryReport() const
{
  MemoryReport r;
  r.gridletScalars = this->gridletScalars.size() * sizeof(float);
  r.gridletHeaders = this->gridlets.size() * sizeof(GridletHeader);
  r.elementVertices = this->vertices.size() * sizeof(ElementVertex);
  for (const auto& indices : this->elementIndices)
  {
    r.elementIndices += indices.size() * sizeof(std::uint32_t);
  }
  r.bvh = this->bvh.bytes();
  r.leafCells = this->counts.leafCells;
  return r;
}

void DualMesh::validate() const
{
  const std::size_t numVertices = this->vertices.size();
  for (int k = 0; k < kElementKindCount; ++k)
  {
    const auto& indices = this->elementIndices[k];
    const std::size_t n = static_cast<std::size_t>(elementCorners(k));
    if (indices.size() % n != 0)
    {
      throw std::invalid_argument("the dual mesh's " + std::string(elementKindName(k)) +
                                  " index array holds " + std::to_string(indices.size()) +
                                  " indices; expected a multiple of " + std::to_string(n) +
                                  " (corners per " + elementKindName(k) + ")");
    }
    for (std::size_t i = 0; i < indices.size(); ++i)
    {
      if (indices[i] >= numVertices)
      {
        throw std::invalid_argument("corner " + std::to_string(i % n) + " of " +
                                    elementKindName(k) + " " + std::to_string(i / n) +
                                    " is vertex " + std::to_string(indices[i]) + "; expected < " +
                                    std::to_string(numVertices) + " (the stitching vertices)");
      }
    }
  }
  for (std::size_t i = 0; i < this->bvh.prims.size(); ++i)
  {
    const std::uint32_t ref = this->bvh.prims[i];
    const std::uint32_t type = primType(ref);
    if (type != PrimGridlet && !isElementPrimType(type))
    {
      throw std::invalid_argument("BVH primitive reference " + std::to_string(i) + " has type " +
                                  std::to_string(type) + "; expected 0 (gridlet) or 1.." +
                                  std::to_string(kElementKindCount) + " (" + elementKindNames() +
                                  ", mesh/ElementList.h)");
    }
    const std::uint64_t count = type == PrimGridlet
                                  ? this->gridlets.size()
                                  : std::uint64_t(this->numElements(primElementKind(type)));
    if (primIndex(ref) >= count)
    {
      throw std::invalid_argument(
        "BVH primitive reference " + std::to_string(i) + " points at " +
        (type == PrimGridlet ? std::string("gridlet") : elementKindName(primElementKind(type))) +
        " " + std::to_string(primIndex(ref)) + "; expected < " + std::to_string(count));
    }
  }
}

void DualMesh::gridBounds(glm::vec3& lo, glm::vec3& hi) const
{
  lo = glm::vec3(std::numeric_limits<float>::max());
  hi = -lo;
  if (!this->bvh.nodes.empty())
  {
    lo = this->bvh.nodes[0].lo;
    hi = this->bvh.nodes[0].hi;
  }
}

std::string MemoryReport::toJson() const
{
  std::ostringstream s;
  s << "{\"gridletScalars\": " << gridletScalars << ", \"gridletHeaders\": " << gridletHeaders
    << ", \"elementVertices\": " << elementVertices << ", \"elementIndices\": " << elementIndices
    << ", \"bvh\": " << bvh << ", \"total\": " << total() << ", \"leafCells\": " << leafCells
    << ", \"bytesPerLeafCell\": " << bytesPerLeafCell() << "}";
  return s.str();
}

namespace
{
/// The DualMeshCounts member of element kind `kind` (const or not).
template<typename Counts>
auto& elementCount(Counts& c, int kind)
{
  switch (kind)
  {
#define AMRDM_ELEMENT_MEMBER(k, name, member, ...)                                                 \
  case int(ElementKind::k):                                                                        \
    return c.member;
    AMRDM_ELEMENTS(AMRDM_ELEMENT_MEMBER)
#undef AMRDM_ELEMENT_MEMBER
    default:
      throw std::out_of_range("element kind " + std::to_string(kind) + " is not in the list (" +
                              elementKindNames() + ")");
  }
}
} // namespace

std::int64_t& DualMeshCounts::elements(int kind)
{
  return elementCount(*this, kind);
}

std::int64_t DualMeshCounts::elements(int kind) const
{
  return elementCount(*this, kind);
}

std::int64_t DualMeshCounts::totalElements() const
{
  std::int64_t n = 0;
  for (int k = 0; k < kElementKindCount; ++k)
  {
    n += this->elements(k);
  }
  return n;
}

std::string DualMeshCounts::toJson() const
{
  std::ostringstream s;
  s << "{\"leafCells\": " << leafCells << ", \"perfectCubes\": " << perfectCubes
    << ", \"gridlets\": " << gridlets;
#define AMRDM_ELEMENT_JSON(kind, name, member, ...) s << ", \"" #member "\": " << member;
  AMRDM_ELEMENTS(AMRDM_ELEMENT_JSON)
#undef AMRDM_ELEMENT_JSON
  s << ", \"degenerateHexes\": " << degenerateHexes << ", \"dropped\": " << dropped
    << ", \"vertices\": " << vertices << ", \"nonFiniteValues\": " << nonFiniteValues << "}";
  return s.str();
}

} // namespace amrdm
