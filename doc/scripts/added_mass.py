#!/usr/bin/env python3
"""Potential-flow added mass of a 2D section moving vertically, by a panel method.

    /usr/bin/python3 doc/scripts/added_mass.py [--panels N] [--tank X0 X1 FLOOR SURFACE]

Prints, per unit length, the added mass m_a of the geocontainers' two
sections (prm/geocontainer_ellipse.prm and prm/geocontainer_polygon.prm)
moving along y, and the initial acceleration of the bag released at rest in
still water,

    a_0 = (m_bag - rho V) g / (m_bag + m_a),

with m_bag the sand (1900 kg/m^3) plus the textile (0.3 kg/m^2 times the
circumference), V the enclosed area and rho = 1000 kg/m^3.

The method (Hess & Smith): constant-strength sources on straight panels,
the normal velocity U.n on the body, m_a = -rho oint phi n_y ds (the
fluid's kinetic energy is m_a U^2 / 2). It is checked against the closed
forms for a circle (rho pi R^2) and an ellipse moving along its minor axis
(rho pi a^2, a the semi-axis across the motion: Newman, Marine
Hydrodynamics, 1977, section 4.13), which it prints with their errors.

With --tank the body sits in a tank (side walls x = X0 and X1, floor,
free surface at y = SURFACE) and the first images are added: the walls
and floor by mirror images of the same sign (no flow through them), the
free surface by one of opposite sign (phi = 0 there: the surface's
impulsive-start condition, right for the initial acceleration).
"""
import math
import sys

import numpy as np


def panel_influence(points, a, b):
    """Potential and velocity at points (n, 2) of a unit source panel a-b."""
    t = (b - a) / np.linalg.norm(b - a)
    n = np.array([t[1], -t[0]])
    h = 0.5 * np.linalg.norm(b - a)
    d = points - 0.5 * (a + b)
    x = d @ t
    y = d @ n
    r1 = (x + h) ** 2 + y ** 2
    r2 = (x - h) ** 2 + y ** 2
    th1 = np.arctan2(y, x + h)
    th2 = np.arctan2(y, x - h)
    with np.errstate(divide="ignore", invalid="ignore"):
        l1 = np.where(r1 > 0, np.log(r1), 0.)
        l2 = np.where(r2 > 0, np.log(r2), 0.)
    phi = (0.5 * (x + h) * l1 - 0.5 * (x - h) * l2 - 2 * h
           + y * (th2 - th1)) / (2 * math.pi)
    u = 0.5 * (l1 - l2) / (2 * math.pi)
    v = (th2 - th1) / (2 * math.pi)
    return phi, np.outer(u, t) + np.outer(v, n)


def added_mass(vertices, images=(), rho=1000.):
    """m_yy of the closed counter-clockwise polygon `vertices` (n, 2).

    images: (sign, transform) pairs, transform mapping a point array to its
    mirror image; each mirrored body carries the sources times sign.
    """
    v = np.asarray(vertices, float)
    a, b = v, np.roll(v, -1, axis=0)
    mid = 0.5 * (a + b)
    length = np.linalg.norm(b - a, axis=1)
    normal = np.stack([(b - a)[:, 1], -(b - a)[:, 0]], axis=1) / length[:, None]
    m = len(v)
    A = np.zeros((m, m))
    P = np.zeros((m, m))
    for j in range(m):
        phi, vel = panel_influence(mid, a[j], b[j])
        # On its own panel, the fluid side's limit: +1/2 normal velocity.
        vel[j] = 0.5 * normal[j]
        A[:, j] = np.sum(vel * normal, axis=1)
        P[:, j] = phi
        for sign, mirror in images:
            pa, pb = mirror(a[j:j + 1])[0], mirror(b[j:j + 1])[0]
            # A mirror reverses the traversal: keep the panel's own ends.
            phi, vel = panel_influence(mid, pa, pb)
            A[:, j] += sign * np.sum(vel * normal, axis=1)
            P[:, j] += sign * phi
    sigma = np.linalg.solve(A, normal[:, 1])
    phi = P @ sigma
    return -rho * np.sum(phi * normal[:, 1] * length)


def ellipse(centre, a, b, n):
    s = 2 * math.pi * (np.arange(n) + 0.5) / n
    return np.stack([centre[0] + a * np.cos(s), centre[1] + b * np.sin(s)],
                    axis=1)


