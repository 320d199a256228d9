"""Writes stack.msh (Gmsh 2.2 ASCII, quadrilaterals) for prm/stack_of_three.prm:
three blocks stacked above the floor y = 0, no vertex shared.

  body 1 (cell tag 1): [0, 2] x [0, 0.4], 40 x 8 cells, bottom 10, top 11
  body 2 (cell tag 2): [0.6, 1.4] x [0.42, 0.72], 16 x 6 cells, bottom 12, top 13
  body 3 (cell tag 3): [0.85, 1.15] x [0.75, 0.95], 6 x 4 cells, bottom 14

Run: python3 stack.py (writes stack.msh beside it)."""
import os

BLOCKS = [  # x0, x1, y0, y1, nx, ny, cell tag, bottom tag, top tag
    (0.0, 2.0, 0.0, 0.4, 40, 8, 1, 10, 11),
    (0.6, 1.4, 0.42, 0.72, 16, 6, 2, 12, 13),
    (0.85, 1.15, 0.75, 0.95, 6, 4, 3, 14, 0),
]

nodes, elements = [], []
for x0, x1, y0, y1, nx, ny, cell_tag, bottom, top in BLOCKS:
    first = len(nodes) + 1
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny))

    def node(i, j):
        return first + j * (nx + 1) + i

    for j in range(ny):
        for i in range(nx):
            elements.append((3, cell_tag, (node(i, j), node(i + 1, j), node(i + 1, j + 1),
                                           node(i, j + 1))))
    for i in range(nx):
        if bottom:
            elements.append((1, bottom, (node(i, 0), node(i + 1, 0))))
        if top:
            elements.append((1, top, (node(i, ny), node(i + 1, ny))))

with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "stack.msh"), "w") as out:
    out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
    for k, (x, y) in enumerate(nodes, 1):
        out.write("%d %.17g %.17g 0\n" % (k, x, y))
    out.write("$EndNodes\n$Elements\n%d\n" % len(elements))
    for k, (kind, tag, vertices) in enumerate(elements, 1):
        out.write("%d %d 2 %d %d %s\n" % (k, kind, tag, tag, " ".join(map(str, vertices))))
    out.write("$EndElements\n")
