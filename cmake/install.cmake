# `cmake --install build --prefix P` (docs/integration.md, "Installing and finding the
# package"): the libraries as namespaced targets (Antumbra::framegraph, ...), their headers,
# the pass shaders and the data under share/antumbra/, the `antumbra` program, and
# AntumbraConfig.cmake. Nothing installed names a folder of the build machine, so P can move.
include(CMakePackageConfigHelpers)

# Three export sets, one per component of the package, so that a host asking only for the
# graph core (COMPONENTS framegraph) needs neither Vulkan nor anything else of the renderer:
#   framegraph: base, framegraph                                 (nlohmann_json)
#   scene:      scene, watch, gpu_interface, layering(_scene)    (+ glm, TinyGLTF, stb)
#   runtime:    engine, fg_vulkan, passes, runtime               (+ Vulkan, glslang, spdlog)
set(antumbra_components framegraph scene runtime)
set(antumbra_framegraph_targets antumbra_base antumbra_framegraph)
set(antumbra_scene_targets antumbra_scene antumbra_watch antumbra_gpu_interface antumbra_layering
    antumbra_layering_scene)
set(antumbra_runtime_targets antumbra_engine antumbra_fg_vulkan antumbra_passes antumbra_runtime)

set(ANTUMBRA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Antumbra)
# Shaders are compiled at run time, so their sources are what a program needs; the layout
# under it is the source tree's (data/, passes/), which runtime::DataPaths expects.
set(ANTUMBRA_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/antumbra)

foreach(component IN LISTS antumbra_components)
  foreach(target IN LISTS antumbra_${component}_targets)
    # In-tree names stay antumbra_<name>; exported, Antumbra::<name>.
    string(REGEX REPLACE "^antumbra_" "" export_name ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
    # The headers are C++20: a host compiling them gets the standard with the target.
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "INTERFACE_LIBRARY")
      target_compile_features(${target} INTERFACE cxx_std_20)
    else()
      target_compile_features(${target} PUBLIC cxx_std_20)
    endif()
  endforeach()
  install(TARGETS ${antumbra_${component}_targets}
    EXPORT Antumbra_${component}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT Antumbra_${component}
    NAMESPACE Antumbra::
    FILE AntumbraTargets-${component}.cmake
    DESTINATION ${ANTUMBRA_INSTALL_CMAKEDIR})
endforeach()

# Headers: each library's include/ tree holds antumbra/<library>/..., merged under include/.
foreach(dir base framegraph framegraph/vulkan engine/core engine/scene engine/watch
    passes/light_layering/core runtime)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
# The passes' headers a host writing its own pass type includes, with their in-tree paths
# below include/antumbra/passes/ ("common/pass_support.hpp", "interface/shared/limits.h").
set(passes_include ${CMAKE_INSTALL_INCLUDEDIR}/antumbra/passes)
install(FILES ${PROJECT_SOURCE_DIR}/passes/register_builtin_passes.hpp DESTINATION ${passes_include})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/passes/common/ DESTINATION ${passes_include}/common
  FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/passes/interface/shared/
  DESTINATION ${passes_include}/interface/shared FILES_MATCHING PATTERN "*.h")

# The shaders and every header they include (passes/interface/shared/*.h, each pass's
# *_interface.h), file by file so that no empty C++-only folder is created.
file(GLOB_RECURSE shader_files RELATIVE ${PROJECT_SOURCE_DIR}/passes CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/passes/*.comp ${PROJECT_SOURCE_DIR}/passes/*.frag
  ${PROJECT_SOURCE_DIR}/passes/*.vert ${PROJECT_SOURCE_DIR}/passes/*.glsl
  ${PROJECT_SOURCE_DIR}/passes/*.h)
foreach(file IN LISTS shader_files)
  get_filename_component(dir ${file} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/passes/${file} DESTINATION ${ANTUMBRA_INSTALL_DATADIR}/passes/${dir})
endforeach()
# Graphs, scenes, the models they reference and the JSON Schema of graph files.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${ANTUMBRA_INSTALL_DATADIR}/data)

# The program: it finds the data through <prefix>/bin/../share/antumbra (runtime/data_paths).
install(TARGETS antumbra RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/AntumbraConfig.cmake.in
  ${PROJECT_BINARY_DIR}/AntumbraConfig.cmake
  INSTALL_DESTINATION ${ANTUMBRA_INSTALL_CMAKEDIR}
  PATH_VARS ANTUMBRA_INSTALL_DATADIR)
# Before 1.0 a minor version may change the API, so only the same major.minor matches.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/AntumbraConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/AntumbraConfig.cmake
  ${PROJECT_BINARY_DIR}/AntumbraConfigVersion.cmake DESTINATION ${ANTUMBRA_INSTALL_CMAKEDIR})
