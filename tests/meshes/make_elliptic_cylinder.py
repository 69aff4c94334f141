#!/usr/bin/python3
"""Second-order Gmsh surface of an elliptic cylinder (a geotube slab).

Usage: make_elliptic_cylinder.py CIRCUMFERENCE AREA X_LOW Y_LOW Z0 Z1 N NZ
       FORMAT [--first-order] > file.msh

The ellipse of the given circumference and enclosed area has its lowest
point at (X_LOW, Y_LOW); it is extruded from z = Z0 to Z1. N cells around
(equal arc length, counter-clockwise from the lowest point, as fsgmpm's
Membrane/Shape = ellipse), NZ along z; each quad is split into two triangles
with outward normals. Second order (Gmsh type 9, 6-node triangles): every
edge node lies ON the cylinder, at the middle arc length and middle z of its
edge, as Gmsh places the nodes of a curved surface. FORMAT is 2.2 or 4.1
(ASCII). Debian's python3 only. The shipped meshes (the geotube A5.56 of
prm/geotube_A5.56_3d.prm over the 16 cm slab):
  make_elliptic_cylinder.py 9.2 5.56 3 0 0 0.16 40 1 4.1 \
      > tests/meshes/geotube_A5.56_p2.msh
  make_elliptic_cylinder.py 9.2 5.56 3 0 0 0.16 8 1 2.2 \
      > tests/meshes/geotube_A5.56_p2_coarse_v2.msh
  make_elliptic_cylinder.py 9.2 5.56 3 0 0 0.16 80 2 2.2 --first-order \
      > tests/meshes/geotube_A5.56_p1.msh
"""
import math
import sys


def perimeter(a, b, m=20000):
    s, prev = 0.0, (0.0, -b)
    for i in range(1, m + 1):
        t = 2 * math.pi * i / m
        p = (a * math.sin(t), -b * math.cos(t))
        s += math.dist(p, prev)
        prev = p
    return s


def axes(L, A):
    """Semi-axes a >= b of the ellipse with perimeter L and area A."""
    lo, hi = math.sqrt(A / math.pi), L / 4  # circle .. flat
    for _ in range(100):
        a = 0.5 * (lo + hi)
        if perimeter(a, A / (math.pi * a)) < L:
            lo = a
        else:
            hi = a
    a = 0.5 * (lo + hi)
    return a, A / (math.pi * a)


def main(argv):
    if len(argv) < 9:
        sys.exit(__doc__)
    L, A, x0, y0, z0, z1 = (float(v) for v in argv[:6])
    n, nz, fmt = int(argv[6]), int(argv[7]), argv[8]
    second = "--first-order" not in argv
    a, b = axes(L, A)
    # Arc length table of the parameter t, inverted for equal spacing.
    m = 200000
    at = lambda t: (x0 + a * math.sin(t), y0 + b - b * math.cos(t))
    s = [0.0]
    for i in range(1, m + 1):
        s.append(s[-1] + math.dist(at(2 * math.pi * i / m),
                                   at(2 * math.pi * (i - 1) / m)))

    def point(f):
        """The point at fraction f of the circumference."""
        target = s[-1] * (f % 1.0)
        lo, hi = 0, m
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if s[mid] <= target:
                lo = mid
            else:
                hi = mid
        g = (target - s[lo]) / (s[lo + 1] - s[lo]) if hi > lo else 0
        return at(2 * math.pi * (lo + g) / m)

    # Nodes on a (2 n) x (2 nz + 1) lattice of (arc, z) half steps; the
    # corners use the even ones.
    k = 2 if second else 1
    nodes, tag = [], {}
    for j in range(k * nz + 1):
        z = z0 + (z1 - z0) * j / (k * nz)
        for i in range(k * n):
            x, y = point(i / (k * n))
            tag[(i, j)] = len(nodes) + 1
            nodes.append((x, y, z))
    T = lambda i, j: tag[(i % (k * n), j)]
    triangles = []
    for j in range(nz):
        for i in range(n):
            I, J = k * i, k * j
            a_, b_, c_, d_ = (I, J), (I + k, J), (I, J + k), (I + k, J + k)
            for tri in ((a_, b_, d_), (a_, d_, c_)):
                corners = [T(*p) for p in tri]
                if second:
                    mids = [T((p[0] + q[0]) // 2, (p[1] + q[1]) // 2)
                            for p, q in zip(tri, tri[1:] + tri[:1])]
                    corners += mids
                triangles.append(corners)
    etype = 9 if second else 2
    out = sys.stdout
    out.write(f"$MeshFormat\n{fmt} 0 8\n$EndMeshFormat\n")
    if fmt == "2.2":
        out.write(f"$Nodes\n{len(nodes)}\n")
        for t, (x, y, z) in enumerate(nodes, 1):
            out.write(f"{t} {x!r} {y!r} {z!r}\n")
        out.write(f"$EndNodes\n$Elements\n{len(triangles)}\n")
        for e, tri in enumerate(triangles, 1):
            out.write(f"{e} {etype} 2 1 1 " + " ".join(map(str, tri)) + "\n")
        out.write("$EndElements\n")
    elif fmt == "4.1":
        out.write(f"$Nodes\n1 {len(nodes)} 1 {len(nodes)}\n2 1 0 {len(nodes)}\n")
        for t in range(1, len(nodes) + 1):
            out.write(f"{t}\n")
        for x, y, z in nodes:
            out.write(f"{x!r} {y!r} {z!r}\n")
        out.write(f"$EndNodes\n$Elements\n1 {len(triangles)} 1 {len(triangles)}\n"
                  f"2 1 {etype} {len(triangles)}\n")
        for e, tri in enumerate(triangles, 1):
            out.write(f"{e} " + " ".join(map(str, tri)) + "\n")
        out.write("$EndElements\n")
    else:
        sys.exit("FORMAT must be 2.2 or 4.1")


if __name__ == "__main__":
    main(sys.argv[1:])
