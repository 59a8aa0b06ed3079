/*
 * contensou.contact: what the step-aware wrench needs from MuJoCo for the pairs of an instance
 * at the state of one passive-force evaluation — each pair's contact velocity
 * u = (v_n, v_x, v_y, ω) = J q̇ (B relative to A, v_n = −ḣ), its free end-of-step velocity
 * u_free = J q̇_free and the pairs' inverse mass W = J M⁻¹ Jᵀ with its cross blocks
 * (inverse_mass.c).
 *
 * and the approach h_free of each pair at the free end-of-step pose: the gap as the bodies drift
 * (a rattleback rolling over its 2 m bottom radius moves its gap by ≈ 1e-5 m per 1 ms step, four
 * times its static approach). Each body moves rigidly with its free end velocity (v_o of its
 * origin, ω; mj_jac times q̇_free): origin p' = p + Δt·v_o, attitude R' = Q·R with Q the
 * rotation by Δt·ω, so a geom at x goes to p' + Q(x − p). For a free joint this is MuJoCo's Euler
 * position update (q̇_free as the end velocity; its quaternion integration is the same rotation,
 * to rounding); for other joints a first-order rigid drift.
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

int step_work_init(step_work* s, const mjModel* m, int npair, double point) {
  memset(s, 0, sizeof(*s));
  s->point = point;
  s->body_v = calloc((size_t)3 * (size_t)m->nbody, sizeof(mjtNum));
  s->body_w = calloc((size_t)3 * (size_t)m->nbody, sizeof(mjtNum));
  s->body_p = calloc((size_t)3 * (size_t)m->nbody, sizeof(mjtNum));
  size_t nv = (size_t)(m->nv ? m->nv : 1);
  s->body_jac = calloc((size_t)6 * nv * (size_t)m->nbody, sizeof(mjtNum));
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
  s->roll = calloc(rows / 2, sizeof(double));
  s->geom_xpos = calloc((size_t)3 * (size_t)(m->ngeom ? m->ngeom : 1), sizeof(mjtNum));
  s->geom_xmat = calloc((size_t)9 * (size_t)(m->ngeom ? m->ngeom : 1), sizeof(mjtNum));
  s->done = calloc(rows / 4, sizeof(int));
  s->geom = calloc(rows / 4, sizeof(geometry));
  s->index = calloc(rows / 4, sizeof(int));
  if (!s->jac || !s->work || !s->scratch || !s->w || !s->qfrc || !s->qvel || !s->u || !s->u_free || !s->geom ||
      !s->index || !s->h_free || !s->roll || !s->geom_xpos || !s->geom_xmat || !s->done ||
      !s->body_v || !s->body_w || !s->body_p || !s->body_jac) {
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
  free(s->roll);
  free(s->geom_xpos);
  free(s->geom_xmat);
  free(s->done);
  free(s->body_v);
  free(s->body_w);
  free(s->body_p);
  free(s->body_jac);
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

/* res = a·b, 3 × 3 row-major (mju_mulMatMat's sums, in its order, without its general loops:
 * drift_pose runs it per geom up to three times a step). */
static void mat3_product(mjtNum res[9], const mjtNum a[9], const mjtNum b[9]) {
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      res[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
    }
  }
}

/* The geoms' poses at the free end of the step (module docs) in s->geom_xpos, s->geom_xmat:
 * every geom of a body that moves (body_weldid ≠ 0), the others as they are; the bodies'
 * Jacobians taken afresh if `fresh` (else those of the last fresh call: the same state). */
