// Scene files (see SceneFile.h). The payload, in order (u8/u32/i32/u64/f32/f64 little-endian):
//   name:        u32 length, bytes
//   hierarchy:   u32 levels, i32 ratio[levels], f64 sceneOrigin[3], origin[3], finestSpacing[3],
//                u32 blocks, then per block: i32 level, lower[3], dims[3], u8 hasState,
//                f32 values[cells], u8 state[cells] (only when hasState: states that
//                finalizeCellStates() would derive are not stored)
//   transfer:    u32 entries, f32 lo, hi, unitDistance, u8 logScale, f32 table[entries][4]
//   parameters:  the RenderParams fields that are not rows of core/ParameterTable.h:
//                i32 rouletteStartBounce, maxStepsPerWalk, f32 earlyTermination,
//                u8 gradientShading, f32 gradientDelta[3], ambientCoefficient,
//                diffuseCoefficient, specularCoefficient, specularPower, u32 numLights, per light:
//                i32 type, f32 direction[3], position[3], color[3], intensity;
//                camera: f32 position[3], direction[3], up[3], u8 parallel, f32 viewAngle,
//                parallelScale; u8 pixelJitter, i32 width, height, tileSize,
//                u8 cullInvisiblePrimitives, f32 heatMapScale
//   table:       the rows of core/ParameterTable.h a scene stores (its Build rows and its
//                RenderParams fields but the NotInSceneFile ones), by name
//                (io/SceneFileParameters.h; the list is the generated block below)
// and nothing after it.
#include "io/SceneFile.h"
#include "io/SceneFileCodec.h"
#include "io/SceneFileParameters.h"
#include "mesh/PrepareHierarchy.h"

#include <cstring>
#include <fstream>
#include <limits>

