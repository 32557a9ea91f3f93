# Tests of the general polygon booleans (the "booleans" group); each file appends to CLIP_TESTS.
list(APPEND CLIP_TESTS
  ${CMAKE_CURRENT_LIST_DIR}/boolean_checks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/polygon_boolean_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/polygon_boolean_extreme_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/polyline_clip_test.cpp)

# The shared corpus of peer overlay cases: reads JSON Lines and WKT, so it needs contain::io and
# nlohmann-json (present with the CLI build).
if(TARGET contain::io AND TARGET nlohmann_json::nlohmann_json)
  contain_test(clip_boolean_corpus
               SOURCES ${CMAKE_CURRENT_LIST_DIR}/boolean_checks.cpp
                       ${CMAKE_CURRENT_LIST_DIR}/polygon_boolean_corpus_test.cpp
               LIBS contain::contain contain::io nlohmann_json::nlohmann_json)
endif()
