"""Writes hertz_disc.msh (Gmsh 2.2 ASCII, quadrilaterals) for
prm/hertz_gmsh.prm: the half model (x >= 0) of a cylinder of radius 1 m
about (0, 1) on a block, as the built-in Hertz scene meshes it.

- The quarter disc x >= 0, y <= 1 in three cells (cell tag 1): its arc
  (two coarse faces of 45 degrees each) tag 11, its flat top y = 1 tag 12,
  its side on the symmetry plane x = 0 tag 13. The arc's lowest point
  touches the block at the origin.
- The block [0, 5 pi/4] x [-4, 0] in 5 x 5 cells (cell tag 2): its top
  tag 21, bottom tag 22, side on the symmetry plane tag 23. Its columns are
  pi/4 wide, the length of the disc's coarse faces along the arc, so that
  refined alike the block's top nodes lie under the disc's surface nodes
  near the contact (the built-in scene's 'Block mesh = matched').

Run: python3 hertz_disc.py (writes hertz_disc.msh beside it)."""
import math
import os

import msh_blocks

s = math.sqrt(0.5)
# the quarter disc: centre, its axis down, the inner corner, the arc
nodes = [(0, 1), (0, 0.5), (0, 0), (0.5, 1), (1, 1), (0.5, 0.5), (s, 1 - s)]
elements = [(3, 1, (1, 2, 6, 4)), (3, 1, (2, 3, 7, 6)), (3, 1, (6, 7, 5, 4)),
            (1, 11, (3, 7)), (1, 11, (7, 5)),
            (1, 12, (1, 4)), (1, 12, (4, 5)),
            (1, 13, (2, 1)), (1, 13, (3, 2))]
# the block, numbered after the disc
NX, NY, WIDTH, DEPTH = 5, 5, 5 * math.pi / 4, 4.0
first = len(nodes) + 1
for j in range(NY + 1):
    for i in range(NX + 1):
        nodes.append((WIDTH * i / NX, -DEPTH + DEPTH * j / NY))


def node(i, j):
    return first + j * (NX + 1) + i


for j in range(NY):
    for i in range(NX):
        elements.append((3, 2, (node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))))
for i in range(NX):
    elements.append((1, 21, (node(i, NY), node(i + 1, NY))))
    elements.append((1, 22, (node(i, 0), node(i + 1, 0))))
for j in range(NY):
    elements.append((1, 23, (node(0, j + 1), node(0, j))))

msh_blocks.write_mesh(os.path.join(os.path.dirname(os.path.abspath(__file__)), "hertz_disc.msh"),
                      nodes, elements)
