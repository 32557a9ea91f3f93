# The file formats of contain::io (WKT, GeoJSON, point files, meshes); included by CMakeLists.txt.
list(APPEND IO_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/text_scan.cpp
  ${CMAKE_CURRENT_LIST_DIR}/number_table.cpp
  ${CMAKE_CURRENT_LIST_DIR}/points_io.cpp
  ${CMAKE_CURRENT_LIST_DIR}/wkt.cpp
  ${CMAKE_CURRENT_LIST_DIR}/geojson.cpp
  ${CMAKE_CURRENT_LIST_DIR}/region_io.cpp)
list(APPEND IO_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/mesh_io.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_stl.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_ply.cpp)
