# Optional CUDA: the same kernel headers compiled by nvcc. Built whenever nvcc is found; never
# required to build or to run the tests (tests that need a device skip and say why).
option(AMRDM_ENABLE_CUDA "Build the CUDA launcher when nvcc is found" ON)
if (AMRDM_ENABLE_CUDA AND NOT CMAKE_CUDA_COMPILER AND EXISTS "/usr/local/cuda/bin/nvcc")
  set(CMAKE_CUDA_COMPILER "/usr/local/cuda/bin/nvcc")
endif ()
if (AMRDM_ENABLE_CUDA)
  include(CheckLanguage)
  check_language(CUDA)
endif ()
if (AMRDM_ENABLE_CUDA AND CMAKE_CUDA_COMPILER)
  if (NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
    set(CMAKE_CUDA_ARCHITECTURES 90)
  endif ()
  enable_language(CUDA)
  find_package(CUDAToolkit REQUIRED)
  # CudaRenderer.cu is the one heavy translation unit (every integrator for the dual-mesh medium).
  add_library(amrdm_cuda STATIC Kernels/CudaLauncher.cu Kernels/CudaRenderer.cu)
  target_link_libraries(amrdm_cuda PRIVATE glm::glm PUBLIC CUDA::cudart_static amrdm_kernels)
  target_compile_options(amrdm_cuda PRIVATE
    $<$<COMPILE_LANGUAGE:CUDA>:--expt-relaxed-constexpr -diag-suppress=20012>)
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
