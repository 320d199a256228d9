"""Writes ring.msh (Gmsh 2.2 ASCII, quadrilaterals) for
prm/ring_in_groove.prm: a ring of radii 0.3 and 0.4 m about (0, 0.6), 48
cells around and 3 across, cell tag 1, its outer boundary tag 11.

Run: python3 ring.py (writes ring.msh beside it)."""
import math
import os

import msh_blocks

R1, R2, CENTRE_Y, AROUND, ACROSS = 0.3, 0.4, 0.6, 48, 3

nodes, elements = [], []
for j in range(ACROSS + 1):
    r = R1 + (R2 - R1) * j / ACROSS
    for i in range(AROUND):
        a = 2 * math.pi * i / AROUND
        nodes.append((r * math.cos(a), CENTRE_Y + r * math.sin(a)))


def node(i, j):
    return j * AROUND + i % AROUND + 1


for j in range(ACROSS):
    for i in range(AROUND):
        elements.append((3, 1, (node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))))
for i in range(AROUND):
    elements.append((1, 11, (node(i, ACROSS), node(i + 1, ACROSS))))

msh_blocks.write_mesh(os.path.join(os.path.dirname(os.path.abspath(__file__)), "ring.msh"),
                      nodes, elements)
