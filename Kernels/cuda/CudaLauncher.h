// The CUDA launcher's host interface. Only CudaLauncher.cu includes CUDA headers; this header is
// plain C++ so the Mapper can call it when the project was built with nvcc (AMRDM_HAVE_CUDA).
#pragma once

#include "mesh/DualMesh.h"
#include "mesh/ElementTest.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace amrdm
{
namespace cuda
{

/// True when a CUDA device can be used; otherwise `reason` says why (no device, driver error).
bool deviceAvailable(std::string* reason = nullptr);

/// Samples the field at n grid-space points on the GPU: uploads the mesh, launches the same
/// sampleField() the CPU runs, and downloads values and hit flags. Throws std::runtime_error
/// naming the failing CUDA call (out of memory included).
void samplePoints(const DualMesh& mesh,
  const glm::vec3* points,
  std::size_t n,
  const ElementTestParams& params,
  float* values,
  std::uint8_t* hits);

} // namespace cuda
} // namespace amrdm
