// Device choice: which Renderer implementation to create. Compiled code (RendererFactory.cpp,
// library amrdm_renderers): the answer depends on how the project was built (nvcc found or not),
// never on the includer's macros.
//   Cpu:  CpuRenderer.
//   Cuda: CudaRenderer; std::runtime_error naming the reason when this build has no CUDA or no
//         device can be used. Out of device memory is GpuOutOfMemory (an error, no fallback).
//   Auto: CUDA when a device can be used, else the CPU, said once through `log`. Out of device
//         memory (mesh upload, transfer function, frame buffers) switches to the CPU, said once,
//         and the interrupted call is replayed there (accumulated samples restart).
// Host code.
#pragma once

#include "render/Renderer.h"

#include <functional>
#include <memory>
#include <string>

namespace amrdm
{

/// Receives the factory's one-line messages (device chosen, fallback).
using RendererLog = std::function<void(const std::string&)>;

/// True when this build has CUDA and a device can be used; otherwise `reason` says why.
bool cudaRenderingAvailable(std::string* reason = nullptr);

/// True when this build compiled the CUDA renderer (nvcc found, AMRDM_ENABLE_CUDA on).
bool cudaSupportBuilt();

/// Creates the renderer for `device` (see the top of this file). `log` (default: stderr) gets
/// one line for Auto saying which device renders and why, and one line on an out-of-memory
/// fallback.
std::unique_ptr<Renderer> createRenderer(RenderDevice device, RendererLog log = nullptr);

/// Wraps a CUDA renderer so that running out of device memory hands over to a CpuRenderer
/// (replaying the mesh and transfer function, said once through `log`): the Auto device's
/// renderer. Without CUDA in this build, returns `gpu` unchanged.
std::unique_ptr<Renderer> withCpuFallback(std::unique_ptr<Renderer> gpu, RendererLog log);

} // namespace amrdm
