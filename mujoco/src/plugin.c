/*
 * contensou.contact: a MuJoCo engine plugin (passive forces + sensor) over the contensou C API.
 *
 * For every body that carries an instance of the plugin ("plugin body", body B) it computes,
 * at every evaluation of the passive forces, the Hertz normal force with Hunt–Crossley damping
 * and the Contensou–Erismann friction force and drilling torque (contensou::dynamic through
 * capi/include/contensou.h, f64) of
 *   - each sphere, capsule (its two end spheres) and ellipsoid geom of the body against every
 *     plane geom of the model (body A: the plane's body, usually the world), and
 *   - each sphere geom of the body against each sphere geom of another body of the same
 *     instance (the body earlier in the model is A),
 * and adds the wrench on B (and its opposite on A unless A is welded to the world) to qfrc_passive by
 * mj_applyFT. Crate conventions: forces on B from A, contact frame z = the normal from A to B,
 * x = the patch's major axis.
 *
 * Per pair and step (mujoco/README.md, "What it computes"; pairs.c):
 *   sphere/plane: h = r − (c − p₀)·n, patch centre P = c − ((c − p₀)·n) n (on the plane),
 *                 P = Q = 1/(2r), x = the plane's x axis;
 *   ellipsoid/plane: the support point of the ellipsoid in the direction −n in closed form,
 *                 x*ᵢ = aᵢ²uᵢ/s, s = √(Σaᵢ²uᵢ²) (u = −n in the geom frame), h = −(x* − p₀)·n,
 *                 P ≤ Q and the major axis from the 2×2 form ½s·Tᵀdiag(1/aᵢ²)T over the plane's
 *                 (x, y) axes T (quadratic_form below, the twin of Curvatures::from_quadratic),
 *                 as src/scenes/rattleback.rs; varying form: contensou_contact_set_curvatures;
 *   sphere/sphere: h = r_a + r_b − |c_b − c_a|, n = (c_b − c_a)/|c_b − c_a|,
 *                 P = c_a + n (r_a − h r_b/(r_a + r_b)), P = Q = ½(1/r_a + 1/r_b).
 * Slip v_B(P) − v_A(P) in (x, y), ḣ = −(v_B(P) − v_A(P))·n, spin (ω_B − ω_A)·n; the material
 * point velocities from the bodies' free-joint velocities (a free body, the arithmetic of
 * python/examples/floor_contact.py, so that both agree bit for bit) or mj_objectVelocity.
 *
 * Configuration (<config key="…" value="…"/>): estar (Pa) or young1, poisson1, young2,
 * poisson2; f; cd (s/m, default 0); delta (m/s, default 1e-4); law (best|simplified|pade|
 * ellipsoid|coulomb, default best, or a rolling law rolling (= table)|table|blend|fastsim|
 * fastsim-16); G (Pa), nu (rolling laws only; else from the materials by Kalker's rule, else
 * the library's defaults); form (auto|fixed|varying, default auto: fixed for spheres
 * and capsules, varying for ellipsoids). With a rolling law each pair also gets Kalker's
 * rolling velocity V = v_P − ½(u_A + u_B) (v_P: the geometric contact point's velocity,
 * contact_point_velocity in pairs.c; u: the material velocities at P). A bad value, an unsupported geom, or a plugin geom that
 * MuJoCo would also collide with a plane (contype/conaffinity) refuses the model at load:
 * init() warns with the attribute and the value and returns −1, which the compiler turns into
 * the load error.
 *
 * Sensor (<sensor><plugin instance="…"/></sensor>): per pair, in the order above, the seven
 * values N, F_x, F_y, T_z, a, b, h (contact frame; zeros but h when apart).
 */
#include <stdlib.h>
#include <string.h>

#include "contensou_mujoco.h"

static const char* const ATTRIBUTES[] = {"estar", "young1", "poisson1", "young2", "poisson2", "cd", "f",
                                         "delta", "law",    "form",     "G",      "nu",       "step",
                                         "step_point"};
#define NATTRIBUTE ((int)(sizeof(ATTRIBUTES) / sizeof(ATTRIBUTES[0])))

/* A body's velocity this step: ω (world) and the velocity of its origin xpos (world). */
typedef struct {
  double w[3];
  double v[3];
  double force[3];
  double torque[3]; /* about xpos */
  int active;
} body_state;

