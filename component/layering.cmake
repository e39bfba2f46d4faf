# The component's layers: one folder, one static library peristep_layer_<folder>. A layer may include
# headers of its own folder and of the layers it USES, and links exactly those; check_layer.cmake reads
# every #include "<folder>/..." of the folder's files before the library is compiled, so an include
# against the layering fails the build.

# peristep_layer(NAME USES <layers> SOURCES <files>)
function(peristep_layer name)
  cmake_parse_arguments(L "" "" "USES;SOURCES" ${ARGN})
  add_library(peristep_layer_${name} STATIC ${L_SOURCES})
  target_include_directories(peristep_layer_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
  foreach(used IN LISTS L_USES)
    target_link_libraries(peristep_layer_${name} PUBLIC peristep_layer_${used})
  endforeach()
  peristep_check_layer(${name} USES ${L_USES})
  add_dependencies(peristep_layer_${name} peristep_layering_${name})
endfunction()

# peristep_check_layer(NAME USES <layers>): target peristep_layering_NAME runs the check of NAME/ whenever
# one of its files changes; the target that compiles NAME/ depends on it.
function(peristep_check_layer name)
  cmake_parse_arguments(L "" "" "USES" ${ARGN})
  file(GLOB files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.hpp ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cpp)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/layering/${name}.checked)
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DROOT=${CMAKE_CURRENT_SOURCE_DIR} -DLAYER=${name} "-DUSES=${L_USES}" -DSTAMP=${stamp}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/check_layer.cmake
    DEPENDS ${files} ${CMAKE_CURRENT_SOURCE_DIR}/check_layer.cmake
    COMMENT "Checking the includes of component/${name}/ against its layers (${L_USES})" VERBATIM)
  add_custom_target(peristep_layering_${name} DEPENDS ${stamp})
endfunction()
