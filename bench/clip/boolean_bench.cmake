# Polygon intersection against Clipper 1 (libpolyclipping-dev), Boost.Geometry and GEOS.
find_path(POLYCLIPPING_INCLUDE_DIR polyclipping/clipper.hpp)
find_library(POLYCLIPPING_LIBRARY polyclipping)
if(NOT TARGET PkgConfig::GEOS OR NOT POLYCLIPPING_INCLUDE_DIR OR NOT POLYCLIPPING_LIBRARY)
  message(WARNING "GEOS or libpolyclipping not found: polygon_boolean_bench not built")
else()
  add_executable(polygon_boolean_bench ${CMAKE_CURRENT_LIST_DIR}/polygon_boolean_bench.cpp)
  target_include_directories(polygon_boolean_bench PRIVATE ${POLYCLIPPING_INCLUDE_DIR})
  target_link_libraries(polygon_boolean_bench PRIVATE contain::contain contain_scenes
                        benchmark::benchmark Boost::headers PkgConfig::GEOS ${POLYCLIPPING_LIBRARY})
  contain_warnings(polygon_boolean_bench)
  # Boost.Geometry 1.74's rescale policy trips GCC 12's -Wmaybe-uninitialized in its own headers.
  target_compile_options(polygon_boolean_bench PRIVATE -Wno-maybe-uninitialized)
endif()
