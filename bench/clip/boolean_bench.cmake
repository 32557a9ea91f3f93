# Polygon intersection and box clipping against Clipper 1 (libpolyclipping-dev), Boost.Geometry,
# GEOS and, when built, Clipper2 (not in Debian: build it from ../shared/peers/clipper2 with its
# build.sh into a folder outside the project and pass that folder as CONTAIN_CLIPPER2_DIR).
find_path(POLYCLIPPING_INCLUDE_DIR polyclipping/clipper.hpp)
find_library(POLYCLIPPING_LIBRARY polyclipping)
set(CONTAIN_CLIPPER2_DIR "" CACHE PATH
    "folder holding libclipper2.a built by ../shared/peers/clipper2/build.sh (empty: no Clipper2)")
set(CONTAIN_CLIPPER2_INCLUDE "${PROJECT_SOURCE_DIR}/../shared/peers/clipper2/include" CACHE PATH
    "folder holding clipper2/clipper.h")
if(NOT TARGET PkgConfig::GEOS OR NOT POLYCLIPPING_INCLUDE_DIR OR NOT POLYCLIPPING_LIBRARY)
  message(WARNING "GEOS or libpolyclipping not found: polygon_boolean_bench not built")
else()
  add_executable(polygon_boolean_bench ${CMAKE_CURRENT_LIST_DIR}/polygon_boolean_bench.cpp)
  target_include_directories(polygon_boolean_bench PRIVATE ${POLYCLIPPING_INCLUDE_DIR})
  target_link_libraries(polygon_boolean_bench PRIVATE contain::contain contain_scenes
                        benchmark::benchmark Boost::headers PkgConfig::GEOS ${POLYCLIPPING_LIBRARY})
  if(CONTAIN_CLIPPER2_DIR AND EXISTS "${CONTAIN_CLIPPER2_DIR}/libclipper2.a"
     AND EXISTS "${CONTAIN_CLIPPER2_INCLUDE}/clipper2/clipper.h")
    target_include_directories(polygon_boolean_bench SYSTEM PRIVATE ${CONTAIN_CLIPPER2_INCLUDE})
    target_link_libraries(polygon_boolean_bench PRIVATE "${CONTAIN_CLIPPER2_DIR}/libclipper2.a")
    target_compile_definitions(polygon_boolean_bench PRIVATE CONTAIN_HAVE_CLIPPER2=1)
    message(STATUS "polygon_boolean_bench: Clipper2 from ${CONTAIN_CLIPPER2_DIR}")
  else()
    message(STATUS "polygon_boolean_bench: Clipper2 skipped (set CONTAIN_CLIPPER2_DIR to the "
                   "folder of ../shared/peers/clipper2/build.sh's libclipper2.a)")
  endif()
  contain_warnings(polygon_boolean_bench)
  # Boost.Geometry 1.74's rescale policy trips GCC 12's -Wmaybe-uninitialized in its own headers.
  target_compile_options(polygon_boolean_bench PRIVATE -Wno-maybe-uninitialized)
endif()