/* One pair's kinematics at this state: the bodies (NULL: at rest, welded to the world), the
 * arms from their origins to P, the slip v_B(P) − v_A(P) and spin ω_B − ω_A (world). */
typedef struct kinematics_ {
  body_state *sa, *sb;
  double arm_a[3], arm_b[3];
  double vrel[3], wrel[3];
} kinematics;

typedef struct {
  int rolling; /* a rolling law: the rolling velocity is computed and passed */
  int aware;   /* step = aware: the step-aware wrench (step_work) */
  step_work step;
  /* step = aware, per pair taken: */
  contensou_step_f64* steps;
  contensou_rolling_step_f64* rolls;
  struct kinematics_* kins;
  double* ab;     /* the start patch's a, b */
  double* wrench; /* 4 */
  int* group;
  int* other;
  int npair;
  pair* pairs;
  double* out;       /* NOUT per pair */
  int nbody;         /* bodies that move and take loads (not welded to the world) */
  int* bodies;       /* their ids */
  body_state* state; /* per entry of bodies */
  int* slot;         /* model body id → index into bodies, −1 */
} instance_data;

static void free_instance(instance_data* x) {
  if (!x) return;
  if (x->aware) step_work_free(&x->step);
  free(x->steps);
  free(x->rolls);
  free(x->kins);
  free(x->ab);
  free(x->wrench);
  free(x->group);
  free(x->other);
  free(x->pairs);
  free(x->out);
  free(x->bodies);
  free(x->state);
  free(x->slot);
  free(x);
}

static int init(const mjModel* m, mjData* d, int instance) {
  config c;
  if (read_config(m, instance, &c)) return -1;
  instance_data* x = calloc(1, sizeof(*x));
  if (!x) return -1;
  x->npair = enumerate_pairs(m, instance, NULL);
  x->pairs = calloc(x->npair ? x->npair : 1, sizeof(pair));
  x->out = calloc(x->npair ? (size_t)x->npair * NOUT : 1, sizeof(double));
  x->slot = malloc(sizeof(int) * m->nbody);
  x->bodies = calloc(m->nbody, sizeof(int));
  x->state = calloc(m->nbody, sizeof(body_state));
  if (!x->pairs || !x->out || !x->slot || !x->bodies || !x->state) {
    free_instance(x);
    return -1;
  }
  x->rolling = c.rolling;
  enumerate_pairs(m, instance, x->pairs);
  if (c.step_aware) {
    if (step_work_init(&x->step, m, x->npair, c.step_point)) {
      free_instance(x);
      return -1;
    }
    x->aware = 1;
    size_t n = (size_t)(x->npair ? x->npair : 1);
    x->steps = calloc(n, sizeof(contensou_step_f64));
    x->rolls = calloc(n, sizeof(contensou_rolling_step_f64));
    x->kins = calloc(n, sizeof(kinematics));
    x->ab = calloc(2 * n, sizeof(double));
    x->wrench = calloc(4 * n, sizeof(double));
    x->group = calloc(n, sizeof(int));
    x->other = calloc(n, sizeof(int));
    if (!x->steps || !x->rolls || !x->kins || !x->ab || !x->wrench || !x->group || !x->other) {
      free_instance(x);
      return -1;
    }
  }
  if (check_geoms(m, instance, x->pairs, x->npair)) {
    free_instance(x);
    return -1;
  }
  for (int b = 0; b < m->nbody; b++) x->slot[b] = -1;
  for (int k = 0; k < x->npair; k++) {
    pair* p = &x->pairs[k];
    int ids[2] = {p->body_b, p->body_a};
    for (int i = 0; i < 2; i++) {
      /* A body welded to the world (a plane's static body) neither moves nor takes a load. */
      if (ids[i] > 0 && m->body_weldid[ids[i]] != 0 && x->slot[ids[i]] < 0) {
        x->slot[ids[i]] = x->nbody;
        x->bodies[x->nbody++] = ids[i];
      }
    }
    contensou_curvatures_f64 k0;
    contensou_status s;
    int varying;
    if (p->kind == ELLIPSOID_PLANE) {
      ellipsoid_rest(m, p->geom_b, &k0.p, &k0.q);
      s = CONTENSOU_STATUS_OK;
      varying = c.form != FORM_FIXED;
    } else if (p->kind == SPHERE_PLANE) {
      s = contensou_curvatures_sphere_plane_f64(p->radius, &k0);
      varying = c.form == FORM_VARYING;
    } else {
      s = contensou_curvatures_sphere_sphere_f64(p->radius_a, p->radius, &k0);
      varying = c.form == FORM_VARYING;
    }
    contensou_spec_f64 spec = c.spec;
    spec.p = k0.p;
    spec.q = k0.q;
    contensou_column column = CONTENSOU_COLUMN_NONE;
    if (s == CONTENSOU_STATUS_OK) {
      s = new_contact(&p->contact, &c, &spec, varying ? CONTENSOU_FORM_VARYING : CONTENSOU_FORM_FIXED, &column);
    }
    if (s != CONTENSOU_STATUS_OK) {
      mju_warning(PLUGIN_NAME ": geom '%s' (size %g) against '%s': curvatures P = %g, Q = %g: %s",
                  geom_name(m, p->geom_b), m->geom_size[3 * p->geom_b], geom_name(m, p->geom_a), spec.p, spec.q,
                  contensou_status_message(s));
      free_instance(x);
      return -1;
    }
  }
  d->plugin_data[instance] = (uintptr_t)x;
  return 0;
}

