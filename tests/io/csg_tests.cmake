# The CSG group of the io tests.
list(APPEND IO_TESTS ${CMAKE_CURRENT_LIST_DIR}/csg_json_test.cpp)
