// The dual-mesh build's memory budget (mesh/DualMeshBudget.h) against the bytes the finished
// mesh measures (DualMesh::memoryReport(): gridlet scalars and headers, element vertices and
// indices, BVH nodes and references) on every real set: the estimate made before the build is
// within 10 % of the measured total and of each category above 1 % of it. A build whose
// estimated peak exceeds the memory limit is refused with the estimate, the limit and what
// would fit; one within it builds. The upper bound the build checks first (from cell states,
// no discovery) holds every measured category.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "AMRIntake.h"
#include "RealData.h"

#include "mesh/DualMeshBuilder.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

using namespace amrdm;

namespace
{
constexpr double kTolerance = 0.10;

double relativeError(std::uint64_t estimate, std::uint64_t measured)
{
  return measured > 0 ? (double(estimate) - double(measured)) / double(measured)
                      : (estimate > 0 ? 1.0 : 0.0);
}

void compare(const char* name, const AmrHierarchy& amr)
{
  DualMeshBuildOptions options;
  options.threads = 2;
  const auto t0 = std::chrono::steady_clock::now();
  const DualMeshMemoryEstimate e = estimateDualMeshMemory(amr, options);
  const auto t1 = std::chrono::steady_clock::now();
  const DualMesh mesh = buildDualMesh(amr, options);
  const auto t2 = std::chrono::steady_clock::now();
  const DualMeshMemoryEstimate bound = boundDualMeshMemory(amr, options);
  const auto t3 = std::chrono::steady_clock::now();
  const MemoryReport m = mesh.memoryReport();
  const MemoryReport& p = e.mesh;
  std::printf(
    "%s: %lld leaf cells, estimate %.3f MiB vs measured %.3f MiB (%+.2f %%); peak "
    "%.3f MiB; BVH nodes %zu for %lld primitives (%.3f per primitive); estimate "
    "%.3f s, build %.3f s; upper bound %.3f MiB, peak %.3f MiB (%.3f s)\n  estimate %s\n  "
    "measured %s\n",
    name,
    (long long)m.leafCells,
    double(p.total()) / (1 << 20),
    double(m.total()) / (1 << 20),
    100.0 * relativeError(p.total(), m.total()),
    double(e.peak()) / (1 << 20),
    mesh.bvh.nodes.size(),
    (long long)e.primitives,
    e.primitives > 0 ? double(mesh.bvh.nodes.size()) / double(e.primitives) : 0.0,
    std::chrono::duration<double>(t1 - t0).count(),
    std::chrono::duration<double>(t2 - t1).count(),
    double(bound.mesh.total()) / (1 << 20),
    double(bound.peak()) / (1 << 20),
    std::chrono::duration<double>(t3 - t2).count(),
    e.toJson().c_str(),
    m.toJson().c_str());
  CHECK(std::abs(relativeError(p.total(), m.total())) <= kTolerance);
  // Exact categories: everything the counting pass counts.
  CHECK(p.gridletScalars == m.gridletScalars);
  CHECK(p.gridletHeaders == m.gridletHeaders);
  CHECK(p.elementVertices == m.elementVertices);
  CHECK(p.elementIndices == m.elementIndices);
  CHECK(p.leafCells == m.leafCells);
  CHECK(e.gridlets == mesh.counts.gridlets);
  CHECK(e.vertices == mesh.counts.vertices);
  for (int k = 0; k < kElementKindCount; ++k)
  {
    CHECK(e.elements[k] == mesh.counts.elements(k));
  }
  // The BVH's node count is the one estimated category (kBvhNodesPerPrimitive, measured on sets
  // of more than 10^3 primitives; a single-level set has only its 125 gridlets).
  if (m.bvh * 100 > m.total() && e.primitives >= 1000)
  {
    CHECK(std::abs(relativeError(p.bvh, m.bvh)) <= kTolerance);
  }
  CHECK(e.peak() >= p.total());
  // The bound the build checks first (no counting pass when it fits) holds every category.
  CHECK(bound.mesh.gridletScalars >= m.gridletScalars);
  CHECK(bound.mesh.gridletHeaders >= m.gridletHeaders);
  CHECK(bound.mesh.elementVertices >= m.elementVertices);
  CHECK(bound.mesh.elementIndices >= m.elementIndices);
  CHECK(bound.mesh.bvh >= m.bvh);
  CHECK(bound.peak() >= e.peak());
}

AmrHierarchy convert(const amrdm_test::RealSet& set)
{
  vtkSmartPointer<vtkOverlappingAMR> data = amrdm_test::readSet(set);
  REQUIRE(data);
  AmrHierarchy amr;
  std::string error;
  REQUIRE_MESSAGE(amrdm_vtk::ConvertAMR(data, set.array.c_str(), -1, false, amr, error), error);
  amr.validate();
  amr.finalizeCellStates();
  return amr;
}
} // namespace

TEST_CASE("the estimate is within 10 % of the measured mesh on every real set")
{
  int tested = 0;
  for (const amrdm_test::RealSet& set : amrdm_test::realSets())
  {
    if (set.path.empty())
    {
      std::printf("skipping %s: not found (large sets live in ../shared/amr-data, or set "
                  "AMRDM_SHARED_DATA)\n",
        set.name.c_str());
      continue;
    }
    compare(set.name.c_str(), convert(set));
    ++tested;
  }
  CHECK(tested >= 3); // the sets in Testing/Data are always there
}

TEST_CASE("a build over the limit is refused with the estimate, the limit and what would fit")
{
  const std::vector<amrdm_test::RealSet> sets = amrdm_test::realSets();
  REQUIRE(!sets[0].path.empty());
  const AmrHierarchy amr = convert(sets[0]);
  DualMeshBuildOptions options;
  options.threads = 2;
  const DualMeshMemoryEstimate e = estimateDualMeshMemory(amr, options);
  REQUIRE(boundDualMeshMemory(amr, options).peak() > e.peak()); // the counting pass runs
  options.memoryLimit = e.peak() - 1;
  std::string message;
  try
  {
    buildDualMesh(amr, options);
  }
  catch (const std::length_error& error)
  {
    message = error.what();
  }
  MESSAGE(message);
  char expected[64];
  std::snprintf(
    expected, sizeof(expected), "needs about %.1f MiB at its peak", e.peak() / 1048576.0);
  CHECK(message.find(expected) != std::string::npos);
  CHECK(message.find("MiB are available") != std::string::npos);
  CHECK(message.find(" leaf cells would fit") != std::string::npos);
  // The coarser levels fit (Enzo has 8): the message names how many, and that cut's leaf cells.
  std::int64_t cut = 0;
  const int levels = detail::levelsThatFit(amr, e, options.memoryLimit, cut);
  CHECK(levels >= 1);
  CHECK(levels < amr.numLevels());
  CHECK(cut < amr.numLeafCells());
  CHECK(message.find("levels 0.." + std::to_string(levels - 1) + " of " +
                     std::to_string(amr.numLevels()) + " (about " + std::to_string(cut) +
                     " leaf cells) would") != std::string::npos);
  options.memoryLimit = e.peak();
  CHECK_NOTHROW(buildDualMesh(amr, options));
}
