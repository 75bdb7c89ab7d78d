// Scene export: an AMR data set plus the transfer function, camera, lights and render
// parameters of a render, written as a VTK-free scene file (Kernels/io/SceneFile.h) that
// amrdm-devcheck and other kernels-only programs read. Used by amrdm-render --export-scene and
// amrdm-bench --export-scenes.
#pragma once

#include "render/RenderParams.h"       // For amrdm::RenderParams
#include "sampling/TransferFunction.h" // For amrdm::TransferFunction

#include <string>

class vtkOverlappingAMR;

namespace amrdm_app
{

/// Converts `amr` (cell array `array`, `component`, log10 when `logScale`) into the scene's
/// hierarchy and writes it with the rest of the scene to `path`. `params`' camera and point
/// lights must be in the dual mesh's scene frame (world - AMR origin), as the renderer gets
/// them. Prints one line with the file size. False with `error` naming what failed.
bool ExportScene(const std::string& path,
  const std::string& name,
  vtkOverlappingAMR* amr,
  const std::string& array,
  int component,
  bool logScale,
  int gridletSize,
  int bvhLeafSize,
  const amrdm::RenderParams& params,
  const amrdm::TransferFunction& tf,
  std::string& error);

} // namespace amrdm_app