static void destroy(mjData* d, int instance) {
  free_instance((instance_data*)d->plugin_data[instance]);
  d->plugin_data[instance] = 0;
}

static void copy(mjData* dest, const mjModel* m, const mjData* src, int instance) {
  (void)m;
  instance_data* to = (instance_data*)dest->plugin_data[instance];
  const instance_data* from = (const instance_data*)src->plugin_data[instance];
  if (!to || !from || to->npair != from->npair) return;
  memcpy(to->pairs, from->pairs, sizeof(pair) * (size_t)from->npair);
  memcpy(to->out, from->out, sizeof(double) * NOUT * (size_t)from->npair);
}

static void reset(const mjModel* m, mjtNum* plugin_state, void* plugin_data, int instance) {
  (void)m;
  (void)plugin_state;
  (void)instance;
  instance_data* x = (instance_data*)plugin_data;
  if (x) memset(x->out, 0, sizeof(double) * NOUT * (size_t)x->npair);
}

static int nstate(const mjModel* m, int instance) {
  (void)m;
  (void)instance;
  return 0;
}

static int nsensordata(const mjModel* m, int instance, int sensor_id) {
  (void)sensor_id;
  return NOUT * enumerate_pairs(m, instance, NULL);
}

/* ω (world) and the velocity of the origin xpos (world) of body b. */
static void body_velocity(const mjModel* m, const mjData* d, int b, body_state* s) {
  int j = m->body_jntadr[b];
  if (m->body_jntnum[b] == 1 && m->jnt_type[j] == mjJNT_FREE) {
    /* As floor_contact.py: qvel[0:3] the origin's world velocity, qvel[3:6] ω in the body frame. */
    const mjtNum* qv = d->qvel + m->jnt_dofadr[j];
    const mjtNum* r = d->xmat + 9 * b;
    double bx = qv[3], by = qv[4], bz = qv[5];
    s->v[0] = qv[0];
    s->v[1] = qv[1];
    s->v[2] = qv[2];
    s->w[0] = r[0] * bx + r[1] * by + r[2] * bz;
    s->w[1] = r[3] * bx + r[4] * by + r[5] * bz;
    s->w[2] = r[6] * bx + r[7] * by + r[8] * bz;
  } else {
    mjtNum res[6];
    mj_objectVelocity(m, d, mjOBJ_BODY, b, res, 0);
    for (int i = 0; i < 3; i++) {
      s->w[i] = res[i];
      s->v[i] = res[3 + i];
    }
  }
}

static const double ZERO3[3] = {0.0, 0.0, 0.0};

/* The bodies' velocities at this state; their loads cleared. */
static void begin_bodies(const mjModel* m, mjData* d, instance_data* x) {
  for (int i = 0; i < x->nbody; i++) {
    body_state* s = &x->state[i];
    body_velocity(m, d, x->bodies[i], s);
    memset(s->force, 0, sizeof(s->force));
    memset(s->torque, 0, sizeof(s->torque));
    s->active = 0;
  }
}

/* Each loaded body's sum of loads into qfrc_passive, once per body. */
static void end_bodies(const mjModel* m, mjData* d, instance_data* x) {
  for (int i = 0; i < x->nbody; i++) {
    body_state* s = &x->state[i];
    if (s->active) {
      int b = x->bodies[i];
      mj_applyFT(m, d, s->force, s->torque, d->xpos + 3 * b, b, d->qfrc_passive);
    }
  }
}


