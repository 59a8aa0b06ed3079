#!/usr/bin/env python3
"""Independent reference for the rattleback's per-step contact geometry
(host-tests/rattleback.rs against contensou::scenes::rattleback::Rattleback::geometry).

Independent of the crate's closed form (support point + second fundamental form): mpmath at
dps 40,
  1. the body: Kane & Levinson's ellipsoid a = (0.2, 0.03, 0.02) m, G at O - 0.01 m e3, the
     principal axes of inertia turned by delta = atan(2D/(A-B))/2 about e3 from the curvature
     axes (A, B, D = 2e-4, 1.6e-3, -2e-5 kg m^2);
  2. an attitude q (body = principal frame -> world, rotation matrix from the quaternion
     formula) and G at height zG;
  3. the lowest point: minimise the world height over the lower half of the ellipsoid,
     parametrised as a graph (a1 p, a2 r, -a3 sqrt(1 - p^2 - r^2)) in curvature coordinates,
     by Newton on the numerical gradient (mp.findroot of mp.diff, over the plane mapped onto the disk);
  4. the curvatures: the lower sheet as a height function f(x, y) over the world floor (for
     each (x, y) the surface point found by mp.findroot), its Hessian by mp.diff at the lowest
     point; P <= Q the eigenvalues of Hessian/2, the major axis the eigenvector of P.

Output tools/data/rattleback_geometry.csv, columns
  qw,qx,qy,qz,zG,h,px,py,P,Q,c2,s2
with h = -(world height of the lowest point), (px, py) the lowest point minus G (world
x, y), and (c2, s2) = (cos 2phi, sin 2phi) of the major axis angle phi from world x (the axis
is a line: 2phi is what is defined).

Run:  python3 tools/gen_rattleback_geometry.py
"""
import mpmath as mp

from data_csv import write_rows

mp.mp.dps = 40

A1, A2, A3 = mp.mpf("0.2"), mp.mpf("0.03"), mp.mpf("0.02")
EPS = mp.mpf("0.01")
IA, IB, ID = mp.mpf("2e-4"), mp.mpf("1.6e-3"), mp.mpf("-2e-5")
DELTA = mp.atan(2 * ID / (IA - IB)) / 2


def rot(q):
    w, x, y, z = q
    n = mp.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    return mp.matrix([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def world_point(R, zg, p, r):
    """World position of the surface point (p, r) of the lower sheet."""
    xc = mp.matrix([A1 * p, A2 * r, -A3 * mp.sqrt(1 - p * p - r * r)])
    c, s = mp.cos(DELTA), mp.sin(DELTA)
    # curvature -> principal (body) coordinates: R_z(-delta); O = G + EPS e3
    xb = mp.matrix([c * xc[0] + s * xc[1], -s * xc[0] + c * xc[1], xc[2] + EPS])
    xw = R * xb
    return xw[0], xw[1], xw[2] + zg


def geometry(q, zg):
    R = rot(q)
    height = lambda p, r: world_point(R, zg, p, r)[2]
    # The lowest point, searched over the whole plane (u, v) mapped onto the open unit disk
    # (p, r) = (u, v)/√(1 + u² + v²), on which the lower sheet is defined: a stationary point in
    # (u, v) is one in (p, r), and a Newton step can no longer leave the disk (mpmath ≥ 1.4's
    # undamped steps did on the large tilts).
    disk = lambda u, v: (u / mp.sqrt(1 + u * u + v * v), v / mp.sqrt(1 + u * u + v * v))
    lifted = lambda u, v: height(*disk(u, v))
    grad = lambda u, v: (mp.diff(lifted, (u, v), (1, 0)), mp.diff(lifted, (u, v), (0, 1)))
    p0, r0 = disk(*mp.findroot(grad, (mp.mpf(0), mp.mpf(0))))
    x0, y0, z0 = world_point(R, zg, p0, r0)

    def f(x, y):
        sol = mp.findroot(
            lambda p, r: (world_point(R, zg, p, r)[0] - x, world_point(R, zg, p, r)[1] - y),
            (p0, r0),
        )
        return world_point(R, zg, sol[0], sol[1])[2]

    fxx = mp.diff(f, (x0, y0), (2, 0))
    fyy = mp.diff(f, (x0, y0), (0, 2))
    fxy = mp.diff(f, (x0, y0), (1, 1))
    mxx, myy, mxy = fxx / 2, fyy / 2, fxy / 2
    d = (mxx - myy) / 2
    rr = mp.sqrt(d * d + mxy * mxy)
    P, Q = (mxx + myy) / 2 - rr, (mxx + myy) / 2 + rr
    # eigenvector of P: angle phi with cos 2phi = -d/rr, sin 2phi = -mxy/rr
    return -z0, x0, y0, P, Q, -d / rr, -mxy / rr


def quat(axis_angles):
    q = mp.matrix([1, 0, 0, 0])
    for ax, ang in axis_angles:
        h = mp.mpf(ang) / 2
        e = [mp.cos(h), 0, 0, 0]
        e[1 + "xyz".index(ax)] = mp.sin(h)
        a, b = q, e
        q = mp.matrix([
            a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
        ])
    return [q[i] for i in range(4)]


CASES = [
    # (rotation sequence, zG): rest, small rock, larger rock, yawed, big tilts
    ([("z", "0.0")], "0.00999"),
    ([("x", "0.0087"), ("y", "0.0087")], "0.01"),
    ([("x", "0.05"), ("y", "-0.01")], "0.0101"),
    ([("z", "1.1"), ("x", "-0.03"), ("y", "0.004")], "0.0102"),
    ([("z", "-2.5"), ("y", "0.02"), ("x", "0.08")], "0.0105"),
    ([("x", "0.3"), ("y", "0.1"), ("z", "0.7")], "0.0098"),
    ([("y", "0.25"), ("x", "-0.2")], "0.011"),
]


def main():
    rows = ["qw,qx,qy,qz,zG,h,px,py,P,Q,c2,s2"]
    for seq, zg in CASES:
        q = quat(seq)
        vals = geometry(q, mp.mpf(zg))
        rows.append(",".join(mp.nstr(v, 20) for v in list(q) + [mp.mpf(zg)] + list(vals)))
    print(f"wrote {write_rows('rattleback_geometry.csv', rows)} ({len(rows) - 1} cases)")


if __name__ == "__main__":
    main()
