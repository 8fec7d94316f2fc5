include(CMakePackageConfigHelpers)
install(TARGETS granpipe_core EXPORT granpipeTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The curve fitter (a static library, as in the tree) for plugins that declare DEPENDS GSL.
if(TARGET granpipe_curve_fit)
  install(TARGETS granpipe_curve_fit EXPORT granpipeTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
install(TARGETS granpipe RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(PROGRAMS scripts/report.py DESTINATION ${CMAKE_INSTALL_DATADIR}/granpipe)
list(REMOVE_ITEM GRANPIPE_REPORT_SCRIPTS report.py)
list(TRANSFORM GRANPIPE_REPORT_SCRIPTS PREPEND scripts/ OUTPUT_VARIABLE report_modules)
install(FILES ${report_modules} DESTINATION ${CMAKE_INSTALL_DATADIR}/granpipe)
install(DIRECTORY core/include/granpipe DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/core/include/granpipe/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/granpipe)
set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/granpipe)
install(EXPORT granpipeTargets NAMESPACE granpipe:: DESTINATION ${config_dir})
# Made for the install only, and kept out of the build tree's top: there find_package
# (CMAKE_PREFIX_PATH=build) took it and failed on the targets only an install has.
set(staged_config ${PROJECT_BINARY_DIR}/install-config)
configure_package_config_file(cmake/granpipeConfig.cmake.in
  ${staged_config}/granpipeConfig.cmake INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${staged_config}/granpipeConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${staged_config}/granpipeConfig.cmake
              ${staged_config}/granpipeConfigVersion.cmake
              cmake/GranpipePlugin.cmake
        DESTINATION ${config_dir})
