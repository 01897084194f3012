#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Outlines for regions of one's own shape (-region_<r>_polygon_file, -region_<r>_surface; src/scene/outline.c).

usage:
  scripts/outline.py ogive --radius R --crh PSI --shank L [--tip Z] [--n N] [--profile FILE] [--stl FILE] [--segments M]
      a tangent-ogive-nosed projectile of radius R [cm], ogive radius PSI calibres (rho = 2 R PSI), shank L [cm], its
      tip at z = Z pointing down -z: the (r, z) profile as a polygon file (N points along the nose) for r-z scenes,
      and the surface of revolution (M segments around) as a binary STL for 3D scenes, its axis along z through
      x = y = 0. Prints the volume of each: the profile's revolved volume per radian (Pappus) and the mesh's.
  scripts/outline.py prism --polygon X1,Y1,X2,Y2,... --depth W0,W1 [--turn DEG] --stl FILE
      a convex polygon in (x, y) extruded along z from W0 to W1, then turned by DEG about the y axis
      (x' = x cos DEG + z sin DEG, z' = z cos DEG - x sin DEG): a 3D body whose faces cross the grid's cells (the
      rigid wedge and the block of inputs/wedge_3d.opts).
  scripts/outline.py torus --R R --a A [--center X,Y,Z] [--n N] [--stl FILE]
      a torus (tube radius A about a circle of radius R in the xy plane): a non-convex closed surface.

