# granpipe_add_plugin(NAME SOURCES...)
#
# Builds one plugin shared library named granpipe_<NAME> into the plugin directory.
# The file name carries the plugin name so that the loader can tell the user which
# plugin a refused (ABI-mismatched) library would have provided. Used in-tree and,
# through granpipeConfig.cmake, by out-of-tree plugins.
function(granpipe_add_plugin name)
  add_library(granpipe_${name} MODULE ${ARGN})
  set_target_properties(granpipe_${name} PROPERTIES
    PREFIX ""
    OUTPUT_NAME granpipe_${name}
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  if(TARGET granpipe::core)
    target_link_libraries(granpipe_${name} PRIVATE granpipe::core)
  else()
    target_link_libraries(granpipe_${name} PRIVATE granpipe_core)
  endif()
  target_compile_options(granpipe_${name} PRIVATE -Wall -Wextra)
  set_property(GLOBAL APPEND PROPERTY GRANPIPE_PLUGIN_TARGETS granpipe_${name})
  if(DEFINED GRANPIPE_PLUGIN_BUILD_DIR)
    set_target_properties(granpipe_${name} PROPERTIES
      LIBRARY_OUTPUT_DIRECTORY ${GRANPIPE_PLUGIN_BUILD_DIR})
  endif()
  if(DEFINED GRANPIPE_PLUGIN_INSTALL_DIR)
    install(TARGETS granpipe_${name} LIBRARY DESTINATION ${GRANPIPE_PLUGIN_INSTALL_DIR})
  endif()
endfunction()