static void drift_pose(const mjModel* m, const mjData* d, step_work* s, double fraction, int fresh) {
  int nv = m->nv;
  double dt = m->opt.timestep * fraction;
  mju_copy(s->geom_xpos, d->geom_xpos, 3 * m->ngeom);
  mju_copy(s->geom_xmat, d->geom_xmat, 9 * m->ngeom);
  for (int b = 1; b < m->nbody; b++) {
    if (m->body_weldid[b] == 0 || m->body_geomnum[b] == 0) continue;
    const mjtNum* p = d->xpos + 3 * b;
    mjtNum* jp = s->body_jac + (size_t)6 * (size_t)nv * (size_t)b;
    mjtNum* jr = jp + 3 * nv;
    if (fresh) mj_jac(m, d, jp, jr, p, b);
    double v[3], w[3];
    for (int i = 0; i < 3; i++) {
      v[i] = mju_dot(jp + i * nv, s->qvel, nv);
      w[i] = mju_dot(jr + i * nv, s->qvel, nv);
      s->body_v[3 * b + i] = v[i];
      s->body_w[3 * b + i] = w[i];
      s->body_p[3 * b + i] = p[i] + dt * v[i];
    }
    mjtNum q[4] = {1, 0, 0, 0}, rot[9];
    double angle = mju_norm3(w) * dt;
    if (angle > 0.0) {
      mjtNum axis[3] = {w[0], w[1], w[2]};
      mju_normalize3(axis);
      mju_axisAngle2Quat(q, axis, angle);
    }
    mju_quat2Mat(rot, q);
    for (int g = m->body_geomadr[b]; g < m->body_geomadr[b] + m->body_geomnum[b]; g++) {
      const mjtNum* x = d->geom_xpos + 3 * g;
      double r[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]}, rr[3];
      mju_mulMatVec3(rr, rot, r);
      for (int i = 0; i < 3; i++) s->geom_xpos[3 * g + i] = p[i] + dt * v[i] + rr[i];
      mat3_product(s->geom_xmat + 9 * g, rot, d->geom_xmat + 9 * g);
    }
  }
}

/* The free end velocity u = (v_n, v_x, v_y, ω) of pair k at the drifted geometry e: the
 * bodies' free end velocities (origin drifted as in drift_pose) at e's contact point, in e's
 * frame; and Kalker's rolling velocity there, V = v_P − ½(u_A + u_B) in (x, y) (the velocity
 * of e's geometric contact point over each surface, averaged: contact_point_velocity_at with
 * the free velocities, as the Rust scenes take it at their mid-step pose). */
static void drifted_velocity(const mjModel* m, const step_work* s, const pair* k, const geometry* e, double u[4],
                             double roll[2]) {
  double v[3] = {0, 0, 0}, w[3] = {0, 0, 0}, usum[3] = {0, 0, 0};
  const int bodies[2] = {k->body_b, k->body_a};
  const double* vel[2] = {NULL, NULL};
  const double* ang[2] = {NULL, NULL};
  for (int side = 0; side < 2; side++) {
    int b = bodies[side];
    if (b <= 0 || m->body_weldid[b] == 0) continue;
    double sign = side == 0 ? 1.0 : -1.0, arm[3], pv[3];
    for (int i = 0; i < 3; i++) arm[i] = e->point[i] - s->body_p[3 * b + i];
    point_velocity(s->body_v + 3 * b, s->body_w + 3 * b, arm, pv);
    vel[side] = s->body_v + 3 * b;
    ang[side] = s->body_w + 3 * b;
    for (int i = 0; i < 3; i++) {
      v[i] += sign * pv[i];
      w[i] += sign * s->body_w[3 * b + i];
      usum[i] += pv[i];
    }
  }
  u[0] = dot3(v, e->n);
  u[1] = dot3(v, e->x);
  u[2] = dot3(v, e->y);
  u[3] = dot3(w, e->n);
  static const double zero[3] = {0, 0, 0};
  double vp[3];
  contact_point_velocity_at(m, s->body_p, s->geom_xmat, k, e, vel[0] ? vel[0] : zero, ang[0] ? ang[0] : zero, vel[1],
                            ang[1], vp);
  for (int i = 0; i < 3; i++) vp[i] -= 0.5 * usum[i];
  roll[0] = dot3(vp, e->x);
  roll[1] = dot3(vp, e->y);
}

