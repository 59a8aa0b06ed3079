/*
 * contensou.contact: what the step-aware wrench needs from MuJoCo for the pairs of an instance
 * at the state of one passive-force evaluation — each pair's contact velocity
 * u = (v_n, v_x, v_y, ω) = J q̇ (B relative to A, v_n = −ḣ), its free end-of-step velocity
 * u_free = J q̇_free and the pairs' inverse mass W = J M⁻¹ Jᵀ with its cross blocks
 * (inverse_mass.c).
 *
 * and the approach h_free of each pair at the free end-of-step pose — q integrated over Δt with
 * q̇_free (mj_integratePos), as MuJoCo's Euler does with the end velocity: the gap as the bodies
 * drift (a rattleback rolling over its 2 m bottom radius moves its gap by ≈ 1e-5 m per 1 ms step,
 * four times its static approach) — by mj_kinematics on a scratch mjData.
 *
 * The free end-of-step velocity is MuJoCo's semi-implicit Euler velocity update without this
 * instance's contacts:
 *
 *   q̇_free = q̇ + Δt·M⁻¹·(qfrc_passive so far + qfrc_applied + Σ J_bᵀ xfrc_applied,b − qfrc_bias)
 *
 * with qfrc_bias (gravity, Coriolis and centrifugal terms) from mj_rne at this state, and
 * qfrc_passive as MuJoCo's passive stage has filled it before the plugin (springs, dampers,
 * gravity compensation, fluid forces). Left out, because MuJoCo computes them after the passive
 * forces: actuator forces and MuJoCo's own constraint forces (joint limits, native contacts).
 */
#include <stdlib.h>
#include <string.h>

#include "contensou_mujoco.h"

int step_work_init(step_work* s, const mjModel* m, int npair) {
  memset(s, 0, sizeof(*s));
  size_t nv = (size_t)(m->nv ? m->nv : 1);
  size_t rows = (size_t)4 * (size_t)(npair ? npair : 1);
  s->cap = npair;
  s->jac = calloc(rows * nv, sizeof(mjtNum));
  s->work = calloc(rows * nv, sizeof(mjtNum));
  s->scratch = calloc(6 * nv, sizeof(mjtNum));
  s->w = calloc(rows * rows, sizeof(mjtNum));
  s->qfrc = calloc(nv, sizeof(mjtNum));
  s->qvel = calloc(nv, sizeof(mjtNum));
  s->u = calloc(rows, sizeof(double));
  s->u_free = calloc(rows, sizeof(double));
  s->h_free = calloc(rows / 4, sizeof(double));
  s->drift = mj_makeData(m);
  s->geom = calloc(rows / 4, sizeof(geometry));
  s->index = calloc(rows / 4, sizeof(int));
  if (!s->jac || !s->work || !s->scratch || !s->w || !s->qfrc || !s->qvel || !s->u || !s->u_free || !s->geom ||
      !s->index || !s->h_free || !s->drift) {
    step_work_free(s);
    return -1;
  }
  return 0;
}

void step_work_free(step_work* s) {
  free(s->jac);
  free(s->work);
  free(s->scratch);
  free(s->w);
  free(s->qfrc);
  free(s->qvel);
  free(s->u);
  free(s->u_free);
  free(s->h_free);
  if (s->drift) mj_deleteData(s->drift);
  free(s->geom);
  free(s->index);
  memset(s, 0, sizeof(*s));
}

/* q̇_free (module docs) into s->qvel. */
static void free_velocity(const mjModel* m, mjData* d, step_work* s) {
  int nv = m->nv;
  mj_rne(m, d, 0, s->qfrc); /* qfrc_bias at this state */
  for (int i = 0; i < nv; i++) s->qfrc[i] = d->qfrc_passive[i] + d->qfrc_applied[i] - s->qfrc[i];
  for (int b = 1; b < m->nbody; b++) {
    const mjtNum* x = d->xfrc_applied + 6 * b;
    if (x[0] != 0 || x[1] != 0 || x[2] != 0 || x[3] != 0 || x[4] != 0 || x[5] != 0) {
      mj_applyFT(m, d, x, x + 3, d->xipos + 3 * b, b, s->qfrc);
    }
  }
  mj_solveM(m, d, s->qvel, s->qfrc, 1);
  for (int i = 0; i < nv; i++) s->qvel[i] = d->qvel[i] + m->opt.timestep * s->qvel[i];
}

/* The pose q + Δt·q̇_free in s->drift (its kinematics). */
static void drift_pose(const mjModel* m, const mjData* d, step_work* s) {
  mjData* x = s->drift;
  mju_copy(x->qpos, d->qpos, m->nq);
  if (m->nmocap) {
    mju_copy(x->mocap_pos, d->mocap_pos, 3 * m->nmocap);
    mju_copy(x->mocap_quat, d->mocap_quat, 4 * m->nmocap);
  }
  mj_integratePos(m, x->qpos, s->qvel, m->opt.timestep);
  mj_kinematics(m, x);
}

int step_prepare(const mjModel* m, mjData* d, const pair* pairs, int npair, step_work* s) {
  int nv = m->nv;
  free_velocity(m, d, s);
  drift_pose(m, d, s);
  int k = 0;
  for (int i = 0; i < npair; i++) {
    geometry* g = &s->geom[k];
    geometry end;
    int touching = pair_geometry(m, d, &pairs[i], g) == 0;
    int touching_end = pair_geometry(m, s->drift, &pairs[i], &end) == 0;
    if (!touching && !touching_end) continue; /* apart now and at the free end of the step */
    s->h_free[k] = end.h;
    mjtNum* jac = s->jac + (size_t)4 * k * nv;
    contact_jacobian(m, d, &pairs[i], g, jac, s->scratch);
    for (int r = 0; r < 4; r++) {
      s->u[4 * k + r] = mju_dot(jac + (size_t)r * nv, d->qvel, nv);
      s->u_free[4 * k + r] = mju_dot(jac + (size_t)r * nv, s->qvel, nv);
    }
    s->index[k++] = i;
  }
  s->count = k;
  if (k > 0) inverse_mass(m, d, s->jac, 4 * k, s->work, s->w);
  return k;
}