static void pair_kinematics(const mjData* d, instance_data* x, const pair* p, const geometry* g, kinematics* k) {
  k->sb = x->slot[p->body_b] >= 0 ? &x->state[x->slot[p->body_b]] : NULL;
  k->sa = x->slot[p->body_a] >= 0 ? &x->state[x->slot[p->body_a]] : NULL;
  const mjtNum* ob = d->xpos + 3 * p->body_b;
  for (int i = 0; i < 3; i++) {
    k->arm_b[i] = g->point[i] - ob[i];
    k->arm_a[i] = k->vrel[i] = k->wrel[i] = 0.0;
  }
  if (k->sb) {
    point_velocity(k->sb->v, k->sb->w, k->arm_b, k->vrel);
    memcpy(k->wrel, k->sb->w, sizeof(k->wrel));
  }
  if (k->sa) {
    const mjtNum* oa = d->xpos + 3 * p->body_a;
    double va[3];
    for (int i = 0; i < 3; i++) k->arm_a[i] = g->point[i] - oa[i];
    point_velocity(k->sa->v, k->sa->w, k->arm_a, va);
    for (int i = 0; i < 3; i++) {
      k->vrel[i] -= va[i];
      k->wrel[i] -= k->sa->w[i];
    }
  }
}

/* Kalker's rolling velocity V = v_P − ½(u_A + u_B): the velocity of the geometric contact point
 * over each surface, averaged (u the material velocities at P), in (x, y). */
static contensou_rolling_step_f64 rolling_velocity(const mjModel* m, const mjData* d, const pair* p,
                                                   const geometry* g, const kinematics* k) {
  double vp[3], usum[3];
  contact_point_velocity(m, d, p, g, k->sb ? k->sb->v : ZERO3, k->sb ? k->sb->w : ZERO3, k->sa ? k->sa->v : NULL,
                         k->sa ? k->sa->w : NULL, vp);
  for (int i = 0; i < 3; i++) usum[i] = k->vrel[i];
  if (k->sa) {
    double ua[3];
    point_velocity(k->sa->v, k->sa->w, k->arm_a, ua);
    for (int i = 0; i < 3; i++) usum[i] = k->vrel[i] + 2.0 * ua[i]; /* (u_B − u_A) + 2u_A */
  }
  double v[3];
  for (int i = 0; i < 3; i++) v[i] = vp[i] - 0.5 * usum[i];
  contensou_rolling_step_f64 roll = {dot3(v, g->x), dot3(v, g->y)};
  return roll;
}

/* The wrench (N, F_x, F_y, T_z in the contact frame) of a pair: on B at P, its opposite on A. */
static void apply_wrench(const geometry* g, const kinematics* k, double n, double fx, double fy, double tz) {
  double force[3], moment[3];
  for (int i = 0; i < 3; i++) force[i] = n * g->n[i] + fx * g->x[i] + fy * g->y[i];
  if (k->sb) {
    cross3(k->arm_b, force, moment);
    for (int i = 0; i < 3; i++) {
      k->sb->force[i] += force[i];
      k->sb->torque[i] += moment[i] + tz * g->n[i];
    }
    k->sb->active = 1;
  }
  if (k->sa) {
    cross3(k->arm_a, force, moment);
    for (int i = 0; i < 3; i++) {
      k->sa->force[i] -= force[i];
      k->sa->torque[i] -= moment[i] + tz * g->n[i];
    }
    k->sa->active = 1;
  }
}

/* The plain wrench of a pair at this state (its start-of-step wrench; with `step`, at the
 * given per-step inputs instead of the pair's own kinematics). */
static contensou_status plain_wrench(const mjModel* m, const mjData* d, const instance_data* x, pair* p,
                                     const geometry* g, const kinematics* k, const contensou_step_f64* step,
                                     contensou_wrench_f64* w) {
  if (p->kind == ELLIPSOID_PLANE && g->p > 0.0) {
    /* On error (a ratio beyond the library's range) the contact keeps its last curvatures. */
    contensou_contact_set_curvatures_f64(&p->contact, g->p, g->q, NULL);
  }
  if (x->rolling) {
    contensou_rolling_step_f64 roll = rolling_velocity(m, d, p, g, k);
    return contensou_contact_wrench_rolling_f64(&p->contact, step, &roll, w, NULL);
  }
  return contensou_contact_wrench_f64(&p->contact, step, w, NULL);
}