int step_prepare(const mjModel* m, mjData* d, const pair* pairs, int npair, step_work* s) {
  int nv = m->nv;
  free_velocity(m, d, s);
  drift_pose(m, d, s, 1.0, 1);
  int k = 0;
  for (int i = 0; i < npair; i++) {
    geometry* g = &s->geom[k];
    geometry end;
    int touching = pair_geometry(m, d, &pairs[i], g) == 0;
    int touching_end = pair_geometry_at(m, s->geom_xpos, s->geom_xmat, &pairs[i], &end) == 0;
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
  if (s->point > 0.0) {
    /* step_point θ > 0: u_free at the contact point and frame of the pose drifted by θ·Δt. */
    if (s->point != 1.0) drift_pose(m, d, s, s->point, 0);
    for (int t = 0; t < k; t++) {
      geometry e;
      pair_geometry_at(m, s->geom_xpos, s->geom_xmat, &pairs[s->index[t]], &e);
      drifted_velocity(m, s, &pairs[s->index[t]], &e, s->u_free + 4 * t, s->roll + 2 * t);
    }
  }
  if (k > 0) inverse_mass(m, d, s->jac, 4 * k, s->work, s->w);
  return k;
}

int step_solve(const contensou_contact_f64* const* contacts, int k, double dt, const double* w,
               const contensou_step_f64* steps, const contensou_rolling_step_f64* rolling, const double* u_free,
               const double* h_free, double* out) {
  contensou_step_free_f64 free[CONTENSOU_STEP_MAX_CONTACTS];
  contensou_step_wrench_f64 wrench[CONTENSOU_STEP_MAX_CONTACTS];
  if (k < 1 || k > CONTENSOU_STEP_MAX_CONTACTS) return -1;
  for (int i = 0; i < k; i++) {
    free[i].u.vn = u_free[4 * i];
    free[i].u.vx = u_free[4 * i + 1];
    free[i].u.vy = u_free[4 * i + 2];
    free[i].u.omega = u_free[4 * i + 3];
    free[i].h = h_free[i];
  }
  if (contensou_step_many_f64(contacts, (size_t)k, steps, rolling, dt, w, free, wrench, NULL, NULL) !=
      CONTENSOU_STATUS_OK) {
    return -1;
  }
  for (int i = 0; i < k; i++) {
    out[4 * i] = wrench[i].n;
    out[4 * i + 1] = wrench[i].fx;
    out[4 * i + 2] = wrench[i].fy;
    out[4 * i + 3] = wrench[i].tz;
  }
  return 0;
}

/*
 * The normal force made consistent with the end approach (step_normal). The library solves the
 * four rows of a contact together from linearisations, then re-linearises a reversing slip and
 * moves the friction into the law's limit set and scales it to no power: with W's
 * normal–tangential coupling (a contact point off the body's centre of mass: the rattleback's
 * runs centimetres from it) the friction it returns moves the end approach
 * h⁺ = h_free − Δt²·(W·w)_n, and on a rare step N is far from the normal law's value there
 * (measured, rolling rattleback at 1 ms: N = 4.2 N returned where h⁺ = 7.9 µm gives 65 N, the
 * friction reversed that step; the body then sinks and the next step's normal force pushes it
 * out, 1.4e-3 of the energy unpaid; which of the library's stages leaves N behind is not
 * pinned down). Per pair, with every other row fixed, N is re-solved from
 *
 *   r(N) = N − N_law(h⁺(N), ḣ⁺(N)),   h⁺ = h_free − Δt²·(c₀ + W_nn·N),   ḣ⁺ = −(u_free,n + Δt·(c₀ + W_nn·N))
 *
 * (c₀ the other rows' part of (W·w)_n), increasing in N (N_law grows with h and ḣ), r(0) ≤ 0:
 * on a bracket from one Newton step (normal_row), at most NORMAL_STEPS Illinois steps, ending
 * early where the next secant step would move N by less than NORMAL_EXACT·N (|r| ≤
 * NORMAL_EXACT·N·r', r' from the bracket; r' is in the hundreds at 2 ms: Δt²·W_nn·∂N_law/∂h).
 * Only when |r(N)| > NORMAL_TOLERANCE·N (one law call per pair otherwise: the library's N is
 * consistent to ≈ 1e-5 on the other steps), pair after pair, NORMAL_SWEEPS sweeps (pairs
 * sharing a body: a ball on a ball on the floor rests with both contacts at the law's value to
 * 8e-4 at 2 ms, the upper one 32 % off without). If the new N makes the pair's friction do work at
 * u⁺ (its power α·a + α²·b for the friction scaled by α, b = Δt·f·W_ff·f ≥ 0), the friction is
 * scaled to α = −a/b (0 if a ≥ 0) and N re-solved once more with it.
 */
#define NORMAL_STEPS 8
#define NORMAL_TOLERANCE 1e-3
#define NORMAL_EXACT 1e-9
#define NORMAL_SWEEPS 2

static double normal_residual(const contensou_contact_f64* c, double h_free, double un_free, double dt, double c0,
                              double wnn, double n, double* n_law) {
  double p = c0 + wnn * n;
  contensou_step_f64 st = {h_free - dt * dt * p, -(un_free + dt * p), 0.0, 0.0, 0.0};
  contensou_wrench_f64 wl;
  *n_law = 0.0;
  if (st.h > 0.0 && contensou_contact_wrench_f64(c, &st, &wl, NULL) == CONTENSOU_STATUS_OK && wl.n > 0.0) {
    *n_law = wl.n;
  }
  return n - *n_law;
}

/* N of pair t re-solved with the other rows fixed (module docs); 1 if it changed. */
static int normal_row(const contensou_contact_f64* c, const step_work* s, int t, double dt, double* wrench) {
  int rows = 4 * s->count, i = 4 * t;
  double c0 = 0.0, wnn = s->w[i * rows + i], n = wrench[i], law;
  for (int j = 0; j < rows; j++) {
    if (j != i) c0 += s->w[i * rows + j] * wrench[j];
  }
  double r = normal_residual(c, s->h_free[t], s->u_free[i], dt, c0, wnn, n, &law);
  if (!(mju_abs(r) > NORMAL_TOLERANCE * n)) return 0;
  /* The bracket, from a Newton step on r at N with the Hertz slope r' ≈ 1 + 1.5·Δt²·W_nn·N_law/h⁺
   * (∂N_law/∂h = 1.5·N_law/h at a fixed ḣ; the damping's ∂N_law/∂ḣ left out, so r' is
   * underestimated and the step long): x is kept as one end if r(x) has the other sign than r(N),
   * else it replaces N and N_law(x) is the other end (r(N_law(x)) has the other sign than r(x):
   * N_law falls as N grows). Past N_sep the end approach h⁺(N) ≤ 0: N_law = 0 and r(N) = N there,
   * a flat branch the secant crawls along (measured on the top at 2 ms with its N re-solved at
   * MuJoCo's end pose, mujoco/README.md: 8 steps from [N, N_law(N)] left a 2.5 % bracket); the
   * root lies below N_sep (r ≤ 0 needs N_law > 0, h⁺ > 0), so N_sep caps the upper end. */
  double nsep = wnn > 0.0 ? (s->h_free[t] / (dt * dt) - c0) / wnn : mjMAXVAL;
  double hplus = s->h_free[t] - dt * dt * (c0 + wnn * n);
  double x0 = law > 0.0 && hplus > 0.0 ? n - r / (1.0 + 1.5 * dt * dt * wnn * law / hplus) : law;
  if (r < 0.0 && !(x0 < nsep)) x0 = 0.5 * (n + nsep);
  if (!(x0 >= 0.0)) x0 = 0.0;
  double lx, f0 = normal_residual(c, s->h_free[t], s->u_free[i], dt, c0, wnn, x0, &lx);
  double a = n, b = x0, fa = r, fb = f0;
  if ((r < 0.0) == (f0 < 0.0)) {
    /* x0 on N's side: x0 and N_law(x0). */
    a = x0;
    fa = f0;
    b = lx;
    fb = normal_residual(c, s->h_free[t], s->u_free[i], dt, c0, wnn, b, &lx);
  }
  if (a > b) {
    double y = a, fy = fa;
    a = b;
    fa = fb;
    b = y;
    fb = fy;
  }
  if (!(fa <= 0.0 && fb >= 0.0)) return 0;
  if (nsep > a && nsep < b) {
    b = nsep;
    fb = nsep;
  }
  int side = 0;
  for (int step = 0; step < NORMAL_STEPS && fb - fa > 0.0; step++) {
    double slope = (fb - fa) / (b - a), x = b - fb / slope;
    double fx = normal_residual(c, s->h_free[t], s->u_free[i], dt, c0, wnn, x, &law);
    if (mju_abs(fx) <= NORMAL_EXACT * x * slope) {
      /* Converged: the next secant step would move N by less than NORMAL_EXACT·N. */
      a = b = x;
      fa = fb = 0.0;
      break;
    }
    if (fx > 0.0) {
      b = x;
      fb = fx;
      if (side == 1) fa *= 0.5;
      side = 1;
    } else {
      a = x;
      fa = fx;
      if (side == -1) fb *= 0.5;
      side = -1;
    }
  }
  wrench[i] = fb - fa > 0.0 ? a - fa * (b - a) / (fb - fa) : a;
  if (!(wrench[i] >= a && wrench[i] <= b)) wrench[i] = 0.5 * (a + b);
  return 1;
}

/* Pair t's friction f = (F_x, F_y, T_z) scaled to no work at its end velocity, free part
 * `base` (3: the rows x, y, spin of q̇_free) plus Δt·W·w: its power for f scaled by α is
 * α·a + α²·b, a = f·(base + Δt·W·w without f), b = Δt·f·W_ff·f ≥ 0; if a + b > 0, α = −a/b
 * (0 if a ≥ 0). 1 if it scaled. */
static int friction_to_no_work(const step_work* s, int t, const double* base, double dt, double* wrench) {
  int rows = 4 * s->count, i = 4 * t;
  double pa = 0.0, pb = 0.0;
  for (int r = i + 1; r < i + 4; r++) {
    double u = base[r - i - 1], uf = 0.0;
    for (int j = 0; j < rows; j++) {
      if (j > i && j < i + 4) {
        uf += s->w[r * rows + j] * wrench[j];
      } else {
        u += dt * s->w[r * rows + j] * wrench[j];
      }
    }
    pa += wrench[r] * u;
    pb += dt * wrench[r] * uf;
  }
  if (!(pa + pb > 0.0)) return 0;
  double alpha = pa < 0.0 && pb > 0.0 ? -pa / pb : 0.0;
  for (int r = i + 1; r < i + 4; r++) wrench[r] *= alpha;
  return 1;
}

void step_normal(const pair* pairs, const step_work* s, double dt, double* wrench) {
  /* A further sweep only if one changed an N and another pair could feel it. */
  int changed = 1;
  for (int sweep = 0; sweep < NORMAL_SWEEPS && changed && (sweep == 0 || s->count > 1); sweep++) {
    changed = 0;
    for (int t = 0; t < s->count; t++) {
      int i = 4 * t;
      if (!(wrench[i] > 0.0) || !normal_row(&pairs[s->index[t]].contact, s, t, dt, wrench)) continue;
      changed = 1;
      if (friction_to_no_work(s, t, s->u_free + i + 1, dt, wrench)) {
        normal_row(&pairs[s->index[t]].contact, s, t, dt, wrench);
      }
    }
  }
}

/*
 * The friction's work in MuJoCo's update (step_friction_at_start). With step_point θ > 0 the
 * library keeps each pair's friction passive at u_free(θ) + Δt·W·w, u_free read at the pose
 * drifted by θ·Δt, while MuJoCo applies the wrench through the start rows J, whose end
 * velocity is J·q̇_free + Δt·W·w: the friction then did work on some steps (up to 2.6e-4 of
 * the start energy per step, rolling rattleback, θ = 0.6, 2 ms). Per pair, its friction
 * f = (F_x, F_y, T_z) scaled by α has the power α·a + α²·b at that velocity,
 * a = f·(J q̇_free + Δt·W·w without f)_f, b = Δt·f·W_ff·f ≥ 0; if a + b > 0 the friction is
 * scaled to α = −a/b (0 if a ≥ 0): no work over the step. The normal forces are then re-solved
 * (step_normal) and the check made once more (passive_step).
 */
void step_friction_at_start(const mjModel* m, const step_work* s, double* wrench) {
  int nv = m->nv;
  for (int t = 0; t < s->count; t++) {
    double base[3];
    for (int r = 0; r < 3; r++) base[r] = mju_dot(s->jac + (size_t)(4 * t + 1 + r) * nv, s->qvel, nv);
    friction_to_no_work(s, t, base, m->opt.timestep, wrench);
  }
}
