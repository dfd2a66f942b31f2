# `cmake --install build [--prefix P]` (docs/running.md, "Installing"): the executable in P/bin,
# the libraries and their public headers in P/lib and P/include, a CMake package (find_package
# (rodsea): rodsea::engine, rodsea::builder, rodsea::analysis, rodsea::workflow), the scripts that
# `rodsea plot` and `rodsea export --format gsd` run, the examples and the calibration table in
# P/share/rodsea, the docs in P/share/doc/rodsea; the Python package from python/CMakeLists.txt.
# The build's install_manifest.txt lists every file, for uninstalling.
include(CMakePackageConfigHelpers)

set(rodsea_installed_libraries rodsea_engine rodsea_builder)
if(RODSEA_HAVE_CUDA)
  list(APPEND rodsea_installed_libraries rodsea_gpu)  # linked into the engine
endif()
if(NOT RODSEA_ENGINE_ONLY)
  list(APPEND rodsea_installed_libraries rodsea_analysis rodsea_workflow)
endif()
foreach(library IN LISTS rodsea_installed_libraries)
  string(REPLACE "rodsea_" "" export_name ${library})
  set_target_properties(${library} PROPERTIES EXPORT_NAME ${export_name})
endforeach()
install(TARGETS ${rodsea_installed_libraries} EXPORT rodseaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

# The headers of the installed libraries, less the backends' internals (engine/cpu, engine/cuda,
# engine/parallel) and every detail/ folder, which no public header includes.
set(rodsea_header_dirs math shape neighbors engine builder scenes)  # the engine and builder
if(NOT RODSEA_ENGINE_ONLY)
  list(APPEND rodsea_header_dirs analysis cli config io run calibration analyze meanfield)
endif()
# The top level's own (error.hpp, number_text.hpp, ...).
file(GLOB rodsea_top_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/rodsea/*.hpp)
install(FILES ${rodsea_top_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rodsea)
foreach(dir IN LISTS rodsea_header_dirs)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/rodsea/${dir}
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rodsea FILES_MATCHING PATTERN "*.hpp"
          PATTERN "cpu" EXCLUDE PATTERN "cuda" EXCLUDE PATTERN "parallel" EXCLUDE
          PATTERN "detail" EXCLUDE)
endforeach()

set(rodsea_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/rodsea)
install(EXPORT rodseaTargets NAMESPACE rodsea:: DESTINATION ${rodsea_cmake_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rodseaConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/rodseaConfig.cmake
                              INSTALL_DESTINATION ${rodsea_cmake_dir})
# 0.x: a minor version may change the API.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/rodseaConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/rodseaConfig.cmake ${CMAKE_BINARY_DIR}/rodseaConfigVersion.cmake
        DESTINATION ${rodsea_cmake_dir})

if(RODSEA_ENGINE_ONLY)
  return()
endif()

install(TARGETS rodsea RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# What the installed executable runs (view/python_script.cpp finds it beside its bin/).
install(FILES ${PROJECT_SOURCE_DIR}/scripts/rodsea_plot.py ${PROJECT_SOURCE_DIR}/scripts/rodsea_gsd.py
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rodsea/scripts)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scripts/rodsea_plots
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rodsea/scripts FILES_MATCHING PATTERN "*.py"
        PATTERN "__pycache__" EXCLUDE)
# The examples keep their relative paths to the calibration table (../data/calibration.csv).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples DESTINATION ${CMAKE_INSTALL_DATADIR}/rodsea
        PATTERN "__pycache__" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/data/calibration.csv
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rodsea/data)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
