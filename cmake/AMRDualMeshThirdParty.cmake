# Header-only dependencies of the kernels-only build (AMRDM_KERNELS_ONLY): GLM, doctest and
# nlohmann-json. Found as installed packages (Debian: libglm-dev, doctest-dev,
# nlohmann-json3-dev) or, on a bare machine without a package manager, as plain header folders
# under AMRDM_THIRD_PARTY_DIR (default device-check/third_party, filled here by
# `bash scripts/device-check.sh --prepare`). Defines glm::glm, doctest::doctest and
# nlohmann_json::nlohmann_json.
set(AMRDM_THIRD_PARTY_DIR "${PROJECT_SOURCE_DIR}/device-check/third_party" CACHE PATH
  "Folder holding glm/, doctest/ and nlohmann/ header trees for machines without the packages")

# amrdm_header_package(<target> <package> <header>): the installed CMake package, else an
# imported interface target on AMRDM_THIRD_PARTY_DIR; a clear error when neither exists.
function(amrdm_header_package target package header)
  if (TARGET ${target})
    return()
  endif ()
  find_package(${package} CONFIG QUIET)
  if (TARGET ${target})
    return()
  endif ()
  if (EXISTS "${AMRDM_THIRD_PARTY_DIR}/${header}")
    add_library(${target} INTERFACE IMPORTED GLOBAL)
    set_target_properties(${target} PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${AMRDM_THIRD_PARTY_DIR}")
    message(STATUS "AMRDualMesh: ${package} headers from ${AMRDM_THIRD_PARTY_DIR}")
  else ()
    message(FATAL_ERROR "AMRDualMesh: ${package} not found: expected its CMake package (Debian: "
      "scripts/install-deps.sh) or ${AMRDM_THIRD_PARTY_DIR}/${header} (run "
      "`bash scripts/device-check.sh --prepare` on a machine that has the packages)")
  endif ()
endfunction()

amrdm_header_package(glm::glm glm glm/glm.hpp)
amrdm_header_package(doctest::doctest doctest doctest/doctest.h)
amrdm_header_package(nlohmann_json::nlohmann_json nlohmann_json nlohmann/json.hpp)
