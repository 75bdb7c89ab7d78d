// Scene files (Kernels/io/SceneFile.h): a written scene reads back field for field and builds the
// same dual mesh; a truncated file, a wrong magic or version, trailing bytes, inconsistent sizes
// and invalid values are SceneFileErrors whose messages name the problem.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "mesh/DualMeshBuilder.h"
#include "io/SceneFile.h"
#include "SyntheticAmr.h"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <string>

using namespace amrdm;

namespace
{
SceneDescription makeScene()
{
  amrdm_test::SyntheticOptions opt;
  opt.levels = 3;
  opt.rootCells = glm::ivec3(8, 6, 5);
  SceneDescription s;
  s.name = "synthetic (3 levels)";
  s.hierarchy = amrdm_test::makeSynthetic(11,
    opt,
    [](const glm::dvec3& p) { return float(std::sin(0.3 * p.x) + std::cos(0.2 * p.y) * p.z); });
  s.hierarchy.sceneOrigin = glm::dvec3(1e6, -2.0, 0.25);
  s.hierarchy.origin = glm::dvec3(0.5, 0.0, -1.0);
  s.hierarchy.finestSpacing = glm::dvec3(0.1, 0.2, 0.3);
  // One block with explicit states (its coverage plus a hidden leaf cell, as a blanking ghost
  // array gives), the others derived from coverage.
  AmrHierarchy finalized = s.hierarchy;
  finalized.finalizeCellStates();
  AmrBlock& b = s.hierarchy.blocks.front();
  b.state = finalized.blocks.front().state;
  for (std::uint8_t& c : b.state)
    if (c == CellLeaf)
    {
      c = CellHidden;
      break;
    }
  s.gridletSize = 4;
  s.bvhLeafSize = 3;
  s.tf.table = { glm::vec4(0.1f, 0.2f, 0.3f, 0.0f),
    glm::vec4(0.9f, 0.5f, 0.1f, 0.7f),
    glm::vec4(1.0f, 1.0f, 1.0f, 1.0f) };
  s.tf.lo = -1.5f;
  s.tf.hi = 2.5f;
  s.tf.unitDistance = 0.125f;
  s.tf.logScale = true;
  RenderParams& p = s.params;
  p.integrator = IntegratorType::RayMarch;
  p.samplesPerPass = 3;
  p.maxBounces = 7;
  p.anisotropy = -0.25f;
  p.seed = 4242;
  p.stepSize = 0.01f;
  p.samplesPerCell = 2.0f;
  p.gradientShading = true;
  p.gradientDelta = glm::vec3(0.1f, 0.2f, 0.3f);
  p.majorantResolution = glm::ivec3(4, 5, 6);
  p.elementTest.test = ElementTest::PlanarFaces;
  p.elementTest.maxNewtonIterations = 3;
  p.numLights = 2;
  p.lights[1].type = LightType::Point;
  p.lights[1].position = glm::vec3(1.0f, 2.0f, 3.0f);
  p.lights[1].color = glm::vec3(0.5f, 0.25f, 1.0f);
  p.lights[1].intensity = 9.0f;
  p.ambient = glm::vec3(0.2f, 0.3f, 0.4f);
  p.camera.position = glm::vec3(5.0f, -4.0f, 3.0f);
  p.camera.direction = glm::vec3(-1.0f, 1.0f, -0.5f);
  p.camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
  p.camera.parallel = true;
  p.camera.parallelScale = 2.5f;
  p.pixelJitter = false;
  p.width = 640;
  p.height = 480;
  p.tileSize = 32;
  p.cullInvisiblePrimitives = false;
  p.heatMapScale = 123.0f;
  return s;
}

/// The message of the SceneFileError that decoding `bytes` throws ("" when none is thrown).
std::string decodeError(const std::vector<std::uint8_t>& bytes)
{
  try
  {
    decodeScene(bytes, "test.amrdmscene");
  }
  catch (const SceneFileError& e)
  {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

void putU32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v)
{
  for (int i = 0; i < 4; ++i)
    b[at + i] = std::uint8_t(v >> (8 * i));
}

constexpr std::size_t kHeaderBytes = 8 + 4 + 8;

/// Offset of the first block's record (level) in an encoded scene.
std::size_t firstBlockOffset(const SceneDescription& s)
{
  return kHeaderBytes + 4 + s.name.size() + 4 + 4 * s.hierarchy.ratio.size() + 9 * 8 + 4;
}
} // namespace

TEST_CASE("a scene reads back field for field and builds the same dual mesh")
{
  const SceneDescription s = makeScene();
  const std::vector<std::uint8_t> bytes = encodeScene(s);
  REQUIRE(decodeError(bytes).empty());
  const SceneDescription r = decodeScene(bytes, "memory");
  CHECK(r.name == s.name);
  REQUIRE(r.hierarchy.blocks.size() == s.hierarchy.blocks.size());
  CHECK(r.hierarchy.ratio == s.hierarchy.ratio);
  CHECK(r.hierarchy.sceneOrigin == s.hierarchy.sceneOrigin);
  CHECK(r.hierarchy.origin == s.hierarchy.origin);
  CHECK(r.hierarchy.finestSpacing == s.hierarchy.finestSpacing);
  for (std::size_t i = 0; i < s.hierarchy.blocks.size(); ++i)
  {
    const AmrBlock &a = s.hierarchy.blocks[i], &b = r.hierarchy.blocks[i];
    CHECK(a.level == b.level);
    CHECK(a.lower == b.lower);
    CHECK(a.dims == b.dims);
    CHECK(std::memcmp(a.values.data(), b.values.data(), a.values.size() * 4) == 0);
    CHECK(a.state == b.state);
  }
  CHECK(r.gridletSize == 4);
  CHECK(r.bvhLeafSize == 3);
  CHECK(r.tf.table == s.tf.table);
  CHECK(r.tf.lo == s.tf.lo);
  CHECK(r.tf.hi == s.tf.hi);
  CHECK(r.tf.unitDistance == s.tf.unitDistance);
  CHECK(r.tf.logScale == s.tf.logScale);
  const RenderParams &p = s.params, &q = r.params;
  CHECK(q.integrator == p.integrator);
  CHECK(q.samplesPerPass == p.samplesPerPass);
  CHECK(q.maxBounces == p.maxBounces);
  CHECK(q.anisotropy == p.anisotropy);
  CHECK(q.seed == p.seed);
  CHECK(q.stepSize == p.stepSize);
  CHECK(q.samplesPerCell == p.samplesPerCell);
  CHECK(q.gradientShading == p.gradientShading);
  CHECK(q.gradientDelta == p.gradientDelta);
  CHECK(q.majorantResolution == p.majorantResolution);
  CHECK(q.elementTest.test == p.elementTest.test);
  CHECK(q.elementTest.maxNewtonIterations == p.elementTest.maxNewtonIterations);
  REQUIRE(q.numLights == 2);
  CHECK(q.lights[1].type == LightType::Point);
  CHECK(q.lights[1].position == p.lights[1].position);
  CHECK(q.lights[1].color == p.lights[1].color);
  CHECK(q.lights[1].intensity == p.lights[1].intensity);
  CHECK(q.ambient == p.ambient);
  CHECK(q.camera.position == p.camera.position);
  CHECK(q.camera.direction == p.camera.direction);
  CHECK(q.camera.parallel == p.camera.parallel);
  CHECK(q.camera.parallelScale == p.camera.parallelScale);
  CHECK(q.pixelJitter == p.pixelJitter);
  CHECK(q.width == 640);
  CHECK(q.height == 480);
  CHECK(q.tileSize == 32);
  CHECK(q.cullInvisiblePrimitives == false);
  CHECK(q.heatMapScale == p.heatMapScale);
  CHECK(q.threads == 0);

  AmrHierarchy a = s.hierarchy, b = r.hierarchy;
  a.finalizeCellStates();
  b.finalizeCellStates();
  DualMeshBuildOptions opt;
  opt.gridletSize = r.gridletSize;
  opt.bvhLeafSize = r.bvhLeafSize;
  const DualMesh ma = buildDualMesh(a, opt), mb = buildDualMesh(b, opt);
  CHECK(ma.counts.leafCells == mb.counts.leafCells);
  CHECK(ma.gridletScalars.size() == mb.gridletScalars.size());
  CHECK(ma.vertices.size() == mb.vertices.size());
  CHECK(ma.bvh.nodes.size() == mb.bvh.nodes.size());
  CHECK(ma.counts.leafCells == a.numLeafCells());
}

TEST_CASE("cell states that coverage reproduces are not stored, the rest are")
{
  SceneDescription s = makeScene();
  AmrHierarchy finalized = s.hierarchy;
  finalized.finalizeCellStates();
  // Every block with its derived states, as the VTK intake gives them from ghost arrays, except
  // block 0, which keeps a hidden finite cell that coverage cannot reproduce.
  for (std::size_t i = 1; i < s.hierarchy.blocks.size(); ++i)
    s.hierarchy.blocks[i].state = finalized.blocks[i].state;
  const SceneDescription r = decodeScene(encodeScene(s), "memory");
  CHECK(r.hierarchy.blocks[0].state == s.hierarchy.blocks[0].state);
  for (std::size_t i = 1; i < r.hierarchy.blocks.size(); ++i)
    CHECK(r.hierarchy.blocks[i].state.empty());
  AmrHierarchy a = s.hierarchy, b = r.hierarchy;
  a.finalizeCellStates();
  b.finalizeCellStates();
  for (std::size_t i = 0; i < a.blocks.size(); ++i)
    CHECK(a.blocks[i].state == b.blocks[i].state);
  CHECK(encodeScene(s) == encodeScene(r));
}

TEST_CASE("files on disk: write, read, and a missing file")
{
  const SceneDescription s = makeScene();
  const std::string path = "TestSceneFile.amrdmscene";
  writeSceneFile(path, s);
  const SceneDescription r = readSceneFile(path);
  CHECK(r.hierarchy.blocks.size() == s.hierarchy.blocks.size());
  CHECK(r.params.width == 640);
  std::remove(path.c_str());
  try
  {
    readSceneFile(path);
    FAIL("a missing file must throw");
  }
  catch (const SceneFileError& e)
  {
    CHECK(contains(e.what(), "cannot open"));
    CHECK(contains(e.what(), path));
  }
  CHECK_THROWS_AS(writeSceneFile("no-such-folder/x.amrdmscene", s), SceneFileError);
}

TEST_CASE("a truncated file is an error at every length")
{
  const std::vector<std::uint8_t> bytes = encodeScene(makeScene());
  const std::size_t cuts[] = { 0,
    3,
    8,
    11,
    19,
    kHeaderBytes,
    kHeaderBytes + 2,
    bytes.size() / 3,
    bytes.size() / 2,
    bytes.size() - 5,
    bytes.size() - 1 };
  for (std::size_t cut : cuts)
  {
    CAPTURE(cut);
    const std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + std::ptrdiff_t(cut));
    const std::string e = decodeError(part);
    CHECK(contains(e, "truncated"));
    CHECK(contains(e, "test.amrdmscene"));
  }
  // The header announces the full payload: trailing bytes are refused too.
  std::vector<std::uint8_t> longer = bytes;
  longer.push_back(0);
  CHECK(contains(decodeError(longer), "trailing bytes"));
}