/*
 * The step-aware path (step = aware): the pairs touching now or at the free end of the step
 * (step_prepare: u = J q̇, u_free, h_free, W with its cross blocks), grouped by the moving bodies
 * they share (W's cross blocks couple only those; groups of up to STEP_GROUP pairs, a larger group
 * split in model order without the cross blocks between its parts), each group's step-aware
 * wrenches in one call of the library, applied like the plain ones. The sensor reports the
 * step-aware wrench and the patch (a, b) of the plain wrench at the start state.
 */
#define STEP_GROUP CONTENSOU_STEP_MAX_CONTACTS
/* Block Gauss–Seidel sweeps over the parts of a group larger than STEP_GROUP (fixed count). */
#define STEP_SWEEPS 6

/* The moving body of a pair's side (−1: at rest). */
static int moving(const instance_data* x, int body) { return x->slot[body]; }

/* Do taken pairs t and j of s share a moving body? */
static int coupled(const instance_data* x, const step_work* s, int t, int j) {
  const pair* pt = &x->pairs[s->index[t]];
  const pair* pj = &x->pairs[s->index[j]];
  int a = moving(x, pj->body_a), b = moving(x, pj->body_b);
  int at = moving(x, pt->body_a), bt = moving(x, pt->body_b);
  return (a >= 0 && (a == at || a == bt)) || (b >= 0 && (b == at || b == bt));
}

/* The step-aware wrenches of the n ≤ STEP_GROUP taken pairs part[] (into x->wrench), with
 * u_free and h_free shifted by the impulse of the group's other pairs other[0..nother) (their
 * current x->wrench): Δu = Δt·W·w̄, Δh = −Δt²·(W·w̄)_n. */
static void solve_part(const mjModel* m, instance_data* x, const int* part, int n, const int* other, int nother) {
  step_work* s = &x->step;
  double dt = m->opt.timestep;
  int rows = 4 * s->count;
  const contensou_contact_f64* contacts[STEP_GROUP] = {0};
  contensou_step_f64 steps[STEP_GROUP] = {{0}};
  contensou_rolling_step_f64 rolls[STEP_GROUP] = {{0}};
  double w[16 * STEP_GROUP * STEP_GROUP] = {0}, u_free[4 * STEP_GROUP] = {0}, h_free[STEP_GROUP] = {0};
  double wrench[4 * STEP_GROUP] = {0};
  for (int i = 0; i < n; i++) {
    int t = part[i];
    contacts[i] = &x->pairs[s->index[t]].contact;
    steps[i] = x->steps[t];
    rolls[i] = x->rolls[t];
    h_free[i] = s->h_free[t];
    for (int r = 0; r < 4; r++) {
      double du = 0.0;
      for (int o = 0; o < nother; o++) {
        for (int c = 0; c < 4; c++) du += s->w[(4 * t + r) * rows + 4 * other[o] + c] * x->wrench[4 * other[o] + c];
      }
      u_free[4 * i + r] = s->u_free[4 * t + r] + dt * du;
      if (r == 0) h_free[i] -= dt * dt * du;
    }
    for (int j = 0; j < n; j++) {
      for (int r = 0; r < 4; r++) {
        for (int c = 0; c < 4; c++) w[(4 * i + r) * 4 * n + 4 * j + c] = s->w[(4 * t + r) * rows + 4 * part[j] + c];
      }
    }
  }
  int ok = !step_solve(contacts, n, dt, w, steps, x->rolling ? rolls : NULL, u_free, h_free, wrench);
  for (int i = 0; i < n; i++) {
    /* Refused (a non-finite state): no load, MuJoCo's own checks then act. */
    for (int r = 0; r < 4; r++) x->wrench[4 * part[i] + r] = ok ? wrench[4 * i + r] : 0.0;
  }
}

