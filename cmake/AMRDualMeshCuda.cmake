# Optional CUDA: the same kernel headers compiled by nvcc. Built whenever nvcc is found; never
# required to build or to run the tests (tests that need a device skip and say why).
#
# Architectures: unless CMAKE_CUDA_ARCHITECTURES is given, the default covers the NVIDIA GPUs in
# use (Volta and newer where the toolkit still supports it) as machine code, plus PTX of the
# newest so that later GPUs JIT-compile it:
#   CUDA 13:         75 80 86 89 90 100 120 (+ PTX 120)   (CUDA 13 dropped Volta, sm_70)
#   CUDA 12.8-12.9:  70 75 80 86 89 90 100 120 (+ PTX 120)
#   CUDA 11.8-12.7:  70 75 80 86 89 90 (+ PTX 90)
# Each architecture costs about one more compilation of the kernels (README "GPU": measured
# times); override with -DCMAKE_CUDA_ARCHITECTURES=86 (one GPU), =native (the GPUs of this
# machine) or any CMake list. scripts/build.sh (CI) passes a short list.
option(AMRDM_ENABLE_CUDA "Build the CUDA launcher when nvcc is found" ON)
option(AMRDM_CUDA_PTXAS_REPORT "Print ptxas registers, spills and stack per kernel (-Xptxas -v)" ON)
if (AMRDM_ENABLE_CUDA AND NOT CMAKE_CUDA_COMPILER AND EXISTS "/usr/local/cuda/bin/nvcc")
  set(CMAKE_CUDA_COMPILER "/usr/local/cuda/bin/nvcc")
endif ()
if (AMRDM_ENABLE_CUDA)
  include(CheckLanguage)
  check_language(CUDA)
endif ()
if (AMRDM_ENABLE_CUDA AND CMAKE_CUDA_COMPILER)
  if (NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
    execute_process(COMMAND "${CMAKE_CUDA_COMPILER}" --version OUTPUT_VARIABLE amrdm_nvcc_version)
    string(REGEX MATCH "release ([0-9]+)\\.([0-9]+)" amrdm_nvcc_release "${amrdm_nvcc_version}")
    set(amrdm_nvcc "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}")
    if (amrdm_nvcc VERSION_GREATER_EQUAL 13.0)
      set(amrdm_archs 75-real 80-real 86-real 89-real 90-real 100-real 120)
    elseif (amrdm_nvcc VERSION_GREATER_EQUAL 12.8)
      set(amrdm_archs 70-real 75-real 80-real 86-real 89-real 90-real 100-real 120)
    else ()
      set(amrdm_archs 70-real 75-real 80-real 86-real 89-real 90)
    endif ()
    set(CMAKE_CUDA_ARCHITECTURES "${amrdm_archs}" CACHE STRING
      "CUDA architectures (default for nvcc ${amrdm_nvcc}: Volta/Turing and newer, PTX of the newest)")
    message(STATUS "AMRDualMesh: CUDA architectures ${CMAKE_CUDA_ARCHITECTURES} (nvcc ${amrdm_nvcc}; "
      "override with -DCMAKE_CUDA_ARCHITECTURES=...)")
  else ()
    message(STATUS "AMRDualMesh: CUDA architectures ${CMAKE_CUDA_ARCHITECTURES} (given)")
  endif ()
  enable_language(CUDA)
  find_package(CUDAToolkit REQUIRED)
  # One kernel per integrator, one translation unit each (CudaRenderKernel.h): they compile in
  # parallel, and the path tracer's kernel carries only its own registers.
  add_library(amrdm_cuda STATIC
    Kernels/cuda/CudaLauncher.cu
    Kernels/cuda/CudaRenderer.cu
    Kernels/cuda/GpuMemoryReport.cpp
    Kernels/cuda/CudaRenderPathTracer.cu
    Kernels/cuda/CudaRenderSingleScatter.cu
    Kernels/cuda/CudaRenderRayMarch.cu
    Kernels/cuda/CudaRenderOtherIntegrators.cu)
  target_link_libraries(amrdm_cuda PRIVATE glm::glm PUBLIC CUDA::cudart_static amrdm_kernels)
  target_compile_options(amrdm_cuda PRIVATE
    $<$<COMPILE_LANGUAGE:CUDA>:--expt-relaxed-constexpr -diag-suppress=20012>)
  if (AMRDM_CUDA_PTXAS_REPORT)
    # Registers, spill stores/loads and stack frame of every kernel, per architecture, in the
    # build log (grep "ptxas info").
    target_compile_options(amrdm_cuda PRIVATE $<$<COMPILE_LANGUAGE:CUDA>:-Xptxas=-v>)
  endif ()
  set_target_properties(amrdm_cuda PROPERTIES CUDA_STANDARD 17 POSITION_INDEPENDENT_CODE ON)
  target_compile_definitions(amrdm_cuda PUBLIC AMRDM_HAVE_CUDA=1)
  message(STATUS "AMRDualMesh: CUDA launcher enabled (${CMAKE_CUDA_COMPILER})")
else ()
  message(STATUS "AMRDualMesh: CUDA launcher disabled (no nvcc found or AMRDM_ENABLE_CUDA=OFF)")
endif ()

# The compiled renderer factory (amrdm_renderers, Kernels/CMakeLists.txt) gets CUDA when it is built.
if (TARGET amrdm_cuda)
  target_link_libraries(amrdm_renderers PRIVATE amrdm_cuda)
endif ()