The exact volumes that a region's mass is compared with (tests/tools/outlines.py) come from these functions.
"""
import argparse
import math
import struct

import numpy as np


def ogive_profile(R, crh, shank, tip=0.0, n=24):
    """(r, z) vertices of the closed profile, counter-clockwise: the tip on the axis, the nose, the shank, the back."""
    rho = 2.0 * R * crh
    L = math.sqrt(rho * rho - (rho - R) ** 2)
    pts = [(0.0, tip)]
    for i in range(1, n + 1):
        s = L * i / n  # distance from the tip along the axis
        pts.append((math.sqrt(max(rho * rho - (L - s) ** 2, 0.0)) + R - rho, tip + s))
    pts.append((R, tip + L + shank))
    pts.append((0.0, tip + L + shank))
    return pts


def inside_polygon(poly, x, y):
    """Whether the points (x, y) (arrays) lie inside the polygon poly ((n, 2) vertices in order, the last joining the
    first): the even-odd rule with a ray along +x, as src/scene/outline.c decides -region_<r>_polygon."""
    poly = np.asarray(poly, float)
    inside = np.zeros(np.shape(x), bool)
    for (xa, ya), (xb, yb) in zip(poly, np.roll(poly, -1, axis=0)):
        cross = (ya > y) != (yb > y)
        xc = xa + (y - ya) * (xb - xa) / (yb - ya if yb != ya else 1.0)
        inside ^= cross & (x < xc)
    return inside


def profile_volume(pts):
    """Revolved volume per radian of the polygon (r, z) about r = 0: integral of r dA (shoelace form)."""
    v = 0.0
    for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]):
        c = x1 * y0 - x0 * y1
        v += c * (x0 + x1) / 6.0
    return abs(v)


def revolve(pts, m=48):
    """Triangles of the surface of revolution of a profile whose first and last vertices lie on the axis."""
    rings = []
    for r, z in pts:
        if r == 0.0:
            rings.append([(0.0, 0.0, z)])
        else:
            rings.append([(r * math.cos(2 * math.pi * j / m), r * math.sin(2 * math.pi * j / m), z) for j in range(m)])
    tris = []
    for a, b in zip(rings, rings[1:] + rings[:1]):
        if len(a) == 1 and len(b) == 1:
            continue  # along the axis: no surface
        for j in range(m):
            j1 = (j + 1) % m
            if len(a) == 1:
                tris.append((a[0], b[j1], b[j]))
            elif len(b) == 1:
                tris.append((a[j], a[j1], b[0]))
            else:
                tris.append((a[j], a[j1], b[j1]))
                tris.append((a[j], b[j1], b[j]))
    return np.array(tris)


def torus(R, a, center=(0.0, 0.0, 0.0), n=48):
    """Triangles of a torus: n x n/2 quads."""
    nu, nv = n, max(8, n // 2)
    P = lambda i, j: (center[0] + (R + a * math.cos(2 * math.pi * j / nv)) * math.cos(2 * math.pi * i / nu),
                      center[1] + (R + a * math.cos(2 * math.pi * j / nv)) * math.sin(2 * math.pi * i / nu),
                      center[2] + a * math.sin(2 * math.pi * j / nv))
    tris = []
    for i in range(nu):
        for j in range(nv):
            p00, p10, p11, p01 = P(i, j), P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)
            tris.append((p00, p10, p11))
            tris.append((p00, p11, p01))
    return np.array(tris)


def prism(poly, w0, w1, turn=0.0):
    """Triangles of the convex polygon poly ((n, 2) vertices in (x, y), in order) extruded along z from w0 to w1 and
    turned by turn degrees about the y axis: two fans for the caps, two triangles per side."""
    poly = np.asarray(poly, float)
    e = np.roll(poly, -1, axis=0) - poly
    cross = e[:, 0] * np.roll(e, -1, axis=0)[:, 1] - e[:, 1] * np.roll(e, -1, axis=0)[:, 0]
    if not (np.all(cross > 0) or np.all(cross < 0)):
        raise SystemExit("prism: the polygon must be convex (its caps are fans)")
    c, s = math.cos(math.radians(turn)), math.sin(math.radians(turn))
    P = lambda q, w: (q[0] * c + w * s, q[1], w * c - q[0] * s)
    tris = []
    for i in range(1, len(poly) - 1):
        tris.append((P(poly[0], w0), P(poly[i + 1], w0), P(poly[i], w0)))
        tris.append((P(poly[0], w1), P(poly[i], w1), P(poly[i + 1], w1)))
    for i in range(len(poly)):
        a, b = poly[i], poly[(i + 1) % len(poly)]
        tris.append((P(a, w0), P(b, w0), P(b, w1)))
        tris.append((P(a, w0), P(b, w1), P(a, w1)))
    return np.array(tris)


def mesh_volume(tris):
    """Enclosed volume of a closed triangle mesh: |sum x0 . (x1 x x2)| / 6."""
    return abs(np.einsum("ij,ij->i", tris[:, 0], np.cross(tris[:, 1], tris[:, 2])).sum()) / 6.0


def write_stl(path, tris):
    """Binary STL."""
    with open(path, "wb") as f:
        f.write(b"petmpm scripts/outline.py".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            nrm = np.cross(t[1] - t[0], t[2] - t[0])
            ln = np.linalg.norm(nrm)
            nrm = nrm / ln if ln > 0 else nrm
            f.write(struct.pack("<12fH", *nrm, *t[0], *t[1], *t[2], 0))


def write_profile(path, pts):
    with open(path, "w") as f:
        f.write("# r z [cm]: a profile for -region_<r>_polygon_file (scripts/outline.py)\n")
        for r, z in pts:
            f.write(f"{r:.9g} {z:.9g}\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="kind", required=True)
    o = sub.add_parser("ogive")
    o.add_argument("--radius", type=float, required=True)
    o.add_argument("--crh", type=float, required=True)
    o.add_argument("--shank", type=float, required=True)
    o.add_argument("--tip", type=float, default=0.0)
    o.add_argument("--n", type=int, default=24)
    o.add_argument("--segments", type=int, default=48)
    o.add_argument("--profile")
    o.add_argument("--stl")
    p = sub.add_parser("prism")
    p.add_argument("--polygon", required=True)
    p.add_argument("--depth", required=True)
    p.add_argument("--turn", type=float, default=0.0)
    p.add_argument("--stl", required=True)
    t = sub.add_parser("torus")
    t.add_argument("--R", type=float, required=True)
    t.add_argument("--a", type=float, required=True)
    t.add_argument("--center", default="0,0,0")
    t.add_argument("--n", type=int, default=48)
    t.add_argument("--stl", required=True)
    args = ap.parse_args()
    if args.kind == "ogive":
        pts = ogive_profile(args.radius, args.crh, args.shank, args.tip, args.n)
        print(f"profile: {len(pts)} vertices, revolved volume {profile_volume(pts):.9g} cm^3 per radian")
        if args.profile:
            write_profile(args.profile, pts)
        if args.stl:
            tris = revolve(pts, args.segments)
            write_stl(args.stl, tris)
            print(f"surface: {len(tris)} triangles, volume {mesh_volume(tris):.9g} cm^3")
    elif args.kind == "prism":
        xy = [float(v) for v in args.polygon.split(",")]
        w0, w1 = (float(v) for v in args.depth.split(","))
        tris = prism(np.reshape(xy, (-1, 2)), w0, w1, args.turn)
        write_stl(args.stl, tris)
        print(f"surface: {len(tris)} triangles, volume {mesh_volume(tris):.9g} cm^3")
    else:
        tris = torus(args.R, args.a, tuple(float(c) for c in args.center.split(",")), args.n)
        write_stl(args.stl, tris)
        print(f"surface: {len(tris)} triangles, volume {mesh_volume(tris):.9g} cm^3")


if __name__ == "__main__":
    main()
