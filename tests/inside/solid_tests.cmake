#The solids group of the inside tests(3D point containment and CSG).
list(APPEND INSIDE_TESTS ${CMAKE_CURRENT_LIST_DIR} / implicit_test.cpp ${CMAKE_CURRENT_LIST_DIR} /
     point_in_triangle_test.cpp ${CMAKE_CURRENT_LIST_DIR} /
     convex_polyhedron_test.cpp ${CMAKE_CURRENT_LIST_DIR} / csg_test.cpp)
list(APPEND INSIDE_TESTS ${CMAKE_CURRENT_LIST_DIR}/csg_mesh_test.cpp)
