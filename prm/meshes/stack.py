"""Writes stack.msh (Gmsh 2.2 ASCII, quadrilaterals) for prm/stack_of_three.prm:
three blocks stacked above the floor y = 0, no vertex shared.

  body 1 (cell tag 1): [0, 2] x [0, 0.4], 40 x 8 cells, bottom 10, top 11
  body 2 (cell tag 2): [0.6, 1.4] x [0.42, 0.72], 16 x 6 cells, bottom 12, top 13
  body 3 (cell tag 3): [0.85, 1.15] x [0.75, 0.95], 6 x 4 cells, bottom 14

Run: python3 stack.py (writes stack.msh beside it)."""
import os

import msh_blocks

here = os.path.dirname(os.path.abspath(__file__))
msh_blocks.write(os.path.join(here, "stack.msh"), [
    dict(x0=0.0, x1=2.0, y0=0.0, y1=0.4, nx=40, ny=8, cells=1, bottom=10, top=11),
    dict(x0=0.6, x1=1.4, y0=0.42, y1=0.72, nx=16, ny=6, cells=2, bottom=12, top=13),
    dict(x0=0.85, x1=1.15, y0=0.75, y1=0.95, nx=6, ny=4, cells=3, bottom=14),
])
