/*
 * The plugin from C: load the plugin library, a model that declares it, reset to keyframe 0 and
 * step; print the time, the first free body's position and the plugin sensor (if any) every
 * `every` seconds.
 *
 *   mujoco/build/run_model mujoco/build/libcontensou_mujoco.so mujoco/models/ball.xml 0.5 0.1
 */
#include <stdio.h>
#include <stdlib.h>

#include <mujoco/mujoco.h>

int main(int argc, char** argv) {
  if (argc < 4) {
    fprintf(stderr, "usage: %s PLUGIN.so MODEL.xml END_S [EVERY_S]\n", argv[0]);
    return 2;
  }
  mj_loadPluginLibrary(argv[1]); /* registers contensou.contact */
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[2], NULL, error, sizeof(error));
  if (!m) {
    fprintf(stderr, "%s\n", error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  if (m->nkey > 0) mj_resetDataKeyframe(m, d, 0);
  mj_forward(m, d);
  double end = atof(argv[3]), every = argc > 4 ? atof(argv[4]) : end;
  long steps = (long)(end / m->opt.timestep + 0.5), stride = (long)(every / m->opt.timestep + 0.5);
  if (stride < 1) stride = 1;
  for (long i = 0; i <= steps; i++) {
    if (i % stride == 0) {
      printf("t = %.4f s  body 1 at (%.6g, %.6g, %.6g)", d->time, d->xpos[3], d->xpos[4], d->xpos[5]);
      for (int j = 0; j < m->nsensor; j++) {
        if (m->sensor_type[j] != mjSENS_PLUGIN) continue;
        for (int k = 0; k < m->sensor_dim[j]; k += 7) {
          const mjtNum* s = d->sensordata + m->sensor_adr[j] + k;
          if (s[0] > 0) printf("  [N %.4g Fx %.3g Fy %.3g Tz %.3g a %.3g b %.3g]", s[0], s[1], s[2], s[3], s[4], s[5]);
        }
      }
      printf("\n");
    }
    if (i < steps) mj_step(m, d);
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
