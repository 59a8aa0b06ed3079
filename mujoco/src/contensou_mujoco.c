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
 * Per pair and step (docs/mujoco.md, "Geometry"):
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
 * ellipsoid|coulomb, default best); form (auto|fixed|varying, default auto: fixed for spheres
 * and capsules, varying for ellipsoids). A bad value, an unsupported geom, or a plugin geom that
 * MuJoCo would also collide with a plane (contype/conaffinity) refuses the model at load:
 * init() warns with the attribute and the value and returns −1, which the compiler turns into
 * the load error.
 *
 * Sensor (<sensor><plugin instance="…"/></sensor>): per pair, in the order above, the seven
 * values N, F_x, F_y, T_z, a, b, h (contact frame; zeros but h when apart).
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <mujoco/mujoco.h>

#include "contensou.h"

#define PLUGIN_NAME "contensou.contact"

/* Values per pair in the sensor: N, Fx, Fy, Tz, a, b, h. */
enum { OUT_N, OUT_FX, OUT_FY, OUT_TZ, OUT_A, OUT_B, OUT_H, NOUT };

enum pair_kind { SPHERE_PLANE, ELLIPSOID_PLANE, SPHERE_SPHERE };
enum form_choice { FORM_AUTO, FORM_FIXED, FORM_VARYING };

static const char* const ATTRIBUTES[] = {"estar", "young1", "poisson1", "young2", "poisson2",
                                         "cd",    "f",      "delta",    "law",    "form"};
#define NATTRIBUTE ((int)(sizeof(ATTRIBUTES) / sizeof(ATTRIBUTES[0])))

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

/* A body's velocity this step: ω (world) and the velocity of its origin xpos (world). */
typedef struct {
  double w[3];
  double v[3];
  double force[3];
  double torque[3]; /* about xpos */
  int active;
} body_state;

typedef struct {
  int npair;
  pair* pairs;
  double* out;       /* NOUT per pair */
  int nbody;         /* bodies that move and take loads (not welded to the world) */
  int* bodies;       /* their ids */
  body_state* state; /* per entry of bodies */
  int* slot;         /* model body id → index into bodies, −1 */
} instance_data;

/*------------------------------------------------------------------------ small vector maths */

static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* v + w × r in the operation order of floor_contact.py (vx + wy*az − wz*ay, …). */
static void point_velocity(const double v[3], const double w[3], const double r[3], double out[3]) {
  out[0] = v[0] + w[1] * r[2] - w[2] * r[1];
  out[1] = v[1] + w[2] * r[0] - w[0] * r[2];
  out[2] = v[2] + w[0] * r[1] - w[1] * r[0];
}