namespace amrdm
{
namespace scenefile
{
/// The rows a scene file stores, generated from core/ParameterTable.h: each row with its field of
/// the SceneDescription (const or not).
template<typename Scene, typename Visit>
void visitSceneParameters(Scene& s, Visit&& visit)
{
  // BEGIN GENERATED scene-parameters (Tools/generate_parameters.py)
  // clang-format off
  visit(param::Integrator, s.params.integrator);
  visit(param::SamplesPerRender, s.params.samplesPerPass);
  visit(param::ScatteringAnisotropy, s.params.anisotropy);
  visit(param::EnvironmentRadiance, s.params.ambient);
  visit(param::MaximumBounces, s.params.maxBounces);
  visit(param::StepSize, s.params.stepSize);
  visit(param::SamplesPerCell, s.params.samplesPerCell);
  visit(param::ElementTest, s.params.elementTest.test);
  visit(param::MaxNewtonIterations, s.params.elementTest.maxNewtonIterations);
  visit(param::GridletSize, s.gridletSize);
  visit(param::BVHLeafSize, s.bvhLeafSize);
  visit(param::MajorantResolution, s.params.majorantResolution);
  visit(param::Seed, s.params.seed);
  // clang-format on
  // END GENERATED scene-parameters
}
} // namespace scenefile

namespace
{
using scenefile::Reader;
using scenefile::Writer;

constexpr std::uint32_t kMaxLevels = 64;
constexpr std::uint32_t kMaxTableEntries = 1u << 20;
constexpr std::uint32_t kMaxNameBytes = 1u << 16;
/// Bytes of one block before its values: level, lower, dims (7 x i32) and hasState.
constexpr std::uint64_t kBlockHeaderBytes = 7 * 4 + 1;

/// Per block: whether its explicit cell states must be stored. States equal to what
/// finalizeCellStates() derives from coverage and non-finite values (the common case: the VTK
/// intake copies the readers' ghost arrays) are dropped, which saves 1 byte per cell; the
/// reader's finalizeCellStates() recreates them exactly. An invalid hierarchy keeps them all.
std::vector<bool> statesToStore(const AmrHierarchy& h)
{
  std::vector<bool> store(h.blocks.size());
  for (std::size_t i = 0; i < h.blocks.size(); ++i)
    store[i] = !h.blocks[i].state.empty();
  AmrHierarchy derived = h;
  for (AmrBlock& b : derived.blocks)
    b.state.clear();
  try
  {
    prepareHierarchy(derived);
  }
  catch (const std::invalid_argument&)
  {
    return store;
  }
  for (std::size_t i = 0; i < h.blocks.size(); ++i)
    store[i] = store[i] && h.blocks[i].state != derived.blocks[i].state;
  return store;
}

void writeHierarchy(Writer& w, const AmrHierarchy& h)
{
  const std::vector<bool> storeState = statesToStore(h);
  w.u32(std::uint32_t(h.ratio.size()));
  for (int r : h.ratio)
    w.i32(r);
  w.dvec3(h.sceneOrigin);
  w.dvec3(h.origin);
  w.dvec3(h.finestSpacing);
  w.u32(std::uint32_t(h.blocks.size()));
  for (std::size_t i = 0; i < h.blocks.size(); ++i)
  {
    const AmrBlock& b = h.blocks[i];
    w.i32(b.level);
    w.ivec3(b.lower);
    w.ivec3(b.dims);
    w.u8(storeState[i] ? 1 : 0);
    for (float v : b.values)
      w.f32(v);
    if (storeState[i])
      w.bytes.insert(w.bytes.end(), b.state.begin(), b.state.end());
  }
}

AmrHierarchy readHierarchy(Reader& r)
{
  AmrHierarchy h;
  const std::uint32_t levels = r.u32("the number of levels");
  if (levels < 1 || levels > kMaxLevels)
    r.fail("the hierarchy has " + std::to_string(levels) + " levels; expected 1.." +
           std::to_string(kMaxLevels));
  r.need(std::uint64_t(levels) * 4, "the refinement ratios");
  for (std::uint32_t l = 0; l < levels; ++l)
    h.ratio.push_back(r.i32("a refinement ratio"));
  h.sceneOrigin = r.dvec3("the scene origin");
  h.origin = r.dvec3("the grid origin");
  h.finestSpacing = r.dvec3("the finest spacing");
  const std::uint32_t blocks = r.u32("the number of blocks");
  r.need(std::uint64_t(blocks) * kBlockHeaderBytes, std::to_string(blocks) + " block headers");
  h.blocks.resize(blocks);
  for (std::uint32_t i = 0; i < blocks; ++i)
  {
    AmrBlock& b = h.blocks[i];
    const std::string name = "block " + std::to_string(i);
    b.level = r.i32("a block level");
    b.lower = r.ivec3("a block's first cell");
    b.dims = r.ivec3("a block's dimensions");
    const bool hasState = r.flag("a block's state flag");
    if (b.dims.x <= 0 || b.dims.y <= 0 || b.dims.z <= 0)
      r.fail(name + " has dimensions " + std::to_string(b.dims.x) + " x " +
             std::to_string(b.dims.y) + " x " + std::to_string(b.dims.z) + "; expected positive");
    // In double first: three int32 dimensions can overflow a 64-bit product.
    const double cellsD = double(b.dims.x) * double(b.dims.y) * double(b.dims.z);
    if (cellsD * (hasState ? 5.0 : 4.0) > double(r.left()))
      r.fail("truncated: " + name + "'s " + std::to_string(b.dims.x) + " x " +
             std::to_string(b.dims.y) + " x " + std::to_string(b.dims.z) +
             " cells need more than the " + std::to_string(r.left()) +
             " bytes left; expected a complete scene file");
    const std::uint64_t cells = std::uint64_t(b.numCells());
    b.values.resize(cells);
    for (float& v : b.values)
      v = r.f32("a cell value");
    if (hasState)
    {
      b.state.resize(cells);
      for (std::uint8_t& s : b.state)
      {
        s = r.u8("a cell state");
        if (s > CellHidden)
          r.fail(name + " has cell state " + std::to_string(s) + "; expected 0 (leaf), 1 " +
                 "(refined) or 2 (hidden)");
      }
    }
  }
  return h;
}

/// Writes the fields transferParams() lists.
struct ParamWriter
{
  Writer& w;
  void field(int v, const char*) { this->w.i32(v); }
  void field(float v, const char*) { this->w.f32(v); }
  void field(bool v, const char*) { this->w.u8(v ? 1 : 0); }
  void field(const glm::vec3& v, const char*) { this->w.vec3(v); }
  void field(LightType v, const char*) { this->w.i32(int(v)); }
  void count(int n, int, const char*, const char*) { this->w.u32(std::uint32_t(n)); }
};

/// Reads the fields transferParams() lists, each checked (Reader: SceneFileError naming it).
struct ParamReader
{
  Reader& r;
  void field(int& v, const char* name) { v = this->r.i32(name); }
  void field(float& v, const char* name) { v = this->r.f32(name); }
  void field(bool& v, const char* name) { v = this->r.flag(name); }
  void field(glm::vec3& v, const char* name) { v = this->r.vec3(name); }
  void field(LightType& v, const char* name) { v = LightType(this->r.enumValue(name, 2)); }
  /// A count of at most `max` `things`.
  void count(int& n, int max, const char* name, const char* things)
  {
    const std::uint32_t c = this->r.u32(name);
    if (c > std::uint32_t(max))
      this->r.fail(std::to_string(c) + " " + things + "; expected at most " + std::to_string(max));
    n = int(c);
  }
};

/// The RenderParams fields that are not rows of core/ParameterTable.h, in file order (the
/// "parameters" part of the payload above): the one list writeParams and readParams walk. `io`
/// is a ParamWriter (const RenderParams) or a ParamReader.
template<typename Io, typename Params>
void transferParams(Io& io, Params& p)
{
  io.field(p.rouletteStartBounce, "the roulette start");
  io.field(p.maxStepsPerWalk, "steps per walk");
  io.field(p.earlyTermination, "the early termination");
  io.field(p.gradientShading, "gradient shading");
  io.field(p.gradientDelta, "the gradient offsets");
  io.field(p.ambientCoefficient, "the ambient coefficient");
  io.field(p.diffuseCoefficient, "the diffuse coefficient");
  io.field(p.specularCoefficient, "the specular coefficient");
  io.field(p.specularPower, "the specular power");
  io.count(p.numLights, kMaxLights, "the number of lights", "lights");
  for (int l = 0; l < p.numLights; ++l)
  {
    io.field(p.lights[l].type, "a light type");
    io.field(p.lights[l].direction, "a light direction");
    io.field(p.lights[l].position, "a light position");
    io.field(p.lights[l].color, "a light colour");
    io.field(p.lights[l].intensity, "a light intensity");
  }
  io.field(p.camera.position, "the camera position");
  io.field(p.camera.direction, "the camera direction");
  io.field(p.camera.up, "the camera up vector");
  io.field(p.camera.parallel, "the camera projection");
  io.field(p.camera.viewAngle, "the view angle");
  io.field(p.camera.parallelScale, "the parallel scale");
  io.field(p.pixelJitter, "pixel jitter");
  io.field(p.width, "the image width");
  io.field(p.height, "the image height");
  io.field(p.tileSize, "the tile size");
  io.field(p.cullInvisiblePrimitives, "primitive culling");
  io.field(p.heatMapScale, "the heat-map scale");
}

void writeParams(Writer& w, const RenderParams& p)
{
  ParamWriter io{ w };
  transferParams(io, p);
}

RenderParams readParams(Reader& r)
{
  RenderParams p;
  ParamReader io{ r };
  transferParams(io, p);
  if (p.width < 1 || p.width > 16384 || p.height < 1 || p.height > 16384)
    r.fail("the image is " + std::to_string(p.width) + " x " + std::to_string(p.height) +
           "; expected 1..16384 per axis");
  return p;
}
} // namespace

std::vector<std::uint8_t> encodeScene(const SceneDescription& scene)
{
  if (scene.hierarchy.association != FieldAssociation::Cells)
  {
    throw SceneFileError("scene '" + scene.name +
                         "' holds point (vertex-centred) data; scene files hold cell data only");
  }
  Writer payload;
  payload.u32(std::uint32_t(scene.name.size()));
  payload.bytes.insert(payload.bytes.end(), scene.name.begin(), scene.name.end());
  writeHierarchy(payload, scene.hierarchy);
  payload.u32(std::uint32_t(scene.tf.table.size()));
  payload.f32(scene.tf.lo);
  payload.f32(scene.tf.hi);
  payload.f32(scene.tf.unitDistance);
  payload.u8(scene.tf.logScale ? 1 : 0);
  for (const glm::vec4& e : scene.tf.table)
    for (int c = 0; c < 4; ++c)
      payload.f32(e[c]);
  writeParams(payload, scene.params);
  scenefile::writeSceneParameters(payload, scene);

  Writer file;
  file.bytes.assign(kSceneFileMagic, kSceneFileMagic + 8);
  file.u32(kSceneFileVersion);
  file.u64(payload.bytes.size());
  file.bytes.insert(file.bytes.end(), payload.bytes.begin(), payload.bytes.end());
  return file.bytes;
}

SceneDescription decodeScene(const std::vector<std::uint8_t>& bytes, const std::string& what)
{
  Reader r(bytes, 0, what);
  r.need(8, "the magic number");
  if (std::memcmp(bytes.data(), kSceneFileMagic, 8) != 0)
    throw SceneFileError(what + ": not a scene file (the first 8 bytes are not \"AMRDMSCN\")");
  Reader header(bytes, 8, what);
  const std::uint32_t version = header.u32("the version");
  if (version != kSceneFileVersion)
    throw SceneFileError(what + ": scene file version " + std::to_string(version) +
                         "; this build reads version " + std::to_string(kSceneFileVersion) +
                         " only (export the scene again)");
  const std::uint64_t payloadBytes = header.u64("the payload size");
  if (payloadBytes != header.left())
    throw SceneFileError(what + ": the header announces " + std::to_string(payloadBytes) +
                         " bytes of payload but the file holds " + std::to_string(header.left()) +
                         " (" + (payloadBytes > header.left() ? "truncated" : "trailing bytes") +
                         ")");

  Reader r2(bytes, header.position(), what);
  SceneDescription s;
  const std::uint32_t nameBytes = r2.u32("the name length");
  if (nameBytes > kMaxNameBytes)
    r2.fail("the name is " + std::to_string(nameBytes) + " bytes; expected at most " +
            std::to_string(kMaxNameBytes));
  r2.need(nameBytes, "the name");
  s.name.assign(bytes.begin() + std::ptrdiff_t(r2.position()),
    bytes.begin() + std::ptrdiff_t(r2.position() + nameBytes));
  for (std::uint32_t i = 0; i < nameBytes; ++i)
    r2.u8("the name");
  s.hierarchy = readHierarchy(r2);
  const std::uint32_t entries = r2.u32("the transfer-function size");
  if (entries < 1 || entries > kMaxTableEntries)
    r2.fail("the transfer function has " + std::to_string(entries) + " entries; expected 1.." +
            std::to_string(kMaxTableEntries));
  s.tf.lo = r2.f32("the transfer-function domain");
  s.tf.hi = r2.f32("the transfer-function domain");
  s.tf.unitDistance = r2.f32("the unit distance");
  if (!(s.tf.unitDistance > 0.0f))
    r2.fail("the unit distance is " + std::to_string(s.tf.unitDistance) + "; expected > 0");
  const std::uint8_t logScale = r2.u8("the transfer function's log scale");
  if (logScale > 1)
    r2.fail("the transfer function's log-scale flag is " + std::to_string(logScale) +
            "; expected 0 or 1");
  s.tf.logScale = logScale == 1;
  r2.need(std::uint64_t(entries) * 16, "the transfer-function table");
  s.tf.table.resize(entries);
  for (glm::vec4& e : s.tf.table)
    for (int c = 0; c < 4; ++c)
      e[c] = r2.f32("a table entry");
  s.params = readParams(r2);
  scenefile::readSceneParameters(r2, s);
  if (r2.left() != 0)
    r2.fail(std::to_string(r2.left()) + " bytes after the table parameters; expected none");
  try
  {
    checkHierarchy(s.hierarchy); // the pipeline's checks (mesh/PrepareHierarchy.h)
  }
  catch (const std::invalid_argument& e)
  {
    throw SceneFileError(what + ": inconsistent hierarchy: " + e.what());
  }
  return s;
}

void writeSceneFile(const std::string& path, const SceneDescription& scene)
{
  const std::vector<std::uint8_t> bytes = encodeScene(scene);
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  f.close();
  if (!f)
    throw SceneFileError(path + ": cannot write the scene file (" + std::to_string(bytes.size()) +
                         " bytes); expected a writable path");
}

SceneDescription readSceneFile(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  if (!f)
    throw SceneFileError(path + ": cannot open the scene file; expected a readable file");
  f.seekg(0, std::ios::end);
  const std::streamoff size = f.tellg();
  f.seekg(0, std::ios::beg);
  std::vector<std::uint8_t> bytes(size > 0 ? std::size_t(size) : 0);
  f.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!f)
    throw SceneFileError(path + ": cannot read the scene file; expected a readable file");
  return decodeScene(bytes, path);
}

} // namespace amrdm
