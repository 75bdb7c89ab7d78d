// The element-kind list (mesh/ElementList.h) and where its kinds are checked: the stored values
// and corner counts, the sampler's dispatch (each kind's own test; a type outside the list claims
// nothing, where it used to be sampled as a hex), the counts, and DualMesh::validate(), which
// rejects an out-of-range type or index with a message (kernel only, no VTK).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "mesh/DualMeshBuilder.h"
#include "sampling/FieldSampler.h"
#include "SyntheticAmr.h"

#include <stdexcept>
#include <string>

using namespace amrdm;

namespace
{
DualMesh buildTwoLevels()
{
  amrdm_test::SyntheticOptions opt;
  opt.levels = 2;
  opt.rootCells = glm::ivec3(6);
  AmrHierarchy amr = amrdm_test::makeSynthetic(7,
    opt,
    [](const glm::dvec3& p)
    { return static_cast<float>(0.5 * p.x - 0.25 * p.y + 0.125 * p.z + 1.0); });
  amr.validate();
  amr.finalizeCellStates();
  return buildDualMesh(amr);
}

/// The message of what f throws as std::invalid_argument, "" if it throws nothing.
template<typename F>
std::string invalidArgument(F&& f)
{
  try
  {
    f();
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  return "";
}

/// The first BVH slot holding an element, and its reference.
std::size_t firstElementSlot(const DualMesh& mesh)
{
  for (std::size_t i = 0; i < mesh.bvh.prims.size(); ++i)
  {
    if (primType(mesh.bvh.prims[i]) != PrimGridlet)
    {
      return i;
    }
  }
  return mesh.bvh.prims.size();
}
} // namespace

TEST_CASE("the list: stored values, corners, names")
{
  // BVH references store these values (scenes, caches): append only.
  static_assert(PrimGridlet == 0 && PrimTet == 1 && PrimPyramid == 2 && PrimWedge == 3 &&
                  PrimHex == 4 && PrimTypeCount == 5,
    "primitive types are stored: never renumber");
  CHECK(kElementKindCount == 4);
  const int corners[] = { 4, 5, 6, 8 };
  const char* names[] = { "tet", "pyramid", "wedge", "hex" };
  for (int k = 0; k < kElementKindCount; ++k)
  {
    CHECK(elementCorners(k) == corners[k]);
    CHECK(std::string(elementKindName(k)) == names[k]);
    CHECK(primElementKind(elementPrimType(k)) == k);
    CHECK(isElementPrimType(elementPrimType(k)));
  }
  CHECK(kMaxElementCorners == 8);
  CHECK(elementCorners(-1) == 0);
  CHECK(elementCorners(kElementKindCount) == 0);
  CHECK_FALSE(isElementPrimType(PrimGridlet));
  CHECK_FALSE(isElementPrimType(PrimTypeCount));
  CHECK(std::string(elementKindName(kElementKindCount)) == "unknown");
  CHECK(elementKindNames() == "tet, pyramid, wedge, hex");

  DualMeshCounts c;
  c.tets = 1;
  c.pyramids = 2;
  c.wedges = 3;
  c.hexes = 4;
  for (int k = 0; k < kElementKindCount; ++k)
  {
    CHECK(c.elements(k) == k + 1);
  }
  CHECK(c.totalElements() == 10);
  CHECK_THROWS_AS(c.elements(kElementKindCount), std::out_of_range);
  CHECK(c.toJson().find("\"tets\": 1, \"pyramids\": 2, \"wedges\": 3, \"hexes\": 4") !=
        std::string::npos);
}

TEST_CASE("the sampler dispatches each kind to its own test")
{
  // One unit element of each kind, corners relative to corner 0, value = x + 2 y + 4 z; a point
  // inside the tet (and so inside every other kind, which all contain the unit tet here).
  const glm::vec4 tet[4] = { { 0, 0, 0, 0 }, { 1, 0, 0, 1 }, { 0, 1, 0, 2 }, { 0, 0, 1, 4 } };
  const glm::vec3 p(0.2f, 0.2f, 0.2f);
  float value = -1.0f;
  CHECK(sampleElementOfKind(int(ElementKind::Tet), tet, p, ElementTestParams{}, value));
  CHECK(value == doctest::Approx(0.2 + 0.4 + 0.8).epsilon(1e-5));
  // The same 4 corners as a "hex" would read 4 corners past the array: the dispatch must pick
  // the tet's test. A point outside the tet but inside its box is rejected by the tet test.
  CHECK_FALSE(
    sampleElementOfKind(int(ElementKind::Tet), tet, glm::vec3(0.6f), ElementTestParams{}, value));
  const glm::vec4 hex[8] = { { 0, 0, 0, 0 },
    { 1, 0, 0, 1 },
    { 1, 1, 0, 3 },
    { 0, 1, 0, 2 },
    { 0, 0, 1, 4 },
    { 1, 0, 1, 5 },
    { 1, 1, 1, 7 },
    { 0, 1, 1, 6 } };
  CHECK(
    sampleElementOfKind(int(ElementKind::Hex), hex, glm::vec3(0.6f), ElementTestParams{}, value));
  CHECK(value == doctest::Approx(0.6 * 7).epsilon(1e-5));
  // A kind outside the list claims nothing (no hex fallback).
  value = -1.0f;
  CHECK_FALSE(
    sampleElementOfKind(kElementKindCount, hex, glm::vec3(0.6f), ElementTestParams{}, value));
  CHECK_FALSE(sampleElementOfKind(-1, hex, glm::vec3(0.6f), ElementTestParams{}, value));
  CHECK(value == -1.0f);
}

TEST_CASE("a built mesh validates; an out-of-range type is rejected with a message")
{
  DualMesh mesh = buildTwoLevels();
  REQUIRE(mesh.counts.totalElements() > 0);
  CHECK_NOTHROW(mesh.validate());
  const std::size_t slot = firstElementSlot(mesh);
  REQUIRE(slot < mesh.bvh.prims.size());
  const std::uint32_t ref = mesh.bvh.prims[slot];

  // The sampler claims the element's own points through its real reference ...
  const DualMeshView view = mesh.view();
  const int kind = primElementKind(primType(ref));
  glm::vec4 v[kMaxElementCorners];
  glm::ivec3 anchor2;
  const int n = gatherElement(view, kind, primIndex(ref), v, anchor2);
  glm::vec3 centroid(0.0f);
  for (int i = 0; i < n; ++i)
  {
    centroid += glm::vec3(v[i]) / float(n);
  }
  const glm::vec3 p = centroid + 0.5f * glm::vec3(anchor2);
  float value = 0.0f;
  CHECK(samplePrimitive(view, ref, p, ElementTestParams{}, value));

  // ... but not through the same index with a type outside the list.
  for (std::uint32_t type = PrimTypeCount; type < (1u << (32 - kPrimTypeShift)); ++type)
  {
    CHECK_FALSE(
      samplePrimitive(view, makePrimRef(type, primIndex(ref)), p, ElementTestParams{}, value));
  }

  DualMesh bad = mesh;
  bad.bvh.prims[slot] = makePrimRef(PrimTypeCount, primIndex(ref));
  const std::string message = invalidArgument([&] { bad.validate(); });
  MESSAGE("out-of-range type: ", message);
  CHECK(message.find("BVH primitive reference " + std::to_string(slot) + " has type 5") !=
        std::string::npos);
  CHECK(
    message.find("expected 0 (gridlet) or 1..4 (tet, pyramid, wedge, hex") != std::string::npos);

  bad = mesh;
  bad.bvh.prims[slot] = makePrimRef(primType(ref), kPrimIndexMask);
  CHECK(invalidArgument([&] { bad.validate(); }).find("points at") != std::string::npos);

  bad = mesh;
  bad.elementIndices[kind].push_back(0);
  CHECK(
    invalidArgument([&] { bad.validate(); }).find("expected a multiple of") != std::string::npos);

  bad = mesh;
  bad.elementIndices[kind][0] = static_cast<std::uint32_t>(bad.vertices.size());
  CHECK(
    invalidArgument([&] { bad.validate(); }).find("(the stitching vertices)") != std::string::npos);
}
