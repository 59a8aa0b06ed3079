/*
 * contensou.contact: the contact pairs of a model (their fixed order is the sensor's) and, per
 * evaluation, each pair's geometry in closed form: approach, patch centre, contact frame and,
 * for an ellipsoid, the curvatures P ≤ Q (mujoco/README.md, "What it computes").
 */
#include <math.h>
#include <string.h>

#include "contensou_mujoco.h"

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

/*
 * Enumerates the pairs of `instance` in their fixed order (plugin bodies in model order; each
 * geom of a body against each plane in model order, a capsule's −z end then +z end; then
 * sphere–sphere pairs between plugin bodies); writes them to `out` if not NULL; returns the
 * count. Unsupported geoms are skipped here (init refuses them).
 */
int enumerate_pairs(const mjModel* m, int instance, pair* out) {
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

/* P ≤ Q of an ellipsoid resting on its −z pole (the construction-time curvatures). */
void ellipsoid_rest(const mjModel* m, int g, double* p, double* q) {
  const mjtNum* a = m->geom_size + 3 * g;
  double k1 = 0.5 * a[2] / (a[0] * a[0]), k2 = 0.5 * a[2] / (a[1] * a[1]);
  *p = fmin(k1, k2);
  *q = fmax(k1, k2);
}

static void sphere_centre(const mjtNum* geom_xpos, const mjtNum* geom_xmat, const pair* k, double c[3]) {
  const mjtNum* xp = geom_xpos + 3 * k->geom_b;
  if (k->offset == 0.0) {
    c[0] = xp[0];
    c[1] = xp[1];
    c[2] = xp[2];
  } else {
    const mjtNum* r = geom_xmat + 9 * k->geom_b; /* geom z axis: column 2 */
    c[0] = xp[0] + k->offset * r[2];
    c[1] = xp[1] + k->offset * r[5];
    c[2] = xp[2] + k->offset * r[8];
  }
}

int pair_geometry(const mjModel* m, const mjData* d, const pair* k, geometry* g) {
  return pair_geometry_at(m, d->geom_xpos, d->geom_xmat, k, g);
}

int pair_geometry_at(const mjModel* m, const mjtNum* geom_xpos, const mjtNum* geom_xmat, const pair* k,
                     geometry* g) {
  if (k->kind == SPHERE_SPHERE) {
    const mjtNum* ca = geom_xpos + 3 * k->geom_a;
    const mjtNum* cb = geom_xpos + 3 * k->geom_b;
    double dv[3] = {cb[0] - ca[0], cb[1] - ca[1], cb[2] - ca[2]};
    double dist = sqrt(dot3(dv, dv));
    g->h = k->radius_a + k->radius - dist;
    if (!(dist > 0.0)) return -1;
    for (int i = 0; i < 3; i++) g->n[i] = dv[i] / dist;
    double s = k->radius_a - g->h * k->radius / (k->radius_a + k->radius);
    for (int i = 0; i < 3; i++) g->point[i] = ca[i] + s * g->n[i];
    for (int i = 0; i < 3; i++) {
      g->centre_a[i] = ca[i];
      g->centre[i] = cb[i];
    }
    g->ratio = s / dist;
    any_tangent(g->n, g->x);
    cross3(g->n, g->x, g->y);
    return g->h > 0.0 ? 0 : -1;
  }
  const mjtNum* p0 = geom_xpos + 3 * k->geom_a;
  const mjtNum* pm = geom_xmat + 9 * k->geom_a; /* plane frame: columns x, y, normal */
  double n[3] = {pm[2], pm[5], pm[8]};
  double t1[3] = {pm[0], pm[3], pm[6]};
  double t2[3] = {pm[1], pm[4], pm[7]};
  for (int i = 0; i < 3; i++) g->n[i] = n[i];
  if (k->kind == SPHERE_PLANE) {
    double c[3];
    sphere_centre(geom_xpos, geom_xmat, k, c);
    double rel[3] = {c[0] - p0[0], c[1] - p0[1], c[2] - p0[2]};
    double dist = dot3(rel, n);
    g->h = k->radius - dist;
    for (int i = 0; i < 3; i++) {
      g->centre[i] = c[i];
      g->point[i] = c[i] - dist * n[i];
      g->x[i] = t1[i];
      g->y[i] = t2[i];
    }
    return g->h > 0.0 ? 0 : -1;
  }
  /* Ellipsoid: the support point in the direction −n (geom frame), closed form. */
  const mjtNum* a = m->geom_size + 3 * k->geom_b;
  const mjtNum* r = geom_xmat + 9 * k->geom_b; /* geom → world, row-major */
  const mjtNum* c = geom_xpos + 3 * k->geom_b;
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
  for (int i = 0; i < 3; i++) {
    g->point[i] = xw[i] - dist * n[i];
    g->centre[i] = xw[i];
    g->u[i] = u[i];
    g->xl[i] = xl[i];
  }
  g->inv_s = 1.0 / s;
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
  return g->h > 0.0 ? 0 : -1;
}

/* The material velocity (world) at the world point q of a body with origin velocity v and ω w
 * about its origin o. */
static void material_velocity(const double v[3], const double w[3], const mjtNum* o, const double q[3],
                              double out[3]) {
  double arm[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]};
  point_velocity(v, w, arm, out);
}