static void cross3(const double a[3], const double b[3], double out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

/* A unit vector perpendicular to the unit vector n. */
static void any_tangent(const double n[3], double t[3]) {
  double a[3] = {0, 0, 0};
  double ax = fabs(n[0]), ay = fabs(n[1]), az = fabs(n[2]);
  a[(ax <= ay && ax <= az) ? 0 : (ay <= az ? 1 : 2)] = 1.0;
  double d = dot3(a, n);
  for (int i = 0; i < 3; i++) t[i] = a[i] - d * n[i];
  double len = sqrt(dot3(t, t));
  for (int i = 0; i < 3; i++) t[i] /= len;
}

/*
 * P ≤ Q and the major axis (cos θ, sin θ) of z = mxx x² + 2 mxy x y + myy y²: the C twin of
 * contensou::geometry::Curvatures::from_quadratic (same formula and branches; the Rust
 * function is not in the C API). Returns 0, or −1 if the form is not positive definite.
 */
static int quadratic_form(double mxx, double myy, double mxy, double* p, double* q,
                          double* major_cos, double* major_sin) {
  double d = 0.5 * (mxx - myy);
  double big = fmax(fabs(d), fabs(mxy));
  double dn = 0.0, mn = 0.0;
  if (big > 0.0) {
    dn = d / big;
    mn = mxy / big;
  }
  double rn = sqrt(dn * dn + mn * mn);
  double qq = 0.5 * (mxx + myy) + big * rn;
  if (!(qq > 0.0) || !isfinite(qq)) return -1;
  double pp = (mxx * myy - mxy * mxy) / qq;
  if (!(pp > 0.0) || !isfinite(pp)) return -1;
  if (rn > 0.0) {
    if (dn <= 0.0) {
      double ct = sqrt(0.5 * (rn - dn) / rn);
      *major_cos = ct;
      *major_sin = -mn / (2.0 * rn * ct);
    } else {
      double st = sqrt(0.5 * (rn + dn) / rn);
      if (mn > 0.0) st = -st;
      *major_cos = -mn / (2.0 * rn * st);
      *major_sin = st;
    }
  } else {
    *major_cos = 1.0;
    *major_sin = 0.0;
  }
  *p = fmin(pp, qq);
  *q = qq;
  return 0;
}

/*------------------------------------------------------------------------- pairs of a model */

static int is_supported(int type) {
  return type == mjGEOM_SPHERE || type == mjGEOM_CAPSULE || type == mjGEOM_ELLIPSOID;
}

/*
 * Enumerates the pairs of `instance` in their fixed order (plugin bodies in model order; each
 * geom of a body against each plane in model order, a capsule's −z end then +z end; then
 * sphere–sphere pairs between plugin bodies); writes them to `out` if not NULL; returns the
 * count. Unsupported geoms are skipped here (init refuses them).
 */
static int enumerate_pairs(const mjModel* m, int instance, pair* out) {
  int n = 0;
  for (int b = 1; b < m->nbody; b++) {
    if (m->body_plugin[b] != instance) continue;
    for (int g = m->body_geomadr[b]; g >= 0 && g < m->body_geomadr[b] + m->body_geomnum[b]; g++) {
      int type = m->geom_type[g];
      if (!is_supported(type)) continue;
      for (int p = 0; p < m->ngeom; p++) {
        if (m->geom_type[p] != mjGEOM_PLANE || m->geom_bodyid[p] == b) continue;
        int ends = type == mjGEOM_CAPSULE ? 2 : 1;
        for (int e = 0; e < ends; e++) {
          if (out) {
            pair* k = &out[n];
            memset(k, 0, sizeof(*k));
            k->kind = type == mjGEOM_ELLIPSOID ? ELLIPSOID_PLANE : SPHERE_PLANE;
            k->geom_a = p;
            k->geom_b = g;
            k->body_a = m->geom_bodyid[p];
            k->body_b = b;
            k->radius = m->geom_size[3 * g];
            k->offset = type == mjGEOM_CAPSULE ? (e ? 1.0 : -1.0) * m->geom_size[3 * g + 1] : 0.0;
          }
          n++;
        }
      }
    }
  }
  for (int ba = 1; ba < m->nbody; ba++) {
    if (m->body_plugin[ba] != instance) continue;
    for (int bb = ba + 1; bb < m->nbody; bb++) {
      if (m->body_plugin[bb] != instance) continue;
      for (int ga = m->body_geomadr[ba]; ga >= 0 && ga < m->body_geomadr[ba] + m->body_geomnum[ba]; ga++) {
        if (m->geom_type[ga] != mjGEOM_SPHERE) continue;
        for (int gb = m->body_geomadr[bb]; gb >= 0 && gb < m->body_geomadr[bb] + m->body_geomnum[bb]; gb++) {
          if (m->geom_type[gb] != mjGEOM_SPHERE) continue;
          if (out) {
            pair* k = &out[n];
            memset(k, 0, sizeof(*k));
            k->kind = SPHERE_SPHERE;
            k->geom_a = ga;
            k->geom_b = gb;
            k->body_a = ba;
            k->body_b = bb;
            k->radius_a = m->geom_size[3 * ga];
            k->radius = m->geom_size[3 * gb];
          }
          n++;
        }
      }
    }
  }
  return n;
}

/*--------------------------------------------------------------------------- configuration */

typedef struct {
  contensou_spec_f64 spec; /* estar, cd, f, delta (P, Q per pair) */
  contensou_law law;
  int form;
} config;

static const char* geom_name(const mjModel* m, int g) {
  const char* s = mj_id2name(m, mjOBJ_GEOM, g);
  return s ? s : "(unnamed)";
}

static const char* body_name(const mjModel* m, int b) {
  const char* s = mj_id2name(m, mjOBJ_BODY, b);
  return s ? s : "(unnamed)";
}

static const char* type_name(int type) {
  switch (type) {
    case mjGEOM_PLANE: return "plane";
    case mjGEOM_HFIELD: return "hfield";
    case mjGEOM_SPHERE: return "sphere";
    case mjGEOM_CAPSULE: return "capsule";
    case mjGEOM_ELLIPSOID: return "ellipsoid";
    case mjGEOM_CYLINDER: return "cylinder";
    case mjGEOM_BOX: return "box";
    case mjGEOM_MESH: return "mesh";
    case mjGEOM_SDF: return "sdf";
    default: return "other";
  }
}

static const char* config_value(const mjModel* m, int instance, const char* key) {
  const char* s = mj_getPluginConfig(m, instance, key);
  return (s && *s) ? s : NULL;
}

/* A finite number, or the default when absent; −1 (with a warning) when not a number. */
static int config_number(const mjModel* m, int instance, const char* key, int required,
                         double fallback, double* out) {
  const char* s = config_value(m, instance, key);
  if (!s) {
    if (required) {
      mju_warning(PLUGIN_NAME ": attribute '%s' is required", key);
      return -1;
    }
    *out = fallback;
    return 0;
  }
  char* end = NULL;
  errno = 0;
  double v = strtod(s, &end);
  while (end && (*end == ' ' || *end == '\t')) end++;
  if (end == s || !end || *end || errno == ERANGE || !isfinite(v)) {
    mju_warning(PLUGIN_NAME ": %s = '%s' is not a finite number", key, s);
    return -1;
  }
  *out = v;
  return 0;
}

/* The configuration of `instance`, validated by the library; −1 with a warning naming the
 * attribute and its value. */
static int read_config(const mjModel* m, int instance, config* c) {
  memset(c, 0, sizeof(*c));
  const char* estar = config_value(m, instance, "estar");
  const char* materials[4] = {"young1", "poisson1", "young2", "poisson2"};
  int nmaterial = 0;
  for (int i = 0; i < 4; i++) nmaterial += config_value(m, instance, materials[i]) != NULL;
  if (estar && nmaterial) {
    mju_warning(PLUGIN_NAME ": give either estar (= '%s') or young1, poisson1, young2, poisson2, not both",
                estar);
    return -1;
  }
  if (estar) {
    if (config_number(m, instance, "estar", 1, 0, &c->spec.estar)) return -1;
  } else if (nmaterial == 4) {
    double e[4];
    for (int i = 0; i < 4; i++) {
      if (config_number(m, instance, materials[i], 1, 0, &e[i])) return -1;
    }
    contensou_status s = contensou_modulus_of_f64(e[0], e[1], e[2], e[3], &c->spec.estar);
    if (s != CONTENSOU_STATUS_OK) {
      mju_warning(PLUGIN_NAME ": young1 = %g, poisson1 = %g, young2 = %g, poisson2 = %g: %s", e[0], e[1],
                  e[2], e[3], contensou_status_message(s));
      return -1;
    }
  } else {
    mju_warning(PLUGIN_NAME ": attribute 'estar' (or all of young1, poisson1, young2, poisson2) is required");
    return -1;
  }
  if (config_number(m, instance, "f", 1, 0, &c->spec.f)) return -1;
  if (config_number(m, instance, "cd", 0, 0.0, &c->spec.cd)) return -1;
  if (config_number(m, instance, "delta", 0, 1e-4, &c->spec.delta)) return -1;

  const char* law = config_value(m, instance, "law");
  c->law = CONTENSOU_LAW_BEST;
  if (law && contensou_law_from_name(law, &c->law) != CONTENSOU_STATUS_OK) {
    mju_warning(PLUGIN_NAME ": law = '%s' is no law (best, simplified, pade, ellipsoid, coulomb)", law);
    return -1;
  }
  const char* form = config_value(m, instance, "form");
  c->form = FORM_AUTO;
  if (form) {
    if (!strcmp(form, "auto")) c->form = FORM_AUTO;
    else if (!strcmp(form, "fixed")) c->form = FORM_FIXED;
    else if (!strcmp(form, "varying")) c->form = FORM_VARYING;
    else {
      mju_warning(PLUGIN_NAME ": form = '%s' is no form (auto, fixed, varying)", form);
      return -1;
    }
  }
  /* The library validates estar, cd, f, delta: build a sphere contact to learn its verdict. */
  contensou_spec_f64 probe = c->spec;
  probe.p = probe.q = 1.0;
  contensou_column column = CONTENSOU_COLUMN_NONE;
  contensou_contact_f64 storage;
  contensou_status s = contensou_contact_new_f64(&storage, &probe, c->law, CONTENSOU_FORM_FIXED, &column);
  if (s != CONTENSOU_STATUS_OK) {
    const char* key = contensou_column_name(column);
    double value = column == CONTENSOU_COLUMN_ESTAR ? c->spec.estar
                 : column == CONTENSOU_COLUMN_CD    ? c->spec.cd
                 : column == CONTENSOU_COLUMN_F     ? c->spec.f
                 : column == CONTENSOU_COLUMN_DELTA ? c->spec.delta
                                                    : NAN;
    mju_warning(PLUGIN_NAME ": %s = %g: %s", *key ? key : "configuration", value, contensou_status_message(s));
    return -1;
  }
  return 0;
}

/* Would MuJoCo's own collision also act between geoms a and b? */
static int collides_natively(const mjModel* m, int a, int b) {
  return (m->geom_contype[a] & m->geom_conaffinity[b]) || (m->geom_contype[b] & m->geom_conaffinity[a]);
}

/* The geoms of the plugin bodies: supported types (only spheres when the instance has several
 * bodies), native contact off against their partners. */
static int check_geoms(const mjModel* m, int instance, const pair* pairs, int npair) {
  int nbody = 0;
  for (int b = 1; b < m->nbody; b++) nbody += m->body_plugin[b] == instance;
  if (nbody == 0) {
    mju_warning(PLUGIN_NAME ": instance %d is attached to no body (<body><plugin instance=\"...\"/>)", instance);
    return -1;
  }
  for (int b = 1; b < m->nbody; b++) {
    if (m->body_plugin[b] != instance) continue;
    if (m->body_geomnum[b] == 0) {
      mju_warning(PLUGIN_NAME ": body '%s' has no geom (sphere, capsule or ellipsoid)", body_name(m, b));
      return -1;
    }
    for (int g = m->body_geomadr[b]; g < m->body_geomadr[b] + m->body_geomnum[b]; g++) {
      int type = m->geom_type[g];
      if (!is_supported(type)) {
        mju_warning(PLUGIN_NAME ": geom '%s' of body '%s' is a %s: unsupported geom type "
                    "(sphere, capsule, ellipsoid; move other geoms to a child body without the plugin)",
                    geom_name(m, g), body_name(m, b), type_name(type));
        return -1;
      }
      if (nbody > 1 && type != mjGEOM_SPHERE) {
        mju_warning(PLUGIN_NAME ": geom '%s' of body '%s' is a %s: between the bodies of one instance only "
                    "sphere-sphere contact is supported (give the bodies separate instances)",
                    geom_name(m, g), body_name(m, b), type_name(type));
        return -1;
      }
    }
  }
  for (int k = 0; k < npair; k++) {
    if (collides_natively(m, pairs[k].geom_a, pairs[k].geom_b)) {
      mju_warning(PLUGIN_NAME ": geom '%s' would also collide natively with '%s' (contype/conaffinity): set "
                  "contype=\"0\" conaffinity=\"0\" on the plugin body's geoms (or disjoint bits)",
                  geom_name(m, pairs[k].geom_b), geom_name(m, pairs[k].geom_a));
      return -1;
    }
  }
  return 0;
}

/*-------------------------------------------------------------------------------- lifecycle */

static void free_instance(instance_data* x) {
  if (!x) return;
  free(x->pairs);
  free(x->out);
  free(x->bodies);
  free(x->state);
  free(x->slot);
  free(x);
}

/* P ≤ Q of an ellipsoid resting on its −z pole (the construction-time curvatures). */
static void ellipsoid_rest(const mjModel* m, int g, double* p, double* q) {
  const mjtNum* a = m->geom_size + 3 * g;
  double k1 = 0.5 * a[2] / (a[0] * a[0]), k2 = 0.5 * a[2] / (a[1] * a[1]);
  *p = fmin(k1, k2);
  *q = fmax(k1, k2);
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
  enumerate_pairs(m, instance, x->pairs);
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
      s = contensou_contact_new_f64(&p->contact, &spec, c.law,
                                    varying ? CONTENSOU_FORM_VARYING : CONTENSOU_FORM_FIXED, &column);
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

/*------------------------------------------------------------------------------ per step */

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

/* The geometry of one pair at this state: approach h, patch centre, contact frame (n from A
 * to B, x the major axis, y = n × x); for an ellipsoid also P ≤ Q. Returns 0 if they touch. */
typedef struct {
  double h;
  double point[3];
  double n[3], x[3], y[3];
  double p, q;
} geometry;

static void sphere_centre(const mjData* d, const pair* k, double c[3]) {
  const mjtNum* xp = d->geom_xpos + 3 * k->geom_b;
  if (k->offset == 0.0) {
    c[0] = xp[0];
    c[1] = xp[1];
    c[2] = xp[2];
  } else {
    const mjtNum* r = d->geom_xmat + 9 * k->geom_b; /* geom z axis: column 2 */
    c[0] = xp[0] + k->offset * r[2];
    c[1] = xp[1] + k->offset * r[5];
    c[2] = xp[2] + k->offset * r[8];
  }
}

static int pair_geometry(const mjModel* m, const mjData* d, const pair* k, geometry* g) {
  if (k->kind == SPHERE_SPHERE) {
    const mjtNum* ca = d->geom_xpos + 3 * k->geom_a;
    const mjtNum* cb = d->geom_xpos + 3 * k->geom_b;
    double dv[3] = {cb[0] - ca[0], cb[1] - ca[1], cb[2] - ca[2]};
    double dist = sqrt(dot3(dv, dv));
    g->h = k->radius_a + k->radius - dist;
    if (g->h <= 0.0 || !(dist > 0.0)) return -1;
    for (int i = 0; i < 3; i++) g->n[i] = dv[i] / dist;
    double s = k->radius_a - g->h * k->radius / (k->radius_a + k->radius);
    for (int i = 0; i < 3; i++) g->point[i] = ca[i] + s * g->n[i];
    any_tangent(g->n, g->x);
    cross3(g->n, g->x, g->y);
    return 0;
  }
  const mjtNum* p0 = d->geom_xpos + 3 * k->geom_a;
  const mjtNum* pm = d->geom_xmat + 9 * k->geom_a; /* plane frame: columns x, y, normal */
  double n[3] = {pm[2], pm[5], pm[8]};
  double t1[3] = {pm[0], pm[3], pm[6]};
  double t2[3] = {pm[1], pm[4], pm[7]};
  for (int i = 0; i < 3; i++) g->n[i] = n[i];
  if (k->kind == SPHERE_PLANE) {
    double c[3];
    sphere_centre(d, k, c);
    double rel[3] = {c[0] - p0[0], c[1] - p0[1], c[2] - p0[2]};
    double dist = dot3(rel, n);
    g->h = k->radius - dist;
    if (g->h <= 0.0) return -1;
    for (int i = 0; i < 3; i++) {
      g->point[i] = c[i] - dist * n[i];
      g->x[i] = t1[i];
      g->y[i] = t2[i];
    }
    return 0;
  }
  /* Ellipsoid: the support point in the direction −n (geom frame), closed form. */
  const mjtNum* a = m->geom_size + 3 * k->geom_b;
  const mjtNum* r = d->geom_xmat + 9 * k->geom_b; /* geom → world, row-major */
  const mjtNum* c = d->geom_xpos + 3 * k->geom_b;
  double a2[3] = {a[0] * a[0], a[1] * a[1], a[2] * a[2]};
  double u[3], l1[3], l2[3];
  for (int i = 0; i < 3; i++) {
    u[i] = -(r[i] * n[0] + r[3 + i] * n[1] + r[6 + i] * n[2]);
    l1[i] = r[i] * t1[0] + r[3 + i] * t1[1] + r[6 + i] * t1[2];
    l2[i] = r[i] * t2[0] + r[3 + i] * t2[1] + r[6 + i] * t2[2];
  }
  double s = sqrt(a2[0] * u[0] * u[0] + a2[1] * u[1] * u[1] + a2[2] * u[2] * u[2]);
  double xl[3] = {a2[0] * u[0] / s, a2[1] * u[1] / s, a2[2] * u[2] / s};
  double xw[3];
  for (int i = 0; i < 3; i++) xw[i] = c[i] + r[3 * i] * xl[0] + r[3 * i + 1] * xl[1] + r[3 * i + 2] * xl[2];
  double rel[3] = {xw[0] - p0[0], xw[1] - p0[1], xw[2] - p0[2]};
  double dist = dot3(rel, n);
  g->h = -dist;
  if (g->h <= 0.0) return -1;
  for (int i = 0; i < 3; i++) g->point[i] = xw[i] - dist * n[i];
  double half = 0.5 * s, cs, sn;
  double mxx = half * (l1[0] * l1[0] / a2[0] + l1[1] * l1[1] / a2[1] + l1[2] * l1[2] / a2[2]);
  double myy = half * (l2[0] * l2[0] / a2[0] + l2[1] * l2[1] / a2[1] + l2[2] * l2[2] / a2[2]);
  double mxy = half * (l1[0] * l2[0] / a2[0] + l1[1] * l2[1] / a2[1] + l1[2] * l2[2] / a2[2]);
  if (quadratic_form(mxx, myy, mxy, &g->p, &g->q, &cs, &sn)) {
    g->p = g->q = 0.0; /* degenerate: keep the contact's last curvatures */
    cs = 1.0;
    sn = 0.0;
  }
  for (int i = 0; i < 3; i++) g->x[i] = cs * t1[i] + sn * t2[i];
  cross3(g->n, g->x, g->y);
  return 0;
}

static void passive(const mjModel* m, mjData* d, instance_data* x) {
  for (int i = 0; i < x->nbody; i++) {
    body_state* s = &x->state[i];
    body_velocity(m, d, x->bodies[i], s);
    memset(s->force, 0, sizeof(s->force));
    memset(s->torque, 0, sizeof(s->torque));
    s->active = 0;
  }
  for (int k = 0; k < x->npair; k++) {
    pair* p = &x->pairs[k];
    double* out = x->out + NOUT * k;
    geometry g;
    int touching = pair_geometry(m, d, p, &g) == 0;
    memset(out, 0, sizeof(double) * NOUT);
    out[OUT_H] = g.h;
    if (!touching) continue;
    if (p->kind == ELLIPSOID_PLANE && g.p > 0.0) {
      /* On error (a ratio beyond the library's range) the contact keeps its last curvatures. */
      contensou_contact_set_curvatures_f64(&p->contact, g.p, g.q, NULL);
    }
    /* A body welded to the world (no slot) is at rest and takes no load. */
    body_state* sb = x->slot[p->body_b] >= 0 ? &x->state[x->slot[p->body_b]] : NULL;
    body_state* sa = x->slot[p->body_a] >= 0 ? &x->state[x->slot[p->body_a]] : NULL;
    const mjtNum* ob = d->xpos + 3 * p->body_b;
    double arm_b[3] = {g.point[0] - ob[0], g.point[1] - ob[1], g.point[2] - ob[2]};
    double vrel[3] = {0, 0, 0}, wrel[3] = {0, 0, 0};
    if (sb) {
      point_velocity(sb->v, sb->w, arm_b, vrel);
      memcpy(wrel, sb->w, sizeof(wrel));
    }
    double arm_a[3] = {0, 0, 0};
    if (sa) {
      const mjtNum* oa = d->xpos + 3 * p->body_a;
      double va[3];
      for (int i = 0; i < 3; i++) arm_a[i] = g.point[i] - oa[i];
      point_velocity(sa->v, sa->w, arm_a, va);
      for (int i = 0; i < 3; i++) {
        vrel[i] -= va[i];
        wrel[i] -= sa->w[i];
      }
    }
    contensou_step_f64 step = {g.h, -dot3(vrel, g.n), dot3(vrel, g.x), dot3(vrel, g.y), dot3(wrel, g.n)};
    contensou_wrench_f64 w;
    if (contensou_contact_wrench_f64(&p->contact, &step, &w, NULL) != CONTENSOU_STATUS_OK) {
      continue; /* a non-finite state: no load (MuJoCo's own checks then reset the state) */
    }
    out[OUT_N] = w.n;
    out[OUT_FX] = w.fx;
    out[OUT_FY] = w.fy;
    out[OUT_TZ] = w.tz;
    out[OUT_A] = w.a;
    out[OUT_B] = w.b;
    double force[3], moment[3];
    for (int i = 0; i < 3; i++) force[i] = w.n * g.n[i] + w.fx * g.x[i] + w.fy * g.y[i];
    if (sb) {
      cross3(arm_b, force, moment);
      for (int i = 0; i < 3; i++) {
        sb->force[i] += force[i];
        sb->torque[i] += moment[i] + w.tz * g.n[i];
      }
      sb->active = 1;
    }
    if (sa) {
      cross3(arm_a, force, moment);
      for (int i = 0; i < 3; i++) {
        sa->force[i] -= force[i];
        sa->torque[i] -= moment[i] + w.tz * g.n[i];
      }
      sa->active = 1;
    }
  }
  for (int i = 0; i < x->nbody; i++) {
    body_state* s = &x->state[i];
    if (s->active) {
      int b = x->bodies[i];
      mj_applyFT(m, d, s->force, s->torque, d->xpos + 3 * b, b, d->qfrc_passive);
    }
  }
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