/* A pair of a group that the joint solve left without load although the group's impulses press
 * it into contact by the end of the step: the library decides which contacts take part from each
 * one's own predicted gap (h_free, the others' impulses not counted) and does not re-add a
 * dropped one within the step, so in a stack (a ball on a ball on the floor: the floor's
 * impulse lifts the lower ball into the upper one) the upper contact idles one step (its
 * predicted end approach h⁺ = h_free − Δt²·(W·w)_n > 0 at N = 0) and carries twice the weight
 * the next, a period-2 cycle at 1 and 2 ms. Such pairs (idle) and the others (busy) are then
 * solved as two parts, each with the other's latest impulse in its free motion (solve_part),
 * STEP_SWEEPS sweeps of block Gauss–Seidel, the idle part first. */
static void reactivate(const mjModel* m, instance_data* x, const int* group, int n) {
  step_work* s = &x->step;
  double dt = m->opt.timestep;
  int rows = 4 * s->count, idle[STEP_GROUP], busy[STEP_GROUP], ni = 0, nb = 0;
  for (int i = 0; i < n; i++) {
    int t = group[i];
    double hplus = s->h_free[t];
    for (int j = 0; j < rows; j++) hplus -= dt * dt * s->w[4 * t * rows + j] * x->wrench[j];
    if (x->wrench[4 * t] == 0.0 && hplus > 0.0) {
      idle[ni++] = t;
    } else {
      busy[nb++] = t;
    }
  }
  if (ni == 0 || nb == 0) return;
  for (int sweep = 0; sweep < STEP_SWEEPS; sweep++) {
    solve_part(m, x, idle, ni, busy, nb);
    solve_part(m, x, busy, nb, idle, ni);
  }
}

static void passive_step(const mjModel* m, mjData* d, instance_data* x) {
  begin_bodies(m, d, x);
  for (int k = 0; k < x->npair; k++) {
    geometry g;
    double* out = x->out + NOUT * k;
    memset(out, 0, sizeof(double) * NOUT);
    pair_geometry(m, d, &x->pairs[k], &g);
    out[OUT_H] = g.h;
  }
  step_work* s = &x->step;
  int count = step_prepare(m, d, x->pairs, x->npair, s);
  for (int t = 0; t < count; t++) {
    pair* p = &x->pairs[s->index[t]];
    const geometry* g = &s->geom[t];
    pair_kinematics(d, x, p, g, &x->kins[t]);
    const double* u = s->u + 4 * t;
    x->steps[t] = (contensou_step_f64){g->h, -u[0], u[1], u[2], u[3]};
    contensou_wrench_f64 plain;
    x->ab[2 * t] = x->ab[2 * t + 1] = 0.0;
    if (g->h > 0.0 && plain_wrench(m, d, x, p, g, &x->kins[t], &x->steps[t], &plain) == CONTENSOU_STATUS_OK) {
      x->ab[2 * t] = plain.a;
      x->ab[2 * t + 1] = plain.b;
    } else if (p->kind == ELLIPSOID_PLANE && g->p > 0.0) {
      contensou_contact_set_curvatures_f64(&p->contact, g->p, g->q, NULL);
    }
    x->rolls[t] = x->rolling ? rolling_velocity(m, d, p, g, &x->kins[t]) : (contensou_rolling_step_f64){0.0, 0.0};
    if (x->rolling && s->point > 0.0) {
      /* step_point θ > 0: V at the drifted pose with the free velocities (as u_free). */
      x->rolls[t] = (contensou_rolling_step_f64){s->roll[2 * t], s->roll[2 * t + 1]};
    }
    for (int r = 0; r < 4; r++) x->wrench[4 * t + r] = 0.0;
  }
  /* Groups: the taken pairs connected through shared moving bodies (W couples only those). */
  int* done = s->done;
  int* group = x->group;
  memset(done, 0, sizeof(int) * (size_t)(count > 0 ? count : 1));
  for (int first = 0; first < count; first++) {
    if (done[first]) continue;
    int n = 0;
    group[n++] = first;
    done[first] = 1;
    for (int i = 0; i < n; i++) {
      for (int j = first + 1; j < count; j++) {
        if (!done[j] && coupled(x, s, group[i], j)) {
          group[n++] = j;
          done[j] = 1;
        }
      }
    }
    if (n <= STEP_GROUP) {
      solve_part(m, x, group, n, NULL, 0);
      reactivate(m, x, group, n);
      continue;
    }
    /* A larger group: parts of STEP_GROUP pairs in order, each solved with the others' latest
     * impulse in its free motion, STEP_SWEEPS sweeps (block Gauss–Seidel on the step's system). */
    int* other = x->other;
    for (int sweep = 0; sweep < STEP_SWEEPS; sweep++) {
      for (int start = 0; start < n; start += STEP_GROUP) {
        int len = n - start < STEP_GROUP ? n - start : STEP_GROUP, nother = 0;
        for (int i = 0; i < n; i++) {
          if (i < start || i >= start + len) other[nother++] = group[i];
        }
        solve_part(m, x, group + start, len, other, nother);
      }
    }
  }
  /* N consistent with the end approach of the wrenches as returned (step_normal). */
  step_normal(x->pairs, s, m->opt.timestep, x->wrench);
  if (s->point > 0.0) {
    /* Friction passive at MuJoCo's own end velocity (the wrench acts through the start rows). */
    step_friction_at_start(m, s, x->wrench);
    step_normal(x->pairs, s, m->opt.timestep, x->wrench);
    step_friction_at_start(m, s, x->wrench);
  }
  for (int t = 0; t < count; t++) {
    double* out = x->out + NOUT * s->index[t];
    const double* f = x->wrench + 4 * t;
    out[OUT_N] = f[0];
    out[OUT_FX] = f[1];
    out[OUT_FY] = f[2];
    out[OUT_TZ] = f[3];
    out[OUT_A] = x->ab[2 * t];
    out[OUT_B] = x->ab[2 * t + 1];
    apply_wrench(&s->geom[t], &x->kins[t], f[0], f[1], f[2], f[3]);
  }
  end_bodies(m, d, x);
}

