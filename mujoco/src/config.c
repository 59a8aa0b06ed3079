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

/* The law of a name: the library's sliding and rolling laws, and "rolling" for its default
 * rolling law (table); −1 for any other name (also the library's reference laws full-slip and
 * linear, which build no contact). */
#define LAW_NAMES "best, simplified, pade, ellipsoid, coulomb; rolling laws: rolling (= table), table, blend, fastsim, fastsim-16"
static int read_law(const char* name, contensou_law* law) {
  if (!strcmp(name, "rolling")) {
    *law = CONTENSOU_LAW_TABLE;
    return 0;
  }
  if (contensou_law_from_name(name, law) != CONTENSOU_STATUS_OK) return -1;
  return *law == CONTENSOU_LAW_FULL_SLIP || *law == CONTENSOU_LAW_LINEAR ? -1 : 0;
}

int is_rolling(contensou_law law) {
  return law == CONTENSOU_LAW_TABLE || law == CONTENSOU_LAW_BLEND || law == CONTENSOU_LAW_FASTSIM ||
         law == CONTENSOU_LAW_FASTSIM_16;
}

/*
 * The rolling laws' elasticity: G and ν from the keys G, nu, or from the materials young1,
 * poisson1, young2, poisson2 by Kalker's rule for dissimilar bodies (the C twin of
 * contensou::friction::rolling::Elasticity::dissimilar: Gᵢ = Eᵢ/(2(1 + νᵢ)), with q = G_lo/G_hi,
 * G = 2G_lo/(1 + q), ν = (ν_lo + qν_hi)/(1 + q)), or neither (the library's defaults G = E*(1 − ν),
 * ν = 0.3). Refused: G or nu with a sliding law, G or nu together with the materials.
 */
static int read_elasticity(const mjModel* m, int instance, config* c, const char* law, int materials) {
  const char* g = config_value(m, instance, "G");
  const char* nu = config_value(m, instance, "nu");
  if (!c->rolling) {
    if (g || nu) {
      mju_warning(PLUGIN_NAME ": %s = '%s' is read by the rolling laws only (law = '%s'; rolling laws: "
                  "rolling, table, blend, fastsim, fastsim-16)", g ? "G" : "nu", g ? g : nu, law ? law : "best");
      return -1;
    }
    return 0;
  }
  if (materials && (g || nu)) {
    mju_warning(PLUGIN_NAME ": give either %s (= '%s') or young1, poisson1, young2, poisson2 (which give G "
                "and nu by Kalker's rule), not both", g ? "G" : "nu", g ? g : nu);
    return -1;
  }
  if (materials) {
    double e[4];
    const char* keys[4] = {"young1", "poisson1", "young2", "poisson2"};
    for (int i = 0; i < 4; i++) {
      if (config_number(m, instance, keys[i], 1, 0, &e[i])) return -1;
    }
    for (int i = 1; i < 4; i += 2) {
      if (!(e[i] >= 0.0 && e[i] <= 0.5)) {
        mju_warning(PLUGIN_NAME ": %s = %g: the rolling laws take Poisson's ratios in [0, 0.5]", keys[i], e[i]);
        return -1;
      }
    }
    double g1 = e[0] / (2.0 * (1.0 + e[1])), g2 = e[2] / (2.0 * (1.0 + e[3]));
    double glo = g1 <= g2 ? g1 : g2, ghi = g1 <= g2 ? g2 : g1;
    double nlo = g1 <= g2 ? e[1] : e[3], nhi = g1 <= g2 ? e[3] : e[1];
    double q = glo / ghi, r = 1.0 / (1.0 + q);
    c->shear = fmin(glo * (2.0 * r), ghi);
    c->poisson = fmax(0.0, fmin(0.5, (nlo + q * nhi) * r));
    c->has_g = c->has_nu = 1;
    return 0;
  }
  if (g) {
    if (config_number(m, instance, "G", 1, 0, &c->shear)) return -1;
    c->has_g = 1;
  }
  if (nu) {
    if (config_number(m, instance, "nu", 1, 0, &c->poisson)) return -1;
    c->has_nu = 1;
  }
  return 0;
}

/* A contact of the configuration's law, elasticity and form on spec (P, Q set). */
contensou_status new_contact(contensou_contact_f64* storage, const config* c, const contensou_spec_f64* spec,
                             contensou_form form, contensou_column* column) {
  if (!c->rolling) return contensou_contact_new_f64(storage, spec, c->law, form, column);
  return contensou_contact_new_rolling_f64(storage, spec, c->has_g ? &c->shear : NULL,
                                           c->has_nu ? &c->poisson : NULL, c->law, form, column);
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
  if (law && read_law(law, &c->law)) {
    mju_warning(PLUGIN_NAME ": law = '%s' is no law (" LAW_NAMES ")", law);
    return -1;
  }
  c->rolling = is_rolling(c->law);
  if (read_elasticity(m, instance, c, law, nmaterial == 4)) return -1;
  const char* step = config_value(m, instance, "step");
  c->step_aware = 0;
  if (step) {
    if (!strcmp(step, "aware")) c->step_aware = 1;
    else if (strcmp(step, "explicit")) {
      mju_warning(PLUGIN_NAME ": step = '%s' is no step mode (explicit, aware)", step);
      return -1;
    }
  }
  if (config_number(m, instance, "step_point", 0, 0.0, &c->step_point)) return -1;
  if (!(c->step_point >= 0.0 && c->step_point <= 1.0)) {
    mju_warning(PLUGIN_NAME ": step_point = %g is not in [0, 1] (the fraction of the step at which the "
                "contact velocity is predicted)", c->step_point);
    return -1;
  }
  if (config_value(m, instance, "step_point") && !c->step_aware) {
    mju_warning(PLUGIN_NAME ": step_point is read by step = 'aware' only");
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
  /* The library validates estar, cd, f, delta (and G, ν for a rolling law): build a sphere
   * contact to learn its verdict. */
  contensou_spec_f64 probe = c->spec;
  probe.p = probe.q = 1.0;
  contensou_column column = CONTENSOU_COLUMN_NONE;
  contensou_contact_f64 storage;
  contensou_status s = new_contact(&storage, c, &probe, CONTENSOU_FORM_FIXED, &column);
  if (s != CONTENSOU_STATUS_OK) {
    const char* key = contensou_column_name(column);
    double value = column == CONTENSOU_COLUMN_ESTAR ? c->spec.estar
                 : column == CONTENSOU_COLUMN_CD    ? c->spec.cd
                 : column == CONTENSOU_COLUMN_F     ? c->spec.f
                 : column == CONTENSOU_COLUMN_DELTA ? c->spec.delta
                 : column == CONTENSOU_COLUMN_G     ? c->shear
                 : column == CONTENSOU_COLUMN_NU    ? c->poisson
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
