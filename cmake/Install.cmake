# Installs libmcdenoise with its headers and a CMake package config, so another
# pipeline tool can `find_package(mcdenoise)` and link `mcdenoise::mcdenoise`.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS mcdenoise EXPORT mcdenoiseTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY imageops/include/mcdenoise DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT mcdenoiseTargets NAMESPACE mcdenoise::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mcdenoise)
configure_package_config_file(cmake/mcdenoiseConfig.cmake.in
        ${CMAKE_BINARY_DIR}/mcdenoiseConfig.cmake
        INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mcdenoise)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/mcdenoiseConfigVersion.cmake
        COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/mcdenoiseConfig.cmake
              ${CMAKE_CURRENT_LIST_DIR}/OpenImageIOIncludeFix.cmake
              ${CMAKE_BINARY_DIR}/mcdenoiseConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mcdenoise)
# OIDN 2.x's trained weights (Apache-2.0, their licence beside them as
# LICENSE-weights.txt), from MCD_WEIGHTS_DIR, where scripts/fetch-weights
# puts them; skipped when that folder does not exist at install time.
install(DIRECTORY "${MCD_WEIGHTS_DIR}/" DESTINATION ${CMAKE_INSTALL_DATADIR}/mcdenoise/weights OPTIONAL
        FILES_MATCHING PATTERN "*.tza" PATTERN "LICENSE-weights.txt")
