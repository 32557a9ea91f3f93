# Tests of the file formats of contain::io; included by CMakeLists.txt.
list(APPEND IO_TESTS
  ${CMAKE_CURRENT_LIST_DIR}/points_io_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/wkt_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/geojson_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/region_io_test.cpp)
list(APPEND IO_TESTS
  ${CMAKE_CURRENT_LIST_DIR}/mesh_io_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_io_text_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_io_binary_test.cpp)
