# Sections of a solid by many planes: contain's slicing kernel in its two parts (preparing,
# slicing) beside Manifold's build and Slice (when CONTAIN_MANIFOLD_DIR names the folder of
# ../shared/peers/manifold/build.sh, as for bench/peers), the whole slice_mesh call, and CGAL's
# Polygon_mesh_slicer (Debian's libcgal-dev, polylines only), on UV spheres of 131k and 524k
# triangles and any mesh files given on the command line.
add_executable(slice_bench ${CMAKE_CURRENT_LIST_DIR}/slice_bench.cpp)
target_link_libraries(slice_bench PRIVATE contain::contain contain::io contain_scenes)
if(CGAL_FOUND)
  target_link_libraries(slice_bench PRIVATE CGAL::CGAL)
  target_compile_definitions(slice_bench PRIVATE CONTAIN_BENCH_HAS_CGAL=1)
endif()
if(CONTAIN_MANIFOLD_DIR AND EXISTS "${CONTAIN_MANIFOLD_DIR}/lib/libmanifold.a"
   AND EXISTS "${CONTAIN_MANIFOLD_DIR}/include/manifold/manifold.h")
  target_include_directories(slice_bench SYSTEM PRIVATE "${CONTAIN_MANIFOLD_DIR}/include")
  target_link_libraries(slice_bench PRIVATE "${CONTAIN_MANIFOLD_DIR}/lib/libmanifold.a")
  target_compile_definitions(slice_bench PRIVATE CONTAIN_BENCH_HAS_MANIFOLD=1)
endif()
contain_warnings(slice_bench)
