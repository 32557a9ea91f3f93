# Sections of a solid by many planes: contain's slice_mesh beside CGAL's Polygon_mesh_slicer
# (Debian's libcgal-dev, polylines only) on UV spheres of 131k and 524k triangles.
add_executable(slice_bench ${CMAKE_CURRENT_LIST_DIR}/slice_bench.cpp)
target_link_libraries(slice_bench PRIVATE contain::contain contain_scenes)
if(CGAL_FOUND)
  target_link_libraries(slice_bench PRIVATE CGAL::CGAL)
  target_compile_definitions(slice_bench PRIVATE CONTAIN_BENCH_HAS_CGAL=1)
endif()
contain_warnings(slice_bench)
