# Finds the Debian 12 packages the build needs (see scripts/setup).
find_package(Threads REQUIRED)
find_package(OpenImageIO 2.4 CONFIG REQUIRED)
include(${CMAKE_CURRENT_LIST_DIR}/OpenImageIOIncludeFix.cmake)
