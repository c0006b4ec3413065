#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the meshes of the sliding example (Gmsh 2.2 ASCII, one hex layer 1 mm deep).

Reconstruction of the paper's section 4.3 geometry (its figure is not available):
  lower layer  flat cartilage 8 mm x 1 mm on a flat bone (y = -1), top surface y = 0;
  upper layer  condyle-like cartilage between the radii 9 and 10 mm around (4, 10), spanning a
               4 mm chord of the outer arc, whose lowest point touches the lower layer at x = 4;
               the inner arc is bonded to the (rigid) bone.
Usage: make_mesh.py UPPER_ARC UPPER_THICK LOWER_X LOWER_THICK OUTPUT.msh
  coarse: make_mesh.py 16 3 24 3 sliding_layers_coarse.msh
  fine:   make_mesh.py 40 5 64 5 sliding_layers_fine.msh
"""
import math
import sys

R_OUTER, THICKNESS, CENTRE = 10.0, 1.0, (4.0, 10.0)
LOWER_LENGTH, DEPTH = 8.0, 1.0
HALF_ANGLE = math.asin(2.0 / R_OUTER)  # 4 mm chord of the outer arc


class Msh:
    def __init__(self):
        self.nodes, self.hexes, self.quads, self.names = [], [], [], []

    def node(self, x, y, z):
        self.nodes.append((x, y, z))
        return len(self.nodes)  # 1-based tags

    def group(self, dim, name):
        self.names.append((dim, len(self.names) + 1, name))
        return len(self.names)

    def write(self, path):
        with open(path, "w") as f:
            f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n")
            f.write(f"{len(self.names)}\n")
            for dim, tag, name in self.names:
                f.write(f'{dim} {tag} "{name}"\n')
            f.write(f"$EndPhysicalNames\n$Nodes\n{len(self.nodes)}\n")
            for i, (x, y, z) in enumerate(self.nodes, 1):
                f.write(f"{i} {x:.15g} {y:.15g} {z:.15g}\n")
            f.write(f"$EndNodes\n$Elements\n{len(self.hexes) + len(self.quads)}\n")
            tag = 0
            for kind, elements in ((5, self.hexes), (3, self.quads)):
                for group, nodes in elements:
                    tag += 1
                    f.write(f"{tag} {kind} 2 {group} {group} " + " ".join(map(str, nodes)) + "\n")
            f.write("$EndElements\n")


def body(msh, name, n_along, n_thick, position, surfaces):
    """A structured one-layer body: position(s, t) for s, t in [0, 1] (right-handed in s, t, z).
    surfaces maps a name suffix to 'bottom' (t = 0), 'top' (t = 1), 'zmin' or 'zmax'."""
    ids = {}
    for k in range(2):
        for j in range(n_thick + 1):
            for i in range(n_along + 1):
                x, y = position(i / n_along, j / n_thick)
                ids[i, j, k] = msh.node(x, y, k * DEPTH)
    volume = msh.group(3, name)
    for j in range(n_thick):
        for i in range(n_along):
            quad = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            msh.hexes.append((volume, [ids[a, b, k] for k in range(2) for a, b in quad]))
    for suffix, where in surfaces.items():
        group = msh.group(2, f"{name}.{suffix}")
        if where in ("bottom", "top"):
            j = 0 if where == "bottom" else n_thick
            for i in range(n_along):
                msh.quads.append((group, [ids[i, j, 0], ids[i + 1, j, 0], ids[i + 1, j, 1],
                                          ids[i, j, 1]]))
        else:
            k = 0 if where == "zmin" else 1
            for j in range(n_thick):
                for i in range(n_along):
                    msh.quads.append((group, [ids[i, j, k], ids[i + 1, j, k],
                                              ids[i + 1, j + 1, k], ids[i, j + 1, k]]))


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    n_arc, n_upper, n_x, n_lower = map(int, sys.argv[1:5])
    msh = Msh()
    body(msh, "lower", n_x, n_lower,
         lambda s, t: (LOWER_LENGTH * s, -THICKNESS * (1.0 - t)),
         {"bone": "bottom", "top": "top", "zmin": "zmin", "zmax": "zmax"})

    def arc(s, t):  # t = 0 on the outer (contact) arc, t = 1 on the inner (bone) arc
        theta = HALF_ANGLE * (2.0 * s - 1.0)
        r = R_OUTER - THICKNESS * t
        return CENTRE[0] + r * math.sin(theta), CENTRE[1] - r * math.cos(theta)

    body(msh, "upper", n_arc, n_upper, arc,
         {"contact": "bottom", "bone": "top", "zmin": "zmin", "zmax": "zmax"})
    msh.write(sys.argv[5])


if __name__ == "__main__":
    main()
