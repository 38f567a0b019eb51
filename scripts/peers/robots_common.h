/* Shared by mujoco_robots.c and pinocchio_robots.cpp: the states file written by
 * `robots.py states`, the command line and the output lines of the robot drivers.
 *
 * States file (tab-separated): for each robot a row `robot, names, coordinate names...` (the
 * declaration's order), then rows `robot, k, q..., q̇..., q̈...` (q̈ is the input of inverse
 * dynamics). Every value printed is in the declaration's order; a driver maps it to its own
 * joint order by the joint's name.
 *
 * Command line:
 *   DRIVER values STATES DIR                         every quantity at every state
 *   DRIVER time STATES DIR                           per-call times, every robot and label
 *   DRIVER count STATES DIR ROBOT LABEL CALLS        CALLS calls of one label (for callgrind)
 * DIR holds the models: the URDF files for MuJoCo, Pinocchio's saved models for Pinocchio.
 *
 * Output lines (tab-separated):
 *   side robot quantity k x...                       values: qdd, tau (n values), M (n·n, rows)
 *   side robot label min_ns median_ns calls_per_rep  time: per call, over the robot's states
 */
#ifndef LAGRANGE_PEERS_ROBOTS_COMMON_H
#define LAGRANGE_PEERS_ROBOTS_COMMON_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "timing.h"

#define ROBOTS_MAX 8
#define ROBOTS_MAX_DOF 64
#define ROBOTS_MAX_STATES 16
#define ROBOTS_NAME 64
#define ROBOTS_LINE 65536

typedef struct {
  char name[ROBOTS_NAME];
  int n;     /* degrees of freedom */
  int count; /* states */
  char coord[ROBOTS_MAX_DOF][ROBOTS_NAME];
  double q[ROBOTS_MAX_STATES][ROBOTS_MAX_DOF];
  double v[ROBOTS_MAX_STATES][ROBOTS_MAX_DOF];
  double a[ROBOTS_MAX_STATES][ROBOTS_MAX_DOF];
} robot_states;

typedef struct {
  const char *mode; /* "values", "time" or "count" */
  const char *states, *model_dir;
  const char *robot, *label; /* count mode */
  long calls;
} robots_args;

static void robots_fail(const char *what, const char *detail) {
  fprintf(stderr, "%s: %s\n", what, detail);
  exit(1);
}

static robots_args robots_parse_args(int argc, char **argv) {
  robots_args args = {0};
  int values = argc == 4 && !strcmp(argv[1], "values");
  int time = argc == 4 && !strcmp(argv[1], "time");
  int count = argc == 7 && !strcmp(argv[1], "count");
  if (!values && !time && !count) {
    fprintf(stderr,
            "usage: %s values|time STATES DIR\n"
            "       %s count STATES DIR ROBOT LABEL CALLS\n",
            argv[0], argv[0]);
    exit(1);
  }
  args.mode = argv[1];
  args.states = argv[2];
  args.model_dir = argv[3];
  if (count) {
    args.robot = argv[4];
    args.label = argv[5];
    args.calls = strtol(argv[6], NULL, 10);
  }
  return args;
}

/* Reads every robot of the states file into `out`; returns how many. */
static int robots_read(const char *path, robot_states *out) {
  FILE *f = fopen(path, "r");
  if (!f) robots_fail("cannot open states file", path);
  static char line[ROBOTS_LINE];
  int robots = 0;
  while (fgets(line, sizeof line, f)) {
    line[strcspn(line, "\r\n")] = '\0';
    char *save = NULL;
    const char *name = strtok_r(line, "\t", &save);
    const char *kind = strtok_r(NULL, "\t", &save);
    if (!name || !kind) continue;
    if (!strcmp(kind, "names")) {
      if (robots == ROBOTS_MAX) robots_fail("too many robots in", path);
      robot_states *r = &out[robots++];
      memset(r, 0, sizeof *r);
      snprintf(r->name, sizeof r->name, "%s", name);
      for (const char *c; (c = strtok_r(NULL, "\t", &save));) {
        if (r->n == ROBOTS_MAX_DOF) robots_fail("too many coordinates for", name);
        snprintf(r->coord[r->n++], ROBOTS_NAME, "%s", c);
      }
      continue;
    }
    robot_states *r = robots ? &out[robots - 1] : NULL;
    if (!r || strcmp(r->name, name)) robots_fail("state row before its names row:", name);
    if (r->count == ROBOTS_MAX_STATES) robots_fail("too many states for", name);
    int k = r->count++;
    double *dst[3] = {r->q[k], r->v[k], r->a[k]};
    for (int part = 0; part < 3; part++)
      for (int i = 0; i < r->n; i++) {
        const char *x = strtok_r(NULL, "\t", &save);
        if (!x) robots_fail("short state row for", name);
        dst[part][i] = strtod(x, NULL);
      }
  }
  fclose(f);
  if (!robots) robots_fail("no robot in", path);
  return robots;
}

/* `dir/name.ext` into buf. */
static void robots_path(char *buf, size_t size, const char *dir, const char *name,
                        const char *ext) {
  if ((size_t)snprintf(buf, size, "%s/%s.%s", dir, name, ext) >= size)
    robots_fail("path too long:", dir);
}

static void robots_print_values(const char *side, const char *robot, const char *quantity, int k,
                                int count, const double *x) {
  printf("%s\t%s\t%s\t%d", side, robot, quantity, k);
  for (int i = 0; i < count; i++) printf("\t%.17g", x[i]);
  printf("\n");
}

/* One time line; `batch` timed one call at each of the robot's `states` states. */
static void robots_print_time(const char *side, const char *robot, const char *label,
                              peer_timing batch, int states) {
  printf("%s\t%s\t%s\t%.1f\t%.1f\t%ld\n", side, robot, label, batch.min_ns / states,
         batch.median_ns / states, batch.iters * states);
  fflush(stdout);
}

#endif
