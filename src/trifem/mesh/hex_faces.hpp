// SPDX-License-Identifier: MIT
// Local faces of the hex8 cell (VTK/Gmsh node order: 0-3 bottom counter-clockwise, 4-7 top).
#pragma once

#include <array>

namespace trifem::mesh {

/// Local node numbers of the six faces of a hex8, ordered so that the right-hand rule gives
/// the outward normal. Faces: 0 zeta=-1, 1 zeta=+1, 2 eta=-1, 3 xi=+1, 4 eta=+1, 5 xi=-1.
inline constexpr std::array<std::array<int, 4>, 6> kHexFaces = {{
    {0, 3, 2, 1},
    {4, 5, 6, 7},
    {0, 1, 5, 4},
    {1, 2, 6, 5},
    {2, 3, 7, 6},
    {3, 0, 4, 7},
}};

/// Reference coordinates (xi, eta, zeta) of the hex8 nodes.
inline constexpr std::array<std::array<double, 3>, 8> kHexNodeCoords = {{
    {-1, -1, -1},
    {1, -1, -1},
    {1, 1, -1},
    {-1, 1, -1},
    {-1, -1, 1},
    {1, -1, 1},
    {1, 1, 1},
    {-1, 1, 1},
}};

} // namespace trifem::mesh