TEST_CASE("a wrong magic or version is an error")
{
  std::vector<std::uint8_t> bytes = encodeScene(makeScene());
  std::vector<std::uint8_t> magic = bytes;
  magic[0] = 'X';
  CHECK(contains(decodeError(magic), "not a scene file"));
  std::vector<std::uint8_t> version = bytes;
  putU32(version, 8, kSceneFileVersion + 1);
  const std::string e = decodeError(version);
  CHECK(contains(e, "version " + std::to_string(kSceneFileVersion + 1)));
  CHECK(contains(e, "reads version " + std::to_string(kSceneFileVersion)));
}

TEST_CASE("inconsistent sizes and invalid values are errors that name the field")
{
  const SceneDescription s = makeScene();
  const std::vector<std::uint8_t> bytes = encodeScene(s);
  const std::size_t block = firstBlockOffset(s);
  {
    // Larger dims than the values stored: the block's cells cannot fit in what is left.
    std::vector<std::uint8_t> b = bytes;
    putU32(b, block + 4 + 12, 100000);
    CHECK(contains(decodeError(b), "block 0's"));
  }
  {
    // Huge dims (a 64-bit overflow of the cell count if computed naively).
    std::vector<std::uint8_t> b = bytes;
    for (int a = 0; a < 3; ++a)
      putU32(b, block + 4 + 12 + 4 * a, 0x7fffffff);
    CHECK(contains(decodeError(b), "truncated"));
  }
  {
    std::vector<std::uint8_t> b = bytes;
    putU32(b, block + 4 + 12, 0);
    CHECK(contains(decodeError(b), "expected positive"));
  }
  {
    // Smaller dims: values left over shift everything after, and the file no longer parses.
    std::vector<std::uint8_t> b = bytes;
    const int dx = s.hierarchy.blocks[0].dims.x;
    putU32(b, block + 4 + 12, std::uint32_t(dx - 1));
    CHECK_FALSE(decodeError(b).empty());
  }
  {
    std::vector<std::uint8_t> b = bytes;
    putU32(b, block, 9); // a level the hierarchy does not have
    CHECK(contains(decodeError(b), "inconsistent hierarchy"));
  }
  {
    std::vector<std::uint8_t> b = bytes;
    b[block + 28] = 7; // the state flag
    CHECK(contains(decodeError(b), "expected 0 or 1"));
  }
  {
    std::vector<std::uint8_t> b = bytes;
    putU32(b, kHeaderBytes + 4 + s.name.size(), 0); // no levels
    CHECK(contains(decodeError(b), "levels; expected 1.."));
  }
  {
    std::vector<std::uint8_t> b = bytes;
    // The first cell state follows the block's values: not 0, 1 or 2.
    b[block + 29 + 4 * std::size_t(s.hierarchy.blocks[0].numCells())] = 3;
    CHECK(contains(decodeError(b), "cell state 3"));
  }
  {
    std::vector<std::uint8_t> b = bytes;
    putU32(b, kHeaderBytes, 0xffffffffu); // the name length
    CHECK(contains(decodeError(b), "name"));
  }
  {
    std::vector<std::uint8_t> b = bytes;
    // The table's rows are stored by name (io/SceneFileParameters.h): the integrator's value
    // is the f64 after its name and its component count.
    const std::string name = "Integrator";
    const auto it = std::search(b.begin(), b.end(), name.begin(), name.end());
    REQUIRE(it != b.end());
    const std::size_t at = std::size_t(it - b.begin()) + name.size() + 1;
    const double bad = 17.0;
    std::memcpy(&b[at], &bad, 8);
    const std::string e = decodeError(b);
    CHECK(contains(e, "Integrator is 17"));
    CHECK(contains(e, "expected an integer in 0..4"));
  }
  {
    std::vector<std::uint8_t> b = bytes;
    // A row this build does not know (a file of a newer build) is refused naming it.
    const std::string name = "Integrator";
    const auto it = std::search(b.begin(), b.end(), name.begin(), name.end());
    REQUIRE(it != b.end());
    *it = 'X';
    CHECK(contains(decodeError(b), "unknown parameter 'Xntegrator'"));
  }
  {
    SceneDescription other = s;
    other.params.numLights = 3;
    std::vector<std::uint8_t> b = encodeScene(s), o = encodeScene(other);
    std::size_t at = kHeaderBytes; // the header's payload sizes differ too
    while (o[at] == b[at])
      ++at;
    putU32(b, at, std::uint32_t(kMaxLights + 1));
    CHECK(contains(decodeError(b),
      std::to_string(kMaxLights + 1) + " lights; expected at most " + std::to_string(kMaxLights)));
  }
}
