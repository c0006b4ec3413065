#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the mesh of the 3-D indentation example (Gmsh 2.2 ASCII, hex8), a quarter model.

  layer     cartilage 5 x 5 x 1.5 mm (the quarter of a 10 x 10 mm layer), bottom z = 0 bonded
            to bone; in-plane cells graded towards the indenter axis (x = y = 0);
  indenter  a spherical cap of radius R = 2.5 mm over the quarter square [0, 1.5 mm]^2, one
            cell thick, its lowest point touching the layer at the origin (x = y = 0, z = 1.5).

Physical groups: volumes "layer", "indenter" (node sets of their cells as well); surfaces
"layer.top", "layer.bottom", "layer.xmin", "layer.ymin", "layer.xmax", "layer.ymax",
"indenter.surface" (the spherical face).

Usage: make_mesh.py --cells N [--layers NZ] [--grading G] [--indenter-cells M] [-o FILE]
  N   cells along each in-plane edge of the layer (default 12)
  NZ  cells through the thickness (default max(4, N / 4))
  G   size of the outermost in-plane cell over the innermost (default 4)
  M   cells along each edge of the indenter (default N / 2, at least 4)
Unknowns of the triphasic model: about 12 (N+1)^2 (NZ+1) + 2 N^2 NZ, e.g. 1.0e6 for N = 90, NZ = 8.
"""
import argparse
import math

SIDE, THICKNESS = 5.0, 1.5  # mm: the quarter layer
RADIUS, CAP_SIDE = 2.5, 1.5  # mm: the indenter sphere and the side of its quarter cap


def graded(n, length, grading):
    """n + 1 coordinates on [0, length]; cell sizes grow geometrically by `grading` overall."""
    ratio = grading ** (1.0 / (n - 1)) if n > 1 else 1.0
    sizes = [ratio**k for k in range(n)]
    total, x, points = sum(sizes), 0.0, [0.0]
    for s in sizes:
        x += s * length / total
        points.append(x)
    points[-1] = length
    return points


class Mesh:
    def __init__(self):
        self.nodes, self.hexes, self.quads, self.groups = [], [], [], []

    def group(self, dim, name):
        self.groups.append((dim, name))
        return len(self.groups)

    def block(self, name, xs, ys, zs, position):
        """A structured block of cells over the index grid xs x ys x zs (lists of parameters);
        position(x, y, z) gives the node. Returns the node ids by index (i, j, k)."""
        ids = {}
        for k, z in enumerate(zs):
            for j, y in enumerate(ys):
                for i, x in enumerate(xs):
                    self.nodes.append(position(x, y, z))
                    ids[i, j, k] = len(self.nodes)
        volume = self.group(3, name)
        for k in range(len(zs) - 1):
            for j in range(len(ys) - 1):
                for i in range(len(xs) - 1):
                    corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                    self.hexes.append(
                        (volume, [ids[a, b, c] for c in (k, k + 1) for a, b in corners]))
        return ids

    def face(self, name, ids, axis, index, n1, n2):
        """The quads of the block face where grid index `axis` equals `index` (n1 x n2 quads
        over the other two indices in order). Trifem orients them outward from their hex."""
        group = self.group(2, name)
        for b in range(n2):
            for a in range(n1):
                nodes = []
                for p, q in ((a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1)):
                    key = [p, q]
                    key.insert(axis, index)
                    nodes.append(ids[tuple(key)])
                self.quads.append((group, nodes))

    def write(self, path):
        with open(path, "w") as f:
            f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
            f.write(f"$PhysicalNames\n{len(self.groups)}\n")
            for tag, (dim, name) in enumerate(self.groups, 1):
                f.write(f'{dim} {tag} "{name}"\n')
            f.write(f"$EndPhysicalNames\n$Nodes\n{len(self.nodes)}\n")
            for i, (x, y, z) in enumerate(self.nodes, 1):
                f.write(f"{i} {x:.15g} {y:.15g} {z:.15g}\n")
            f.write(f"$EndNodes\n$Elements\n{len(self.hexes) + len(self.quads)}\n")
            tag = 0
            for kind, elements in ((5, self.hexes), (3, self.quads)):
                for group, nodes in elements:
                    tag += 1
                    f.write(f"{tag} {kind} 2 {group} {group} {' '.join(map(str, nodes))}\n")
            f.write("$EndElements\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cells", type=int, default=12)
    parser.add_argument("--layers", type=int)
    parser.add_argument("--grading", type=float, default=4.0)
    parser.add_argument("--indenter-cells", type=int)
    parser.add_argument("--full", action="store_true",
                        help="the whole 10 x 10 mm layer instead of the quarter")
    parser.add_argument("-o", "--output")
    args = parser.parse_args()
    n = args.cells
    nz = args.layers or max(4, n // 4)
    m = args.indenter_cells or max(4, n // 2)
    if n < 2 or nz < 1 or m < 1 or args.grading <= 0.0:
        parser.error("need --cells >= 2, --layers >= 1, --indenter-cells >= 1, --grading > 0")
    output = args.output or f"indentation_{n}.msh"

    mesh = Mesh()
    xy = graded(n, SIDE, args.grading)
    if args.full:  # mirrored about x = 0 and y = 0
        xy = [-x for x in reversed(xy[1:])] + xy
    zs = [THICKNESS * k / nz for k in range(nz + 1)]
    layer = mesh.block("layer", xy, xy, zs, lambda x, y, z: (x, y, z))
    nxy = len(xy) - 1
    mesh.face("layer.bottom", layer, 2, 0, nxy, nxy)
    mesh.face("layer.top", layer, 2, nz, nxy, nxy)
    mesh.face("layer.xmin", layer, 0, 0, nxy, nz)
    mesh.face("layer.xmax", layer, 0, nxy, nxy, nz)
    mesh.face("layer.ymin", layer, 1, 0, nxy, nz)
    mesh.face("layer.ymax", layer, 1, nxy, nxy, nz)

    cap = [CAP_SIDE * i / m for i in range(-m if args.full else 0, m + 1)]

    def indenter(x, y, t):  # t = 0 on the sphere, 1 on the flat top at the sphere's centre
        bottom = THICKNESS + RADIUS - math.sqrt(RADIUS**2 - x * x - y * y)
        return x, y, bottom + t * (THICKNESS + RADIUS - bottom)

    ids = mesh.block("indenter", cap, cap, [0.0, 1.0], indenter)
    mesh.face("indenter.surface", ids, 2, 0, len(cap) - 1, len(cap) - 1)
    mesh.write(output)
    print(f"{output}: {len(mesh.nodes)} nodes, {len(mesh.hexes)} hex8 cells")


if __name__ == "__main__":
    main()
