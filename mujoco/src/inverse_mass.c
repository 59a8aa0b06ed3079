/*
 * contensou.contact: the contacts' local inverse mass W from MuJoCo itself.
 *
 * For the contact velocity u = (v_n, v_x, v_y, ω) of B relative to A at the patch centre P in
 * the contact frame (n, x, y) — v = v_B(P) − v_A(P), v_n = v·n = −ḣ, ω = (ω_B − ω_A)·n, the
 * library's ordering of the step-aware wrench — u = J q̇ with the 4 × nv rows
 *
 *   J = [nᵀ; xᵀ; yᵀ] (J_p,B(P) − J_p,A(P))   over   nᵀ (J_r,B − J_r,A)
 *
 * (mj_jac: the translational Jacobian J_p of the point P moving with the body, the rotational
 * J_r; the world, body 0, has none). An impulse Δt·w on B (the wrench w = (N, F_x, F_y, T_z) in
 * the contact frame, its opposite on A) is the generalized impulse Δt·Jᵀw, which changes q̇ by
 * Δt·M⁻¹Jᵀw and u by Δt·J M⁻¹ Jᵀ w: W = J M⁻¹ Jᵀ, symmetric positive semidefinite. M⁻¹ by
 * mj_solveM on MuJoCo's factorization of this step's M (qLD, computed in the position stage,
 * before the passive forces). For K contacts the 4K rows are stacked and W (4K × 4K) carries
 * the cross blocks J_k M⁻¹ J_lᵀ of contacts that share a body (zero between contacts of
 * bodies that share no degree of freedom).
 *
 * Cost per evaluation: K calls of mj_jac per body side, one mj_solveM with 4K right-hand sides,
 * (4K)² dot products of length nv; dense in nv (the plugin's models have nv = 6).
 */
#include <string.h>

#include "contensou_mujoco.h"

/* The 4 × nv rows of J (row-major: n, x, y, spin) of pair k at geometry g; `scratch` holds
 * 6 × nv values. */
void contact_jacobian(const mjModel* m, const mjData* d, const pair* k, const geometry* g, mjtNum* jac,
                      mjtNum* scratch) {
  int nv = m->nv;
  mjtNum* jp = scratch;          /* 3 × nv */
  mjtNum* jr = scratch + 3 * nv; /* 3 × nv */
  memset(jac, 0, sizeof(mjtNum) * 4 * (size_t)nv);
  const int bodies[2] = {k->body_b, k->body_a};
  for (int side = 0; side < 2; side++) {
    int b = bodies[side];
    if (b <= 0) continue; /* the world: no degree of freedom */
    double sign = side == 0 ? 1.0 : -1.0;
    mj_jac(m, d, jp, jr, g->point, b);
    for (int j = 0; j < nv; j++) {
      double p[3] = {jp[j], jp[nv + j], jp[2 * nv + j]};
      double r[3] = {jr[j], jr[nv + j], jr[2 * nv + j]};
      jac[j] += sign * dot3(g->n, p);
      jac[nv + j] += sign * dot3(g->x, p);
      jac[2 * nv + j] += sign * dot3(g->y, p);
      jac[3 * nv + j] += sign * dot3(g->n, r);
    }
  }
}

/* W = J M⁻¹ Jᵀ (rows × rows, row-major, symmetric) of the stacked rows J (rows × nv); `work`
 * holds rows × nv values (M⁻¹Jᵀ, transposed). */
void inverse_mass(const mjModel* m, mjData* d, const mjtNum* jac, int rows, mjtNum* work, mjtNum* w) {
  int nv = m->nv;
  mj_solveM(m, d, work, jac, rows);
  for (int i = 0; i < rows; i++) {
    for (int j = i; j < rows; j++) {
      /* Symmetrised: ½(J_i·(M⁻¹J_j) + J_j·(M⁻¹J_i)), exact symmetry whatever the rounding. */
      double s = 0.5 * (mju_dot(jac + (size_t)i * nv, work + (size_t)j * nv, nv) +
                        mju_dot(jac + (size_t)j * nv, work + (size_t)i * nv, nv));
      w[i * rows + j] = s;
      w[j * rows + i] = s;
    }
  }
}
