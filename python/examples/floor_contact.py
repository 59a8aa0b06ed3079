"""contensou as the floor contact of MuJoCo sphere geoms (shared by mujoco_tippe_top.py and
mujoco_ball.py).

For each sphere geom of a body on the floor z = 0 (MuJoCo's own contact disabled for it with
contype = conaffinity = 0): the approach h = radius − (centre height), the patch centre P the
floor point below the centre, the slip v_P = v_G + ω × (P − G) of the body's material point at
P, its spin ω_z about the vertical, ḣ = −v_Pz; `contensou.Contact.step` (a circle, so the
contact frame's x, y are the world's) gives N, F_x, F_y, T_z; the force (F_x, F_y, N) acts at P
and the drilling torque about the vertical; their sum about G goes through `mj_applyFT` into qfrc_passive
from the `mjcb_passive` callback, so that every integrator stage sees the contact of its own
state (the floor is body A, the sphere body B; crate conventions).
"""

import math

import mujoco
import numpy as np

import contensou


class SphereFloor:
    """The floor contact of the sphere geoms `geoms` of `body` (a free body: qvel[0:3] the
    world velocity of the body origin, which must be its centre of mass, qvel[3:6] the angular
    velocity in the body frame)."""

    def __init__(self, model, body, geoms, estar, cd, f, delta, law="best", G=None, nu=None):
        self.body = model.body(body).id
        self.geoms = [model.geom(g).id for g in geoms]
        self.radius = [float(model.geom_size[g][0]) for g in self.geoms]
        # A rolling law (table, blend, fastsim, fastsim-16) takes the pair's G, ν and, per step,
        # the rolling velocity V = v_P − ½u_P: the contact point below the centre moves with the
        # centre, the floor is at rest (u_A = 0), u_P the sphere's material velocity at P.
        self.rolling = law in ("table", "blend", "fastsim", "fastsim-16")
        extra = {"G": G, "nu": nu} if self.rolling else {}
        self.contacts = [
            contensou.Contact(1 / (2 * r), 1 / (2 * r), estar, cd, f, delta, law=law, **extra) for r in self.radius
        ]
        self.qvel = model.jnt_dofadr[model.body_jntadr[self.body]]
        self.force = np.zeros(3)
        self.torque = np.zeros(3)
        self.point = np.zeros(3)
        self.normal = [0.0] * len(self.geoms)  # last N per sphere (diagnostics)

    def install(self):
        mujoco.set_mjcb_passive(self.passive)
        return self

    @staticmethod
    def uninstall():
        mujoco.set_mjcb_passive(None)

    def passive(self, model, data):
        """mjcb_passive: runs after the kinematics of the current (stage) state."""
        gx, gy, gz = data.xpos[self.body].tolist()
        k = self.qvel
        vx, vy, vz, bx, by, bz = data.qvel[k : k + 6].tolist()
        r = data.xmat[self.body].tolist()
        wx = r[0] * bx + r[1] * by + r[2] * bz
        wy = r[3] * bx + r[4] * by + r[5] * bz
        wz = r[6] * bx + r[7] * by + r[8] * bz
        fx = fy = fz = tx = ty = tz = 0.0
        for s, (g, radius, contact) in enumerate(zip(self.geoms, self.radius, self.contacts)):
            cx, cy, cz = data.geom_xpos[g].tolist()
            h = radius - cz
            if h <= 0.0:
                self.normal[s] = 0.0
                continue
            # arm G → P, P = (cx, cy, 0)
            ax, ay, az = cx - gx, cy - gy, -gz
            px = vx + wy * az - wz * ay
            py = vy + wz * ax - wx * az
            pz = vz + wx * ay - wy * ax
            if self.rolling:
                # the centre's velocity (v_P of the contact point below it), minus ½u_P
                ex, ey, ez = cx - gx, cy - gy, cz - gz
                cvx = vx + wy * ez - wz * ey
                cvy = vy + wz * ex - wx * ez
                n, sx, sy, sz = contact.step(h, -pz, px, py, wz, cvx - 0.5 * px, cvy - 0.5 * py)[:4]
            else:
                n, sx, sy, sz = contact.step(h, -pz, px, py, wz)[:4]
            self.normal[s] = n
            # Sum of the forces and of their moments about G (plus the drilling torque).
            fx, fy, fz = fx + sx, fy + sy, fz + n
            tx += ay * n - az * sy
            ty += az * sx - ax * n
            tz += ax * sy - ay * sx + sz
        if fz != 0.0:
            self.force[:] = (fx, fy, fz)
            self.torque[:] = (tx, ty, tz)
            self.point[:] = (gx, gy, gz)
            mujoco.mj_applyFT(model, data, self.force, self.torque, self.point, self.body, data.qfrc_passive)


def hertz_energy(estar, radius, h):
    """Elastic energy (2/5) k_H h^(5/2) of a sphere on a plane, k_H = (4/3) E* sqrt(R)."""
    return 0.4 * (4.0 / 3.0) * estar * math.sqrt(radius) * max(h, 0.0) ** 2.5
