# Every VTK-free test: plain C++ + GLM + doctest, linked to the kernels only (which checks the
# layering too). Included by Testing/CMakeLists.txt in both configurations; in the kernels-only
# configuration (AMRDM_KERNELS_ONLY, a bare GPU machine) these are all the tests there are.
if (NOT TARGET doctest::doctest)
  find_package(doctest REQUIRED)
endif ()

function(amrdm_add_kernel_test name)
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE amrdm_kernels doctest::doctest)
  add_test(NAME ${name} COMMAND ${name})
  set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 125)
endfunction()

# parallelFor on the persistent pool: thread reuse, determinism, exceptions, nesting.
amrdm_add_kernel_test(TestThreadPool Cxx/TestThreadPool.cxx)
set_tests_properties(TestThreadPool PROPERTIES TIMEOUT 300)
# Elements; dual-mesh construction, gridlets, BVH, field.
amrdm_add_kernel_test(TestElements Cxx/TestElements.cxx)
amrdm_add_kernel_test(TestDualMesh Cxx/TestDualMesh.cxx)
amrdm_add_kernel_test(TestBvh Cxx/TestBvh.cxx)
# The element-kind list: stored values, dispatch, an out-of-range type rejected with a message.
amrdm_add_kernel_test(TestElementKinds Cxx/TestElementKinds.cxx)
amrdm_add_kernel_test(TestRandomHierarchies Cxx/TestRandomHierarchies.cxx)
# Vertex-centred (point-data) AMR: linear fields, no jump at transitions, holes, bad input.
amrdm_add_kernel_test(TestVertexMesh Cxx/TestVertexMesh.cxx)
amrdm_add_kernel_test(TestBoundaryLayer Cxx/TestBoundaryLayer.cxx)
# The box index behind the AMR checks that pair blocks of two levels (against brute force).
amrdm_add_kernel_test(TestBoxIndex Cxx/TestBoxIndex.cxx)
# The one hierarchy pipeline: nesting/alignment, metadata parents, states, value range, log rule.
amrdm_add_kernel_test(TestPrepareHierarchy Cxx/TestPrepareHierarchy.cxx)
# Data-parallel partition: kd-tree regions and the ghost band (union of region meshes = serial).
amrdm_add_kernel_test(TestDomainPartition Cxx/TestDomainPartition.cxx)
# DistributionMode Proxy: region mesh inside the box, level-0 proxy outside, composite majorants.
amrdm_add_kernel_test(TestCompositeMedium Cxx/TestCompositeMedium.cxx)
# Path tracing.
amrdm_add_kernel_test(TestTransport Cxx/TestTransport.cxx)
# The ray marcher's per-step opacity against the exact formula.
amrdm_add_kernel_test(TestStepOpacity Cxx/TestStepOpacity.cxx)
amrdm_add_kernel_test(TestMarchOpticalDepth Cxx/TestMarchOpticalDepth.cxx)
amrdm_add_kernel_test(TestCameraRayEstimator Cxx/TestCameraRayEstimator.cxx)
# Per-pixel low-discrepancy samples (Owen-scrambled Sobol pairs).
amrdm_add_kernel_test(TestLowDiscrepancy Cxx/TestLowDiscrepancy.cxx)
amrdm_add_kernel_test(TestMajorants Cxx/TestMajorants.cxx)
amrdm_add_kernel_test(TestCpuRenderer Cxx/TestCpuRenderer.cxx)
amrdm_add_kernel_test(TestPrimitiveCulling Cxx/TestPrimitiveCulling.cxx)
# Blend modes: isosurfaces, MIP / MinIP / average / additive, slice.
amrdm_add_kernel_test(TestBlendModes Cxx/TestBlendModes.cxx)
# Isosurfaces in the path tracer and embedded in the volume (EmbedIsosurfaces).
amrdm_add_kernel_test(TestIsosurfacePathTracer Cxx/TestIsosurfacePathTracer.cxx)
# The first crossing, also on a face between two dual cells or two primitives (issue 34).
amrdm_add_kernel_test(TestIsoFirstHit Cxx/TestIsoFirstHit.cxx)
# Rendering extremes (transfer functions, density scales, face-aligned rays, image sizes,
# bounces, sample counts) and geometry extremes (deep refinement, offsets, thin boxes).
amrdm_add_kernel_test(TestRenderExtremes Cxx/TestRenderExtremes.cxx)
amrdm_add_kernel_test(TestRenderExtremesImage Cxx/TestRenderExtremesImage.cxx)
amrdm_add_kernel_test(TestGeometryExtremes Cxx/TestGeometryExtremes.cxx)
set_tests_properties(TestRenderExtremes TestRenderExtremesImage TestGeometryExtremes
  PROPERTIES TIMEOUT 300)
# Scene files: round trip, truncation, wrong magic or version, inconsistent sizes.
amrdm_add_kernel_test(TestSceneFile Cxx/TestSceneFile.cxx)

# CUDA: sampling and CPU-vs-GPU images; device choice and amrdm-render --device (when built)
# run without a GPU, the rest skips and says why.
if (TARGET amrdm_cuda)
  amrdm_add_kernel_test(TestCudaSampling Cxx/TestCudaSampling.cxx)
  target_link_libraries(TestCudaSampling PRIVATE amrdm_cuda)
  add_executable(TestCudaRenderer Cxx/TestCudaRenderer.cxx)
  target_link_libraries(TestCudaRenderer PRIVATE amrdm_renderers amrdm_cuda doctest::doctest)
  if (TARGET amrdm-render)
    add_test(NAME TestCudaRenderer COMMAND TestCudaRenderer $<TARGET_FILE:amrdm-render>)
  else ()
    add_test(NAME TestCudaRenderer COMMAND TestCudaRenderer)
  endif ()
  set_tests_properties(TestCudaRenderer PROPERTIES SKIP_RETURN_CODE 125 TIMEOUT 600)
endif ()

# amrdm-devcheck's argument checks and a bad scene file (no data needed, both configurations).
add_test(NAME DevCheckBadInput COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/devcheck_bad_input.sh"
  $<TARGET_FILE:amrdm-devcheck> "${CMAKE_BINARY_DIR}/Testing/Temporary")

# The device check in CPU mode (full configuration: amrdm-bench exports the scenes of the four
# shared sets first): scripts/device-check.sh configures and builds the kernels-only
# configuration in its own folder and runs amrdm-devcheck with small sizes and frame counts.
if (TARGET amrdm-bench)
  add_test(NAME ExportScenes COMMAND amrdm-bench --export-scenes
    "${CMAKE_BINARY_DIR}/device-check/scenes")
  set_tests_properties(ExportScenes PROPERTIES FIXTURES_SETUP scenes TIMEOUT 300)
  add_test(NAME DeviceCheckCpu COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/device-check.sh"
    --device cpu --scenes "${CMAKE_BINARY_DIR}/device-check/scenes"
    --build "${CMAKE_BINARY_DIR}/device-check/build" --quick --allow-missing)
  set_tests_properties(DeviceCheckCpu PROPERTIES FIXTURES_REQUIRED scenes TIMEOUT 1800)
endif ()
