# granpipe_add_plugin(<name> SOURCES <file>... [LIBRARY_SOURCES <file>...]
#                     [DEPENDS <dependency>...] [TESTS <file>...] [TEST_DEPENDS <dependency>...])
#
# Builds one plugin shared library named granpipe_<name> into the plugin directory.
# The file name carries the plugin name so that the loader can tell the user which
# plugin a refused (ABI-mismatched) library would have provided. Used in-tree and,
# through granpipeConfig.cmake, by out-of-tree plugins.
#
# LIBRARY_SOURCES   the plugin's logic, built as a static <name>_lib that its tests link;
#                   SOURCES hold the rest (the registration).
# DEPENDS           what the plugin needs beyond the core: CGAL, Boost (headers),
#                   Boost.<component> (e.g. Boost.graph), GSL, TBB, ZLIB. Every plugin also links
#                   OpenMP, since plugins run `num_threads(ctx.threads)` loops.
#                   If one is not found, the plugin is left out of the build with one
#                   message and the rest of granpipe builds.
# TESTS             GoogleTest sources of the plugin; in-tree, tests/CMakeLists.txt builds
#                   each one (linking <name>_lib). Out of tree they are ignored.
# TEST_DEPENDS      what only the tests need; if one is missing the tests are left out.
function(granpipe_add_plugin name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" ""
                        "SOURCES;LIBRARY_SOURCES;DEPENDS;TESTS;TEST_DEPENDS")
  if(arg_UNPARSED_ARGUMENTS OR NOT arg_SOURCES)
    message(FATAL_ERROR "granpipe_add_plugin(${name}): expected SOURCES <file>..., got "
                        "\"${ARGN}\" (e.g. granpipe_add_plugin(${name} SOURCES ${name}.cpp))")
  endif()

  _granpipe_find_dependencies(deps missing OpenMP ${arg_DEPENDS})
  if(missing)
    list(JOIN missing ", " missing)
    message(NOTICE "granpipe: plugin ${name} left out: ${missing} not found")
    return()
  endif()

  set(plugin granpipe_${name})
  add_library(${plugin} MODULE ${arg_SOURCES})
  set_target_properties(${plugin} PROPERTIES
    PREFIX ""
    OUTPUT_NAME granpipe_${name}
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  target_link_libraries(${plugin} PRIVATE granpipe::core ${deps})
  target_compile_options(${plugin} PRIVATE -Wall -Wextra)
  if(arg_LIBRARY_SOURCES)
    add_library(${name}_lib STATIC ${arg_LIBRARY_SOURCES})
    target_link_libraries(${name}_lib PUBLIC granpipe::core ${deps})
    target_include_directories(${name}_lib PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_options(${name}_lib PRIVATE -Wall -Wextra)
    target_link_libraries(${plugin} PRIVATE ${name}_lib)
  endif()
  set_property(GLOBAL APPEND PROPERTY GRANPIPE_PLUGIN_TARGETS ${plugin})
  if(DEFINED GRANPIPE_PLUGIN_BUILD_DIR)
    set_target_properties(${plugin} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${GRANPIPE_PLUGIN_BUILD_DIR})
  endif()
  if(DEFINED GRANPIPE_PLUGIN_INSTALL_DIR)
    install(TARGETS ${plugin} LIBRARY DESTINATION ${GRANPIPE_PLUGIN_INSTALL_DIR})
  endif()
  if(arg_TESTS AND GRANPIPE_BUILD_TESTS)
    _granpipe_record_tests(${name} "${arg_TESTS}" "${arg_TEST_DEPENDS}")
  endif()
endfunction()

# Records a plugin's tests for tests/CMakeLists.txt: the sources (property GRANPIPE_TESTS of
# the plugin target) and, unless what only they need is missing, what they link (the
# interface target granpipe_<name>_test_links, made here because the imported targets found
# here are seen only from this directory).
function(_granpipe_record_tests name tests test_dependencies)
  set(sources)
  foreach(test ${tests})
    get_filename_component(test ${test} ABSOLUTE)  # relative to the plugin's folder
    list(APPEND sources ${test})
  endforeach()
  set_property(TARGET granpipe_${name} PROPERTY GRANPIPE_TESTS ${sources})
  _granpipe_find_dependencies(deps missing ${test_dependencies})
  if(missing)
    list(JOIN missing ", " missing)
    message(NOTICE "granpipe: tests of plugin ${name} left out: ${missing} not found")
    return()
  endif()
  add_library(granpipe_${name}_test_links INTERFACE)
  target_link_libraries(granpipe_${name}_test_links INTERFACE ${deps})
  if(TARGET ${name}_lib)
    target_link_libraries(granpipe_${name}_test_links INTERFACE ${name}_lib)
  endif()
endfunction()

# Finds each named dependency, quietly (the caller says once what is missing): sets <targets>
# to the imported targets of those found and <missing> to the names of those not found.
function(_granpipe_find_dependencies targets missing)
  set(found_targets)
  set(not_found)
  list(REMOVE_DUPLICATES ARGN)
  foreach(dependency ${ARGN})
    if(dependency STREQUAL "CGAL")
      find_package(Boost 1.74 QUIET)  # without Boost, CGAL's own config stops the configure
      if(TARGET Boost::headers)
        find_package(CGAL QUIET)
      endif()
      set(target CGAL::CGAL)
    elseif(dependency STREQUAL "Boost")
      find_package(Boost 1.74 QUIET)
      set(target Boost::headers)
    elseif(dependency MATCHES "^Boost\\.([a-z_]+)$")
      set(target Boost::${CMAKE_MATCH_1})  # before find_package, whose matches overwrite it
      find_package(Boost 1.74 QUIET COMPONENTS ${CMAKE_MATCH_1})
    elseif(dependency STREQUAL "GSL")
      find_package(GSL QUIET)
      set(target GSL::gsl)
    elseif(dependency STREQUAL "TBB")
      find_package(TBB QUIET)
      set(target TBB::tbb)
    elseif(dependency STREQUAL "ZLIB")
      find_package(ZLIB QUIET)
      set(target ZLIB::ZLIB)
    elseif(dependency STREQUAL "OpenMP")
      find_package(OpenMP QUIET COMPONENTS CXX)
      set(target OpenMP::OpenMP_CXX)
    else()
      message(FATAL_ERROR "granpipe_add_plugin: unknown dependency \"${dependency}\" (expected "
                          "CGAL, Boost, Boost.<component>, GSL, TBB, ZLIB or OpenMP)")
    endif()
    if(TARGET ${target})
      list(APPEND found_targets ${target})
      if(dependency STREQUAL "GSL" AND TARGET granpipe_curve_fit)
        list(APPEND found_targets granpipe_curve_fit)  # the core's fitter comes with GSL
      elseif(dependency STREQUAL "GSL" AND TARGET granpipe::granpipe_curve_fit)
        list(APPEND found_targets granpipe::granpipe_curve_fit)  # the same, installed
      elseif(dependency STREQUAL "GSL")
        # The header is installed either way; its library only where granpipe found GSL.
        message(WARNING "granpipe was built without GSL: its curve fitter "
                        "(granpipe/curve_fit.hpp) is not there to link, so a plugin that "
                        "calls it fails to link or load; rebuild granpipe with GSL "
                        "(Debian: libgsl-dev)")
      endif()
    else()
      list(APPEND not_found ${dependency})
    endif()
  endforeach()
  set(${targets} ${found_targets} PARENT_SCOPE)
  set(${missing} ${not_found} PARENT_SCOPE)
endfunction()
