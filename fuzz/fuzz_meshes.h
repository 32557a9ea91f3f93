#pragma once
// Closed meshes of fixed topology whose vertices the geometric targets fuzz: the triangles only
// (counter-clockwise from outside when the vertices are those of the named solid).

#include <array>

#include "contain/shapes/mesh.h"

namespace contain::fuzz {

/// Octahedron: vertices +x, -x, +y, -y, +z, -z.
inline constexpr std::array<TriangleIndices, 8> kOctahedron{
    {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
/// Cube: vertices 0-3 the bottom face counter-clockwise from above, 4-7 the top face.
inline constexpr std::array<TriangleIndices, 12> kCube{{{0, 2, 1},
                                                        {0, 3, 2},
                                                        {4, 5, 6},
                                                        {4, 6, 7},
                                                        {0, 1, 5},
                                                        {0, 5, 4},
                                                        {1, 2, 6},
                                                        {1, 6, 5},
                                                        {2, 3, 7},
                                                        {2, 7, 6},
                                                        {3, 0, 4},
                                                        {3, 4, 7}}};
/// Two tetrahedra on vertices 0-3 and 4-7.
inline constexpr std::array<TriangleIndices, 8> kTwoTetrahedra{
    {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}, {4, 5, 6}, {4, 7, 5}, {5, 7, 6}, {6, 7, 4}}};

}  // namespace contain::fuzz
