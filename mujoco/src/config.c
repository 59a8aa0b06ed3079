/*
 * contensou.contact: the configuration of an instance and the checks of the model, each
 * failure a MuJoCo warning that names the attribute (or geom) and the value, and −1 — init()
 * then refuses the model at load (the compiler appends the warning to its error).
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contensou_mujoco.h"

const char* geom_name(const mjModel* m, int g) {
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
int read_config(const mjModel* m, int instance, config* c) {
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
int check_geoms(const mjModel* m, int instance, const pair* pairs, int npair) {
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
