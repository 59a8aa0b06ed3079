/*
 * contensou.contact (MuJoCo engine plugin): the types shared by its three files —
 * config.c (the configuration and the model's checks, refusals at load), pairs.c (the contact
 * pairs of a model and their geometry per step), plugin.c (the mjpPlugin: lifecycle, passive
 * forces, sensor). Overview in plugin.c and mujoco/README.md.
 */
#ifndef CONTENSOU_MUJOCO_H
#define CONTENSOU_MUJOCO_H

#include <mujoco/mujoco.h>

#include "contensou.h"

#define PLUGIN_NAME "contensou.contact"

/* Values per pair in the sensor: N, Fx, Fy, Tz, a, b, h. */
enum { OUT_N, OUT_FX, OUT_FY, OUT_TZ, OUT_A, OUT_B, OUT_H, NOUT };

enum pair_kind { SPHERE_PLANE, ELLIPSOID_PLANE, SPHERE_SPHERE };
enum form_choice { FORM_AUTO, FORM_FIXED, FORM_VARYING };

typedef struct {
  int kind;
  int geom_a;    /* the plane, or A's sphere */
  int geom_b;    /* the plugin body's geom */
  int body_a;    /* geom_a's body (0: the world) */
  int body_b;
  double offset; /* capsule: the end sphere's centre at ±half-length along the geom's z */
  double radius; /* sphere, capsule: r (of B); sphere–sphere: r_b */
  double radius_a;
  contensou_contact_f64 contact; /* caller-owned storage of the C API */
} pair;

typedef struct {
  contensou_spec_f64 spec; /* estar, cd, f, delta (P, Q per pair) */
  contensou_law law;
  int form;
  int rolling;         /* a rolling law (table, blend, fastsim, fastsim-16): G, ν and V are used */
  int has_g, has_nu;   /* G, ν given (or from the materials); else the library's defaults */
  double shear, poisson; /* G (Pa), ν of the pair (rolling laws) */
  int step_aware;        /* step = aware: the step-aware wrench for MuJoCo's timestep */
  double step_point;     /* step_point θ ∈ [0, 1] (step-aware): where u_free is taken (default 0) */
} config;

/* The geometry of one pair at this state: approach h, patch centre, contact frame (n from A
 * to B, x the major axis, y = n × x); for an ellipsoid also P ≤ Q (0: degenerate). */
typedef struct {
  double h;
  double point[3];
  double n[3], x[3], y[3];
  double p, q;
  /* For the velocity of the geometric contact point (contact_point_velocity): sphere–plane:
   * B's sphere centre; ellipsoid–plane: the support point x* (world), u = −n and x* in the geom
   * frame, 1/s; sphere–sphere: the centres and s/|c_b − c_a| (P = c_a + s n). */
  double centre[3];
  double u[3], xl[3], inv_s;
  double centre_a[3], ratio;
} geometry;

/*------------------------------------------------------------------------ small vector maths */

static inline double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* v + w × r in the operation order of floor_contact.py (vx + wy*az − wz*ay, …). */
static inline void point_velocity(const double v[3], const double w[3], const double r[3], double out[3]) {
  out[0] = v[0] + w[1] * r[2] - w[2] * r[1];
  out[1] = v[1] + w[2] * r[0] - w[0] * r[2];
  out[2] = v[2] + w[0] * r[1] - w[1] * r[0];
}

