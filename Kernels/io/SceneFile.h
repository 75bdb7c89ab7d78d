// Scene files: a whole render scene (the AMR hierarchy, the dual-mesh build option, the transfer
// function, camera, lights and every render parameter) in one compact, versioned binary file
// that needs no VTK to read. amrdm-render --export-scene and amrdm-bench --export-scenes write
// them from any AMR file; the kernels-only programs (amrdm-devcheck) read them and build the
// dual mesh themselves (the hierarchy is 4-5 bytes per cell; the built mesh would be larger).
//
// Layout (little-endian, no padding):
//   "AMRDMSCN" (8 bytes), version (u32, kSceneFileVersion), payload bytes (u64), payload.
// The payload is a fixed sequence of sections, documented field by field in SceneFile.cpp:
// name, hierarchy (levels, ratios, frame, blocks with values and optional cell states), transfer
// function, render parameters, and the parameter table's rows by name (build and render). Every
// count is checked against the bytes left before anything is allocated. Host code.
#pragma once

#include "mesh/AmrHierarchy.h"
#include "core/ParameterTable.h"
#include "render/RenderParams.h"
#include "sampling/TransferFunction.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace amrdm
{

/// The file's first 8 bytes.
constexpr char kSceneFileMagic[8] = { 'A', 'M', 'R', 'D', 'M', 'S', 'C', 'N' };
/// The one version this build reads and writes; a file of another version is refused.
/// 3: the BVH leaf size is stored; 4: the parameter table's rows are stored by name
/// (io/SceneFileParameters.h): a new row needs no new version.
constexpr std::uint32_t kSceneFileVersion = 4;

/// A truncated file, a wrong magic or version, inconsistent sizes or invalid contents; the
/// message names the file, what was wrong and what was expected.
class SceneFileError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Everything a render needs. Camera and point lights are in the hierarchy's scene frame
/// (world - sceneOrigin), as RenderParams always are. params.threads is not stored (0 on read).
struct SceneDescription
{
  std::string name; ///< free text: the source file and array, for reports
  /// As converted from the source (states optional per block). Explicit states equal to what
  /// finalizeCellStates() derives are not stored: read back, such a block has none.
  AmrHierarchy hierarchy;
  /// DualMeshBuildOptions used to build the mesh: the table's Build rows (core/ParameterTable.h).
  // BEGIN GENERATED scene-build-fields (Tools/generate_parameters.py)
  // clang-format off
  int gridletSize = int(param::GridletSize.defaultValue);
  int bvhLeafSize = int(param::BVHLeafSize.defaultValue);
  // clang-format on
  // END GENERATED scene-build-fields
  TransferFunction tf;
  RenderParams params;
};

/// The file's bytes (header and payload).
std::vector<std::uint8_t> encodeScene(const SceneDescription& scene);
/// Parses the bytes of a scene file; `what` names the source in messages. Throws SceneFileError.
/// The hierarchy is validated (AmrHierarchy::validate) but not finalized.
SceneDescription decodeScene(const std::vector<std::uint8_t>& bytes, const std::string& what);

/// Writes `scene` to `path`; throws SceneFileError when the file cannot be written.
void writeSceneFile(const std::string& path, const SceneDescription& scene);
/// Reads a scene file; throws SceneFileError (see decodeScene).
SceneDescription readSceneFile(const std::string& path);

} // namespace amrdm
