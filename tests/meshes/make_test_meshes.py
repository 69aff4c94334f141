#!/usr/bin/python3
"""Write the small Gmsh (MSH 2.2 ASCII) test meshes used by the point-location
test: a jittered unit square of triangles and a jittered unit cube of
tetrahedra. Roughly half of the cells are written with negative orientation
(clockwise triangles, left-handed tets), as Gmsh may produce them, so the
point location must not rely on a positive Jacobian. Two sliver meshes (every other
column of cells a thin strip: smallest angle 5 degrees) serve the
stability tests. Boundary faces carry
physical tags 0..2*dim-1 (x-min, x-max, y-min, ...). Deterministic."""
import itertools
import math
import random

random.seed(12345)


def write(name, nodes, cells, cell_type, faces, face_type):
    with open(name, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for i, p in enumerate(nodes):
            f.write("%d %.17g %.17g %.17g\n" % (i + 1, p[0], p[1], p[2] if len(p) > 2 else 0.0))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(cells) + len(faces)))
        k = 1
        for tag, fv in faces:
            f.write("%d %d 2 %d %d %s\n" % (k, face_type, tag, tag, " ".join(str(v + 1) for v in fv)))
            k += 1
        for cv in cells:
            f.write("%d %d 2 0 1 %s\n" % (k, cell_type, " ".join(str(v + 1) for v in cv)))
            k += 1
        f.write("$EndElements\n")


def jitter(coord, n, h):
    interior = all(0 < c < n for c in coord)
    return [c * h + (random.uniform(-0.25, 0.25) * h if interior else 0.0) for c in coord]


def square(n=8):
    h = 1.0 / n
    index = {}
    nodes = []
    for j in range(n + 1):
        for i in range(n + 1):
            index[(i, j)] = len(nodes)
            nodes.append(jitter((i, j), n, h))
    cells = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = index[(i, j)], index[(i + 1, j)], index[(i + 1, j + 1)], index[(i, j + 1)]
            tris = [(a, b, c), (a, c, d)] if random.random() < 0.5 else [(a, b, d), (b, c, d)]
            for t in tris:
                cells.append(t if random.random() < 0.5 else (t[0], t[2], t[1]))
    faces = []
    for i in range(n):
        faces.append((2, (index[(i, 0)], index[(i + 1, 0)])))
        faces.append((3, (index[(i, n)], index[(i + 1, n)])))
        faces.append((0, (index[(0, i)], index[(0, i + 1)])))
        faces.append((1, (index[(n, i)], index[(n, i + 1)])))
    write("square_triangles.msh", nodes, cells, 2, faces, 1)


def cube(n=4):
    h = 1.0 / n
    index = {}
    nodes = []
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                index[(i, j, k)] = len(nodes)
                nodes.append(jitter((i, j, k), n, h))
    cells = []
    # Kuhn split of every cube into 6 tets along the main diagonal: conforming.
    for k in range(n):
        for j in range(n):
            for i in range(n):
                for perm in itertools.permutations(range(3)):
                    p = [i, j, k]
                    verts = [index[tuple(p)]]
                    for axis in perm:
                        p[axis] += 1
                        verts.append(index[tuple(p)])
                    if random.random() < 0.5:
                        verts[2], verts[3] = verts[3], verts[2]
                    cells.append(tuple(verts))
    faces = []
    # Boundary triangles: faces of tets lying on the cube's faces.
    for cv in cells:
        for skip in range(4):
            fv = [v for m, v in enumerate(cv) if m != skip]
            for axis in range(3):
                for side, value in ((0, 0.0), (1, 1.0)):
                    if all(abs(nodes[v][axis] - value) < 1e-12 for v in fv):
                        faces.append((2 * axis + side, tuple(fv)))
    write("cube_tetrahedra.msh", nodes, cells, 4, faces, 2)