static inline void cross3(const double a[3], const double b[3], double out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

/* A geom type the plugin computes contacts of. */
static inline int is_supported(int type) {
  return type == mjGEOM_SPHERE || type == mjGEOM_CAPSULE || type == mjGEOM_ELLIPSOID;
}

/* config.c */
/* The validated configuration of instance; −1 after a warning naming attribute and value. */
int read_config(const mjModel* m, int instance, config* c);
/* The plugin bodies' geoms and their pairs are computable and not also native; else −1 + warning. */
int check_geoms(const mjModel* m, int instance, const pair* pairs, int npair);
const char* geom_name(const mjModel* m, int g);
/* A rolling law (table, blend, fastsim, fastsim-16)? */
int is_rolling(contensou_law law);
/* A contact of c's law (and, for a rolling law, its G, ν) on spec (P, Q set) in form. */
contensou_status new_contact(contensou_contact_f64* storage, const config* c, const contensou_spec_f64* spec,
                             contensou_form form, contensou_column* column);

/* pairs.c */
/* The pairs of instance in their fixed order (written to out unless NULL); their count. */
int enumerate_pairs(const mjModel* m, int instance, pair* out);
/* P ≤ Q of ellipsoid geom g resting on its −z pole (construction-time curvatures). */
void ellipsoid_rest(const mjModel* m, int g, double* p, double* q);
/* The geometry of pair k at the state of d; 0 if they touch (h > 0), −1 if apart (then h < 0
 * is the gap, the rest filled as well, except for two sphere centres at the same point). */
int pair_geometry(const mjModel* m, const mjData* d, const pair* k, geometry* g);
/* The same at the geoms' poses geom_xpos (3 per geom), geom_xmat (9 per geom, row-major). */
int pair_geometry_at(const mjModel* m, const mjtNum* geom_xpos, const mjtNum* geom_xmat, const pair* k,
                     geometry* g);
/* The velocity (world) of the geometric contact point P of pair k at geometry g: how P moves
 * as the bodies move (not a material velocity). vb, wb: B's origin velocity and ω; va, wa: A's
 * (NULL: A at rest). Only its tangential part is meaningful (the normal part is not computed). */
void contact_point_velocity(const mjModel* m, const mjData* d, const pair* k, const geometry* g,
                            const double vb[3], const double wb[3], const double* va, const double* wa,
                            double out[3]);
/* The same with the bodies' origins xpos (3 per body) and the geoms' attitudes geom_xmat (9 per
 * geom) of another pose (the step-aware path's drifted pose). */
void contact_point_velocity_at(const mjModel* m, const mjtNum* xpos, const mjtNum* geom_xmat, const pair* k,
                               const geometry* g, const double vb[3], const double wb[3], const double* va,
                               const double* wa, double out[3]);

/* inverse_mass.c */
/* The 4 × nv rows (n, x, y, spin) of the contact velocity u = J q̇ of pair k at geometry g
 * (B relative to A at the patch centre); scratch: 6 × nv values. */
void contact_jacobian(const mjModel* m, const mjData* d, const pair* k, const geometry* g, mjtNum* jac,
                      mjtNum* scratch);
/* W = J M⁻¹ Jᵀ (rows × rows, row-major) of the stacked rows jac (rows × nv) by mj_solveM;
 * work: rows × nv values. */
void inverse_mass(const mjModel* m, mjData* d, const mjtNum* jac, int rows, mjtNum* work, mjtNum* w);

/* step_aware.c: what the step-aware wrench needs from MuJoCo, per instance and evaluation. */
typedef struct {
  int cap;          /* pairs of the instance */
  int count;        /* pairs taken this evaluation (touching, or closing within the step) */
  int* index;       /* their pair indices */
  geometry* geom;   /* their geometry (index order) */
  double* u;        /* 4 per pair taken: (v_n, v_x, v_y, ω) = J q̇ */
  double* u_free;   /* 4 per pair taken: J q̇_free, the end-of-step velocity without the instance */
  double* h_free;   /* per pair taken: the approach at the free end-of-step pose (q drifted by Δt·q̇_free) */
  double* roll;     /* 2 per pair taken (step_point θ > 0): Kalker's rolling velocity (V_x, V_y) at the
                       pose drifted by θ·Δt with the free velocities, in that pose's contact frame */
  mjtNum* geom_xpos; /* that pose of every geom, 3 per geom */
  mjtNum* geom_xmat; /* 9 per geom */
  int* done;        /* scratch, per pair */
  double point;     /* step_point θ: u_free at the contact point and frame of the pose drifted by θ·Δt */
  mjtNum* body_v;   /* per body: the free end velocity of its origin (3), */
  mjtNum* body_w;   /* its ω (3), */
  mjtNum* body_p;   /* its origin drifted by θ·Δt (3) */
  mjtNum* body_jac; /* per body: mj_jac at its origin at this state (6 × nv; drift_pose) */
  mjtNum* w;        /* W = J M⁻¹ Jᵀ, 4·count × 4·count, row-major, cross blocks included */
  mjtNum* jac;      /* J, 4·cap × nv */
  mjtNum* work;     /* 4·cap × nv */
  mjtNum* scratch;  /* 6 × nv */
  mjtNum* qfrc;     /* nv */
  mjtNum* qvel;     /* q̇_free, nv */
} step_work;

/* Buffers for npair pairs of model m, u_free at step_point θ; −1 if memory is short (then
 * nothing is held). */
int step_work_init(step_work* s, const mjModel* m, int npair, double point);
void step_work_free(step_work* s);
/* Fills s for the state of d (position and velocity stages done): the pairs that touch now or
 * at the free end-of-step pose (h_free > 0); their count. */
int step_prepare(const mjModel* m, mjData* d, const pair* pairs, int npair, step_work* s);

/* Each taken pair's N (wrench: 4 per pair taken) re-solved, the other rows fixed, where it is not
 * the normal law's value at the end approach and velocity the wrenches give (step_aware.c). */
void step_normal(const pair* pairs, const step_work* s, double dt, double* wrench);
/* With step_point θ > 0: each taken pair's friction scaled so that it does no work at the end
 * velocity MuJoCo's update gives the start rows J (step_aware.c). */
void step_friction_at_start(const mjModel* m, const step_work* s, double* wrench);

/* The step-aware wrenches (4 per contact, contact frame) of k ≤ CONTENSOU_STEP_MAX_CONTACTS
 * contacts sharing W (4k × 4k, row-major) over dt, from their start steps, rolling velocities
 * (NULL: none), free end velocities u_free (4k) and approaches h_free (k), by
 * contensou_step_many_f64; 0, or −1 if the library refused. */
int step_solve(const contensou_contact_f64* const* contacts, int k, double dt, const double* w,
               const contensou_step_f64* steps, const contensou_rolling_step_f64* rolling, const double* u_free,
               const double* h_free, double* out);

#endif /* CONTENSOU_MUJOCO_H */
