# cmake --install: headers, the domain libraries, the contain command, a CMake package
# (find_package(contain) -> contain::contain, contain::io) and a pkg-config file (contain.pc).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(contain_installed_libraries)
foreach(domain IN LISTS CONTAIN_DOMAINS)
  if(TARGET contain_${domain})
    list(APPEND contain_installed_libraries contain_${domain})
  endif()
endforeach()
set(contain_export_targets contain ${contain_installed_libraries})
if(TARGET contain_io)
  set_target_properties(contain_io PROPERTIES EXPORT_NAME io)
  list(APPEND contain_export_targets contain_io)
endif()

install(TARGETS ${contain_export_targets} EXPORT containTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/contain DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET contain_cli)
  install(TARGETS contain_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
# The GDAL plugin, where contain::io looks for it (../lib/contain from bin/contain, and the
# compiled-in install path).
if(TARGET contain_gdal)
  install(TARGETS contain_gdal LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/contain)
endif()
# muparser's plugin likewise (src/io/CMakeLists.txt).
if(TARGET contain_muparser)
  install(TARGETS contain_muparser LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/contain)
endif()

set(contain_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/contain)
install(EXPORT containTargets NAMESPACE contain:: DESTINATION ${contain_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/containConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/containConfig.cmake
                              INSTALL_DESTINATION ${contain_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/containConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/containConfig.cmake
              ${PROJECT_BINARY_DIR}/containConfigVersion.cmake
        DESTINATION ${contain_cmake_dir})

# Static libraries must be listed dependents first: reverse the layering order.
set(contain_pc_libs "")
set(reversed ${contain_installed_libraries})
list(REVERSE reversed)
foreach(library IN LISTS reversed)
  get_target_property(type ${library} TYPE)
  if(type STREQUAL "STATIC_LIBRARY")  # an INTERFACE layer would have no archive
    string(APPEND contain_pc_libs " -l${library}")
  endif()
endforeach()
# Relocatable: the prefix is found from where the .pc file lies.
file(RELATIVE_PATH contain_pc_up /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
configure_file(${PROJECT_SOURCE_DIR}/cmake/contain.pc.in ${PROJECT_BINARY_DIR}/contain.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/contain.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
