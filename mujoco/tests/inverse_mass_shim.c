/*
 * Test shim (not part of the plugin): exposes the plugin's contact geometry and its inverse mass
 * W = J M⁻¹ Jᵀ (src/inverse_mass.c) to tests/test_plugin.py through ctypes. Built by build.sh
 * into build/libcontensou_mujoco_test.so from src/pairs.c and src/inverse_mass.c only — no
 * plugin registration, so it loads beside the plugin library; the model must have been loaded
 * with the plugin (its instance's pairs are enumerated as the plugin does).
 */
#include <stdlib.h>

#include "../src/contensou_mujoco.h"

typedef struct {
  int pair;           /* index in the plugin's pair order (the sensor's) */
  int body_a, body_b; /* A, B */
  double point[3], n[3], x[3], y[3];
} shim_contact;

/* The touching pairs of `instance` at the state of d (position stage done: mj_forward) into
 * contacts[0..K) and their W (4K × 4K, row-major) into w; returns K, or −1 if more than cap
 * pairs touch or memory is short. */
__attribute__((visibility("default"))) int contensou_mujoco_test_inverse_mass(const mjModel* m, mjData* d,
                                                                              int instance,
                                                                              shim_contact* contacts,
                                                                              double* w, int cap) {
  int npair = enumerate_pairs(m, instance, NULL);
  pair* pairs = calloc(npair ? npair : 1, sizeof(pair));
  mjtNum* jac = calloc((size_t)(4 * cap + 6) * (m->nv ? m->nv : 1), sizeof(mjtNum));
  mjtNum* work = calloc((size_t)(4 * cap) * (m->nv ? m->nv : 1), sizeof(mjtNum));
  int k = 0;
  if (!pairs || !jac || !work) k = -1;
  if (k == 0) enumerate_pairs(m, instance, pairs);
  for (int i = 0; k >= 0 && i < npair; i++) {
    geometry g;
    if (pair_geometry(m, d, &pairs[i], &g)) continue;
    if (k == cap) {
      k = -1;
      break;
    }
    shim_contact* c = &contacts[k];
    c->pair = i;
    c->body_a = pairs[i].body_a;
    c->body_b = pairs[i].body_b;
    for (int j = 0; j < 3; j++) {
      c->point[j] = g.point[j];
      c->n[j] = g.n[j];
      c->x[j] = g.x[j];
      c->y[j] = g.y[j];
    }
    contact_jacobian(m, d, &pairs[i], &g, jac + (size_t)4 * k * m->nv, jac + (size_t)4 * cap * m->nv);
    k++;
  }
  if (k > 0) inverse_mass(m, d, jac, 4 * k, work, w);
  free(pairs);
  free(jac);
  free(work);
  return k;
}

/* step_prepare (src/step_aware.c) on the pairs of `instance`: the K pairs taken into pair[],
 * their u and u_free (4K each), h_free (K) and W (4K × 4K); returns K, or −1 if more than cap or memory is
 * short. */
__attribute__((visibility("default"))) int contensou_mujoco_test_step_prepare(const mjModel* m, mjData* d,
                                                                              int instance, int* pair_index,
                                                                              double* u, double* u_free,
                                                                              double* h_free, double* w,
                                                                              int cap) {
  int npair = enumerate_pairs(m, instance, NULL);
  pair* pairs = calloc(npair ? npair : 1, sizeof(pair));
  step_work s;
  if (!pairs || step_work_init(&s, m, npair, 0.0)) {
    free(pairs);
    return -1;
  }
  enumerate_pairs(m, instance, pairs);
  int k = step_prepare(m, d, pairs, npair, &s);
  if (k > cap) k = -1;
  for (int i = 0; i < k; i++) {
    pair_index[i] = s.index[i];
    h_free[i] = s.h_free[i];
    for (int r = 0; r < 4; r++) {
      u[4 * i + r] = s.u[4 * i + r];
      u_free[4 * i + r] = s.u_free[4 * i + r];
    }
  }
  for (int i = 0; k > 0 && i < 16 * k * k; i++) w[i] = s.w[i];
  step_work_free(&s);
  free(pairs);
  return k;
}
