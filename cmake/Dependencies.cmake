# Finds the Debian 12 packages the build needs (see scripts/setup).
find_package(Threads REQUIRED)
find_package(OpenImageIO 2.4 CONFIG REQUIRED)
include(${CMAKE_CURRENT_LIST_DIR}/OpenImageIOIncludeFix.cmake)
# oneDNN (libdnnl-dev), found by hand: its own CMake config also demands
# OpenCL's headers, which the CPU engine never uses. Its CPU runtime is
# OpenMP (libgomp), whose thread count the network sets per run.
find_path(MCD_DNNL_INCLUDE_DIR oneapi/dnnl/dnnl.hpp REQUIRED)
find_library(MCD_DNNL_LIBRARY dnnl REQUIRED)
find_library(MCD_GOMP_LIBRARY NAMES libgomp.so.1 gomp REQUIRED)
add_library(mcd_dnnl INTERFACE IMPORTED)
set_target_properties(mcd_dnnl PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${MCD_DNNL_INCLUDE_DIR}"
                                          INTERFACE_LINK_LIBRARIES "${MCD_DNNL_LIBRARY};${MCD_GOMP_LIBRARY}")
