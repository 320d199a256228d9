"""Writes punch.msh (Gmsh 2.2 ASCII, quadrilaterals) for prm/punch.prm: a
flat punch above a block, no vertex shared.

  body 1 (cell tag 1), the block: [-1, 1] x [0, 0.5], 40 x 10 cells,
      bottom 10, top 11
  body 2 (cell tag 2), the punch: [-0.2, 0.2] x [0.505, 0.705], 8 x 4
      cells, bottom 20, top 21

Run: python3 punch.py (writes punch.msh beside it)."""
import os

import msh_blocks

here = os.path.dirname(os.path.abspath(__file__))
msh_blocks.write(os.path.join(here, "punch.msh"), [
    dict(x0=-1.0, x1=1.0, y0=0.0, y1=0.5, nx=40, ny=10, cells=1, bottom=10, top=11),
    dict(x0=-0.2, x1=0.2, y0=0.505, y1=0.705, nx=8, ny=4, cells=2, bottom=20, top=21),
])
