#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the mesh of the knee flexion example (Gmsh 2.2 ASCII, one hex layer 1 mm deep): a
sagittal section of a femoral condyle on a tibial plateau, in plane strain.

  tibial   flat cartilage 16 mm x 1 mm, top surface y = 0, bottom (y = -1) bonded to the tibia;
  femoral  condyle cartilage between the radii 9 and 10 mm around the flexion axis (8, 10),
           spanning +-0.6 rad about its lowest point, which touches the tibial cartilage at x = 8;
  femur    the condyle's bone: rigid cells between the radii 8.5 and 9 mm (sharing the
           cartilage's inner nodes: the cartilage is bonded to it).

Physical groups: volumes "tibial", "femoral", "femur"; surfaces "tibial.bone", "tibial.top",
"tibial.zmin", "tibial.zmax", "femoral.contact", "femoral.bone"; points "femoral.free" (the
femoral cartilage's nodes off the bone, whose z displacement the plane strain holds).

Usage: make_mesh.py ARC THICK TIBIAL_X TIBIAL_THICK OUTPUT.msh
  make_mesh.py 48 3 40 3 knee_flexion.msh
"""
import math
import sys

CENTRE = (8.0, 10.0)
R_CARTILAGE, THICKNESS, R_BONE = 10.0, 1.0, 8.5
HALF_ANGLE = 0.6
TIBIAL_LENGTH, DEPTH = 16.0, 1.0


class Msh:
    def __init__(self):
        self.nodes, self.elements, self.names = [], [], []

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
            f.write(f"$EndNodes\n$Elements\n{len(self.elements)}\n")
            for tag, (kind, group, nodes) in enumerate(self.elements, 1):
                f.write(f"{tag} {kind} 2 {group} {group} " + " ".join(map(str, nodes)) + "\n")
            f.write("$EndElements\n")


def grid(msh, n_along, n_thick, position, ids=None):
    """Nodes of a structured one-layer body at position(s, t), s, t in [0, 1]; `ids` (i, j, k) ->
    node already made (shared) are reused."""
    ids = dict(ids or {})
    for k in range(2):
        for j in range(n_thick + 1):
            for i in range(n_along + 1):
                if (i, j, k) not in ids:
                    x, y = position(i / n_along, j / n_thick)
                    ids[i, j, k] = msh.node(x, y, k * DEPTH)
    return ids


def cells(msh, name, ids, n_along, n_thick):
    volume = msh.group(3, name)
    for j in range(n_thick):
        for i in range(n_along):
            quad = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            msh.elements.append((5, volume, [ids[a, b, k] for k in range(2) for a, b in quad]))


def face(msh, name, ids, n_along, n_thick, where):
    group = msh.group(2, name)
    if where in ("bottom", "top"):
        j = 0 if where == "bottom" else n_thick
        for i in range(n_along):
            msh.elements.append((3, group, [ids[i, j, 0], ids[i + 1, j, 0], ids[i + 1, j, 1],
                                            ids[i, j, 1]]))
        return
    k = 0 if where == "zmin" else 1
    for j in range(n_thick):
        for i in range(n_along):
            msh.elements.append((3, group, [ids[i, j, k], ids[i + 1, j, k],
                                            ids[i + 1, j + 1, k], ids[i, j + 1, k]]))


def arc(r_outer, r_inner):
    def position(s, t):  # t = 0 on the outer arc, t = 1 on the inner one
        theta = HALF_ANGLE * (2.0 * s - 1.0)
        r = r_outer + (r_inner - r_outer) * t
        return CENTRE[0] + r * math.sin(theta), CENTRE[1] - r * math.cos(theta)
    return position


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    n_arc, n_femoral, n_x, n_tibial = map(int, sys.argv[1:5])
    msh = Msh()
    tibial = grid(msh, n_x, n_tibial,
                  lambda s, t: (TIBIAL_LENGTH * s, -THICKNESS * (1.0 - t)))
    cells(msh, "tibial", tibial, n_x, n_tibial)
    for name, where in (("bone", "bottom"), ("top", "top"), ("zmin", "zmin"), ("zmax", "zmax")):
        face(msh, f"tibial.{name}", tibial, n_x, n_tibial, where)

    femoral = grid(msh, n_arc, n_femoral, arc(R_CARTILAGE, R_CARTILAGE - THICKNESS))
    cells(msh, "femoral", femoral, n_arc, n_femoral)
    face(msh, "femoral.contact", femoral, n_arc, n_femoral, "bottom")
    face(msh, "femoral.bone", femoral, n_arc, n_femoral, "top")
    # the bone shares the cartilage's inner nodes (its outer arc)
    shared = {(i, 0, k): femoral[i, n_femoral, k] for i in range(n_arc + 1) for k in range(2)}
    femur = grid(msh, n_arc, 1, arc(R_CARTILAGE - THICKNESS, R_BONE), shared)
    cells(msh, "femur", femur, n_arc, 1)

    free = msh.group(0, "femoral.free")
    for (i, j, k), node in sorted(femoral.items()):
        if j < n_femoral:
            msh.elements.append((15, free, [node]))
    msh.write(sys.argv[5])


if __name__ == "__main__":
    main()
