# contain's mesh boolean as a whole process on the sphere pairs of sphere_meshes.cmake, beside
# the peer drivers of ../peers (issue 25): mesh_boolean_bench A.off B.off --op OP OUT.off.
add_executable(mesh_boolean_bench ${CMAKE_CURRENT_LIST_DIR}/mesh_boolean_bench.cpp)
target_include_directories(mesh_boolean_bench PRIVATE ${PROJECT_SOURCE_DIR})
target_link_libraries(mesh_boolean_bench PRIVATE contain::contain contain::io)
contain_warnings(mesh_boolean_bench)
