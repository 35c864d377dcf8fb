# OpenMesh's core library as the target OpenMeshCore (mesh clean-up in
# lpv_importers, patch meshing in lpv_radiosity). Debian 12 ships OpenMesh's
# CMake config; the find_library fallback covers installs without it.
include_guard(GLOBAL)
find_package(OpenMesh CONFIG QUIET)
if(NOT TARGET OpenMeshCore)
  find_library(LPV_OPENMESH_CORE_LIBRARY OpenMeshCore REQUIRED)
  find_path(LPV_OPENMESH_INCLUDE_DIR OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh REQUIRED)
  add_library(OpenMeshCore UNKNOWN IMPORTED)
  set_target_properties(OpenMeshCore PROPERTIES
    IMPORTED_LOCATION "${LPV_OPENMESH_CORE_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${LPV_OPENMESH_INCLUDE_DIR}")
endif()