static void passive(const mjModel* m, mjData* d, instance_data* x) {
  if (x->aware) {
    passive_step(m, d, x);
    return;
  }
  begin_bodies(m, d, x);
  for (int k = 0; k < x->npair; k++) {
    pair* p = &x->pairs[k];
    double* out = x->out + NOUT * k;
    geometry g;
    int touching = pair_geometry(m, d, p, &g) == 0;
    memset(out, 0, sizeof(double) * NOUT);
    out[OUT_H] = g.h;
    if (!touching) continue;
    kinematics kin;
    pair_kinematics(d, x, p, &g, &kin);
    contensou_step_f64 step = {g.h, -dot3(kin.vrel, g.n), dot3(kin.vrel, g.x), dot3(kin.vrel, g.y),
                               dot3(kin.wrel, g.n)};
    contensou_wrench_f64 w;
    if (plain_wrench(m, d, x, p, &g, &kin, &step, &w) != CONTENSOU_STATUS_OK) {
      continue; /* a non-finite state: no load (MuJoCo's own checks then reset the state) */
    }
    out[OUT_N] = w.n;
    out[OUT_FX] = w.fx;
    out[OUT_FY] = w.fy;
    out[OUT_TZ] = w.tz;
    out[OUT_A] = w.a;
    out[OUT_B] = w.b;
    apply_wrench(&g, &kin, w.n, w.fx, w.fy, w.tz);
  }
  end_bodies(m, d, x);
}

static void sensor(const mjModel* m, mjData* d, int instance, const instance_data* x) {
  for (int j = 0; j < m->nsensor; j++) {
    if (m->sensor_type[j] == mjSENS_PLUGIN && m->sensor_plugin[j] == instance) {
      memcpy(d->sensordata + m->sensor_adr[j], x->out, sizeof(double) * NOUT * (size_t)x->npair);
    }
  }
}

static void compute(const mjModel* m, mjData* d, int instance, int capability_bit) {
  instance_data* x = (instance_data*)d->plugin_data[instance];
  if (!x) return;
  if (capability_bit & mjPLUGIN_PASSIVE) passive(m, d, x);
  if (capability_bit & mjPLUGIN_SENSOR) sensor(m, d, instance, x);
}

mjPLUGIN_LIB_INIT(contensou_contact) {
  mjpPlugin plugin;
  mjp_defaultPlugin(&plugin);
  plugin.name = PLUGIN_NAME;
  plugin.capabilityflags = mjPLUGIN_PASSIVE | mjPLUGIN_SENSOR;
  plugin.needstage = mjSTAGE_VEL;
  plugin.nattribute = NATTRIBUTE;
  plugin.attributes = ATTRIBUTES;
  plugin.nstate = nstate;
  plugin.nsensordata = nsensordata;
  plugin.init = init;
  plugin.destroy = destroy;
  plugin.copy = copy;
  plugin.reset = reset;
  plugin.compute = compute;
  mjp_registerPlugin(&plugin);
}
