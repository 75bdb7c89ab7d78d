#include "mesh/DualMesh.h"

#include <limits>
#include <sstream>

namespace amrdm
{

DualMeshView DualMesh::view() const
{
  DualMeshView v;
  v.levelWidth = this->levelWidth.data();
  v.numLevels = static_cast<int>(this->levelWidth.size());
  v.gridlets = this->gridlets.data();
  v.gridletScalars = this->gridletScalars.data();
  v.vertices = this->vertices.data();
  for (int t = 0; t < 4; ++t)
  {
    v.elementIndices[t] = this->elementIndices[t].data();
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

std::string DualMeshCounts::toJson() const
{
  std::ostringstream s;
  s << "{\"leafCells\": " << leafCells << ", \"perfectCubes\": " << perfectCubes
    << ", \"gridlets\": " << gridlets << ", \"tets\": " << tets << ", \"pyramids\": " << pyramids
    << ", \"wedges\": " << wedges << ", \"hexes\": " << hexes
    << ", \"degenerateHexes\": " << degenerateHexes << ", \"dropped\": " << dropped
    << ", \"vertices\": " << vertices << ", \"nonFiniteValues\": " << nonFiniteValues << "}";
  return s.str();
}

} // namespace amrdm