/*
 * The velocity of the geometric contact point P (mujoco/README.md, "Rolling"):
 *   sphere–plane (a capsule's end sphere too): P is below the sphere centre c on the plane at
 *     rest: v_P = the material velocity of B at c (tangential part);
 *   ellipsoid–plane: P is below the support point x*, which travels over the body as it turns:
 *     v_P = v_B(x*) + R ẋ*, ẋ* = (A u̇ − x*(x*·u̇))/s, A = diag(aᵢ²), u̇ = u × ω_g (u = −n in
 *     the geom frame, world-fixed, ω_g = Rᵀω_B) — the closed form of src/scenes/rattleback.rs
 *     (Kinematics);
 *   sphere–sphere: P = c_a + s n, n = (c_b − c_a)/|c_b − c_a|: tangential part
 *     v_A(c_a) + (s/|c_b − c_a|)(v_B(c_b) − v_A(c_a)) (ṅ = (I − nnᵀ)(ċ_b − ċ_a)/|c_b − c_a|).
 * Planes are on bodies at rest (MuJoCo's rule): their motion is not taken into account.
 */
void contact_point_velocity(const mjModel* m, const mjData* d, const pair* k, const geometry* g,
                            const double vb[3], const double wb[3], const double* va, const double* wa,
                            double out[3]) {
  contact_point_velocity_at(m, d->xpos, d->geom_xmat, k, g, vb, wb, va, wa, out);
}

void contact_point_velocity_at(const mjModel* m, const mjtNum* xpos, const mjtNum* geom_xmat, const pair* k,
                               const geometry* g, const double vb[3], const double wb[3], const double* va,
                               const double* wa, double out[3]) {
  const mjtNum* ob = xpos + 3 * k->body_b;
  if (k->kind == SPHERE_PLANE) {
    material_velocity(vb, wb, ob, g->centre, out);
    return;
  }
  if (k->kind == SPHERE_SPHERE) {
    double ub[3], ua[3] = {0, 0, 0};
    material_velocity(vb, wb, ob, g->centre, ub);
    if (va) material_velocity(va, wa, xpos + 3 * k->body_a, g->centre_a, ua);
    for (int i = 0; i < 3; i++) out[i] = ua[i] + g->ratio * (ub[i] - ua[i]);
    return;
  }
  const mjtNum* a = m->geom_size + 3 * k->geom_b;
  const mjtNum* r = geom_xmat + 9 * k->geom_b; /* geom → world, row-major */
  double a2[3] = {a[0] * a[0], a[1] * a[1], a[2] * a[2]};
  double wg[3], du[3];
  for (int i = 0; i < 3; i++) wg[i] = r[i] * wb[0] + r[3 + i] * wb[1] + r[6 + i] * wb[2];
  cross3(g->u, wg, du);
  double xdu = dot3(g->xl, du);
  double rate[3];
  for (int i = 0; i < 3; i++) rate[i] = (a2[i] * du[i] - g->xl[i] * xdu) * g->inv_s;
  material_velocity(vb, wb, ob, g->centre, out);
  for (int i = 0; i < 3; i++) out[i] += r[3 * i] * rate[0] + r[3 * i + 1] * rate[1] + r[3 * i + 2] * rate[2];
}
