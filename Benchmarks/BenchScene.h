// One benchmark scene: an AMR set read with every level, its dual mesh (gridlet size 8), and the
// fixed camera, lights and transfer function every run of the benchmark uses. The defaults are
// amrdm-render's (Apps/amrdm-render.cxx): camera at azimuth 35, elevation 25 framing the bounds
// with a 30 degree view angle, a key light of irradiance 4 above-left of the camera plus a white
// environment, the cool-warm preset over the field's range with a linear opacity ramp 0..0.5,
// unit distance = a quarter of the bounding-box half-diagonal (Apps/DefaultView.h).
#pragma once

#include "mesh/AmrHierarchy.h"
#include "render/RenderParams.h"
#include "sampling/TransferFunction.h"

#include "vtkAMRDualMesh.h"
#include "vtkOverlappingAMR.h"
#include "vtkSmartPointer.h"

#include <string>

namespace amrdm_bench
{

struct SetSpec
{
  std::string name;  ///< short id used in file names and tables
  std::string path;  ///< Enzo .hierarchy or AMReX plotfile folder
  std::string array; ///< cell array
  bool logScale = false;
  std::string reader; ///< "enzo" or "amrex" (for the ParaView script)
};

struct Scene
{
  SetSpec spec;
  vtkSmartPointer<vtkOverlappingAMR> amr;
  vtkSmartPointer<vtkAMRDualMesh> field; ///< gridlet size 8, bilinear, log as spec
  amrdm::TransferFunction tf;
  amrdm::RenderParams params;      ///< camera, lights, image size; path tracer, seed 0
  glm::dvec3 sceneOrigin{ 0.0 };   ///< the dual mesh's scene origin (the AMR origin)
  glm::dvec3 lo{ 0.0 }, hi{ 0.0 }; ///< bounds of the data in the scene frame (world - sceneOrigin)
  glm::dvec3 finestSpacing{ 1.0 };
  glm::ivec3 finestDims{ 0 };   ///< finest-level cells over the bounds (ParaView's data_dimensions)
  glm::vec3 focalPoint{ 0.0f }; ///< scene frame, like params.camera
  double readSeconds = 0.0;
};

/// Reads the set, builds its dual mesh and sets up the scene at width x height.
bool loadScene(const SetSpec& spec,
  int width,
  int height,
  int threads,
  Scene& scene,
  std::string& error);

/// The hierarchy (values after log10 when the scene is log scaled), finalized.
bool convertHierarchy(const Scene& scene, amrdm::AmrHierarchy& out, std::string& error);

} // namespace amrdm_bench
