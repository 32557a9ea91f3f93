# 10^7 random 3D segments against a box: each clipper beside a plain copy of the same data.
add_executable(segment_clip_bench ${CMAKE_CURRENT_LIST_DIR}/segment_clip_bench.cpp)
target_link_libraries(segment_clip_bench PRIVATE contain::contain Threads::Threads)
contain_warnings(segment_clip_bench)
# The kernel versions (clip/box_kernel.h, private) are timed one by one.
target_include_directories(segment_clip_bench PRIVATE ${PROJECT_SOURCE_DIR}/src)
