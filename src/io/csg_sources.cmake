# The CSG group of contain::io: the JSON reader and its muparser adaptor.
list(APPEND IO_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/csg_json.cpp
  ${CMAKE_CURRENT_LIST_DIR}/muparser_function.cpp)
