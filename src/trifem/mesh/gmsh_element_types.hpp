// SPDX-License-Identifier: MIT
// Gmsh element type numbers shared by the Gmsh reader and writer (internal to the mesh library).
#pragma once

namespace trifem::mesh {

inline constexpr int kGmshTri3 = 2;
inline constexpr int kGmshQuad4 = 3;
inline constexpr int kGmshTet4 = 4;
inline constexpr int kGmshHex8 = 5;
inline constexpr int kGmshPrism6 = 6;
inline constexpr int kGmshTri6 = 9;
inline constexpr int kGmshTet10 = 11;
inline constexpr int kGmshPoint = 15;
inline constexpr int kGmshQuad8 = 16;
inline constexpr int kGmshHex20 = 17;

} // namespace trifem::mesh