def sliver_coordinates(width, pair, leg):
    """x coordinates 0, d, P, P + d, 2P, ...: every other column of cells is
    a thin strip of width d = leg tan(5 deg), so the right triangles of
    legs d and leg in it (and the tetrahedra's faces) have a smallest angle
    of 5 degrees."""
    d = leg * math.tan(math.radians(5.0))
    xs = []
    for k in range(int(round(width / pair))):
        xs += [k * pair, k * pair + d]
    return xs + [width]


def min_angle(points):
    """Smallest interior angle (degrees) of the triangle faces of a simplex."""
    best = 180.0
    for tri in itertools.combinations(points, 3):
        for a in range(3):
            u = [tri[(a + 1) % 3][m] - tri[a][m] for m in range(len(tri[a]))]
            v = [tri[(a + 2) % 3][m] - tri[a][m] for m in range(len(tri[a]))]
            c = sum(x * y for x, y in zip(u, v)) / math.sqrt(sum(x * x for x in u) * sum(y * y for y in v))
            best = min(best, math.degrees(math.acos(max(-1.0, min(1.0, c)))))
    return best


def sliver_square(width=1.0, height=0.5, pair=0.1, spacing=0.05):
    xs = sliver_coordinates(width, pair, spacing)
    ny = int(round(height / spacing))
    index = {}
    nodes = []
    for j in range(ny + 1):
        for i, x in enumerate(xs):
            index[(i, j)] = len(nodes)
            nodes.append((x, j * spacing))
    cells = []
    for j in range(ny):
        for i in range(len(xs) - 1):
            a, b, c, d = index[(i, j)], index[(i + 1, j)], index[(i + 1, j + 1)], index[(i, j + 1)]
            cells += [(a, b, c), (a, c, d)]
    faces = []
    for i in range(len(xs) - 1):
        faces.append((2, (index[(i, 0)], index[(i + 1, 0)])))
        faces.append((3, (index[(i, ny)], index[(i + 1, ny)])))
    for j in range(ny):
        faces.append((0, (index[(0, j)], index[(0, j + 1)])))
        faces.append((1, (index[(len(xs) - 1, j)], index[(len(xs) - 1, j + 1)])))
    angle = min(min_angle([nodes[v] for v in cv]) for cv in cells)
    print("sliver_triangles.msh: %d triangles, smallest angle %.2f deg" % (len(cells), angle))
    write("sliver_triangles.msh", nodes, cells, 2, faces, 1)


def sliver_cube(width=0.6, height=0.3, depth=0.1, pair=0.1, spacing=0.05):
    # The longest leg across the thin strip is a face diagonal.
    xs = sliver_coordinates(width, pair, spacing * math.sqrt(2.0))
    ny, nz = int(round(height / spacing)), int(round(depth / spacing))
    index = {}
    nodes = []
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i, x in enumerate(xs):
                index[(i, j, k)] = len(nodes)
                nodes.append((x, j * spacing, k * spacing))
    cells = []
    for k in range(nz):
        for j in range(ny):
            for i in range(len(xs) - 1):
                for perm in itertools.permutations(range(3)):
                    p = [i, j, k]
                    verts = [index[tuple(p)]]
                    for axis in perm:
                        p[axis] += 1
                        verts.append(index[tuple(p)])
                    cells.append(tuple(verts))
    upper = (width, height, depth)
    faces = []
    for cv in cells:
        for skip in range(4):
            fv = [v for m, v in enumerate(cv) if m != skip]
            for axis in range(3):
                for side, value in ((0, 0.0), (1, upper[axis])):
                    if all(abs(nodes[v][axis] - value) < 1e-12 for v in fv):
                        faces.append((2 * axis + side, tuple(fv)))
    angle = min(min_angle([nodes[v] for v in cv]) for cv in cells)
    print("sliver_tetrahedra.msh: %d tetrahedra, smallest face angle %.2f deg" % (len(cells), angle))
    write("sliver_tetrahedra.msh", nodes, cells, 4, faces, 2)


square()
cube()
sliver_square()
sliver_cube()
