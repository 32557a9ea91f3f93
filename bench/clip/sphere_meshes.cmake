# The meshes of the solids benchmark (issue 25) as OFF files, for whole-process runs of contain
# and of the peer drivers in ../peers: sphere_pair_meshes OUT_DIR (outside the repository).
add_executable(sphere_pair_meshes ${CMAKE_CURRENT_LIST_DIR}/sphere_pair_meshes.cpp)
target_link_libraries(sphere_pair_meshes PRIVATE contain::contain contain::io)
contain_warnings(sphere_pair_meshes)
