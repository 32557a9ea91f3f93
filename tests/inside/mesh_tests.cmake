# Point in polyhedron: the exact ray decision and MeshIndex against a GMP oracle, generalized
# winding numbers, the shared 3D corpus.
list(APPEND INSIDE_TESTS
  ${CMAKE_CURRENT_LIST_DIR}/mesh_oracle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_test_meshes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_ray_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_index_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fast_winding_number_test.cpp)
list(APPEND INSIDE_TEST_LIBS contain_scenes)
# The corpus is read with contain::io, which exists when the command is built.
if(TARGET contain_io)
  list(APPEND INSIDE_TESTS ${CMAKE_CURRENT_LIST_DIR}/point_in_mesh_corpus_test.cpp)
  list(APPEND INSIDE_TEST_LIBS contain::io)
endif()