def refine(vertices, n):
    """The polygon with about n panels of equal length along its sides."""
    v = np.asarray(vertices, float)
    w = np.roll(v, -1, axis=0)
    perimeter = np.sum(np.linalg.norm(w - v, axis=1))
    out = []
    for p, q in zip(v, w):
        k = max(1, round(n * np.linalg.norm(q - p) / perimeter))
        for i in range(k):
            out.append(p + (q - p) * i / k)
    return np.array(out)


def ellipse_perimeter(a, b):
    h = ((a - b) / (a + b)) ** 2
    return math.pi * (a + b) * (1 + 3 * h / (10 + math.sqrt(4 - 3 * h)))


def ellipse_axes(circumference, area):
    """Semi-axes a >= b of the ellipse of that circumference and area
    (Ramanujan's perimeter, as the membrane's ellipse_axes())."""
    ab = area / math.pi
    lo, hi = math.sqrt(ab) * (1 + 1e-12), 10 * circumference
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if ellipse_perimeter(mid, ab / mid) > circumference:
            hi = mid
        else:
            lo = mid
    a = 0.5 * (lo + hi)
    return a, ab / a


# The shipped sections (prm/geocontainer_ellipse.prm, _polygon.prm): the
# circumference and enclosed area, and the pentagon's vertices,
# counter-clockwise.
CIRCUMFERENCE, AREA = 0.62, 0.0202429
POLYGON = [(1.0, 0.8), (1.13564, 0.88007), (1.09495, 0.92076),
           (0.90505, 0.92076), (0.86436, 0.88007)]


def polygon_area(vertices):
    """The area of a closed polygon (shoelace formula)."""
    p = np.asarray(vertices, float)
    return 0.5 * abs(np.sum(p[:, 0] * np.roll(p[:, 1], -1)
                            - np.roll(p[:, 0], -1) * p[:, 1]))


def main():
    args = sys.argv[1:]
    panels = 2000
    tank = None
    if "--panels" in args:
        i = args.index("--panels")
        panels = int(args[i + 1])
        del args[i:i + 2]
    if "--tank" in args:
        i = args.index("--tank")
        tank = [float(x) for x in args[i + 1:i + 5]]
        del args[i:i + 5]
    if args:
        sys.exit(__doc__)

    rho, g = 1000., 9.81
    print(f"{'check':40s} {'panel':>10s} {'exact':>10s} {'error':>9s}")
    for name, (a, b) in [("circle R = 0.1 m", (0.1, 0.1)),
                         ("ellipse a = 0.14, b = 0.046 m", (0.14, 0.046))]:
        m = added_mass(ellipse((0, 0), a, b, panels))
        exact = rho * math.pi * a * a
        print(f"{name:40s} {m:10.3f} {exact:10.3f} {m / exact - 1:+9.2%}")

    circumference, area = CIRCUMFERENCE, AREA
    a, b = ellipse_axes(circumference, area)
    sections = [("ellipse", ellipse((1.0, 0.8 + b), a, b, panels), area),
                ("polygon", refine(POLYGON, panels), polygon_area(POLYGON))]
    images = ()
    if tank:
        x0, x1, floor, surface = tank
        images = (
            (+1, lambda q: np.stack([2 * x0 - q[:, 0], q[:, 1]], axis=1)),
            (+1, lambda q: np.stack([2 * x1 - q[:, 0], q[:, 1]], axis=1)),
            (+1, lambda q: np.stack([q[:, 0], 2 * floor - q[:, 1]], axis=1)),
            (-1, lambda q: np.stack([q[:, 0], 2 * surface - q[:, 1]], axis=1)),
        )
    print(f"\nellipse semi-axes a = {a:.5f} m, b = {b:.5f} m "
          f"(circumference {circumference} m, area {area} m^2)")
    print(f"{'section':10s} {'m_bag':>8s} {'rho V':>8s} {'m_a':>8s} "
          f"{'m_a/rho V':>9s} {'a_0':>7s} {'a_0 without m_a':>16s}"
          + ("  (tank images)" if tank else "  (unbounded water)"))
    for name, shape, section_area in sections:
        if tank:
            # Released at rest 0.1 m higher than shipped, under water.
            shape = shape + np.array([0, 0.1])
        m_a = added_mass(shape, images)
        m_bag = 1900 * section_area + 0.3 * circumference
        displaced = rho * section_area
        a0 = (m_bag - displaced) * g / (m_bag + m_a)
        a_free = (m_bag - displaced) * g / m_bag
        print(f"{name:10s} {m_bag:8.2f} {displaced:8.2f} {m_a:8.2f} "
              f"{m_a / displaced:9.3f} {a0:7.3f} {a_free:16.3f}")


if __name__ == "__main__":
    main()
