"""Rectangular blocks of quadrilaterals as a Gmsh 2.2 ASCII mesh, no vertex
shared between blocks, and any nodes and elements: the writer of stack.py,
punch.py and ring.py (and of benchmarks/loads_and_motion.py)."""


def write(file, blocks):
    """Writes blocks, each a dict with x0, x1, y0, y1, nx, ny, the cell tag
    'cells' and the boundary tags 'bottom', 'top', 'left', 'right' (0 or
    missing: none), to file."""
    nodes, elements = [], []
    for b in blocks:
        first = len(nodes) + 1
        nx, ny = b["nx"], b["ny"]
        for j in range(ny + 1):
            for i in range(nx + 1):
                nodes.append((b["x0"] + (b["x1"] - b["x0"]) * i / nx,
                              b["y0"] + (b["y1"] - b["y0"]) * j / ny))

        def node(i, j, first=first, nx=nx):
            return first + j * (nx + 1) + i

        for j in range(ny):
            for i in range(nx):
                elements.append((3, b["cells"], (node(i, j), node(i + 1, j),
                                                 node(i + 1, j + 1), node(i, j + 1))))
        for i in range(nx):
            if b.get("bottom"):
                elements.append((1, b["bottom"], (node(i, 0), node(i + 1, 0))))
            if b.get("top"):
                elements.append((1, b["top"], (node(i, ny), node(i + 1, ny))))
        for j in range(ny):
            if b.get("left"):
                elements.append((1, b["left"], (node(0, j + 1), node(0, j))))
            if b.get("right"):
                elements.append((1, b["right"], (node(nx, j), node(nx, j + 1))))
    write_mesh(file, nodes, elements)


def write_mesh(file, nodes, elements):
    """Writes nodes (x, y) and elements (Gmsh type, tag, vertex numbers
    from 1) to file, Gmsh 2.2 ASCII."""
    with open(file, "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, (x, y) in enumerate(nodes, 1):
            out.write("%d %.17g %.17g 0\n" % (k, x, y))
        out.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for k, (kind, tag, vertices) in enumerate(elements, 1):
            out.write("%d %d 2 %d %d %s\n" % (k, kind, tag, tag, " ".join(map(str, vertices))))
        out.write("$EndElements\n")
