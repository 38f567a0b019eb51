/* The timing loop of the peer drivers (mujoco_chain.c, pinocchio_chain.cpp, mujoco_robots.c,
 * pinocchio_robots.cpp): a warm-up that sizes a repetition, then PEER_REPS timed repetitions, of
 * which the min and the median per call are reported. */
#ifndef LAGRANGE_PEERS_TIMING_H
#define LAGRANGE_PEERS_TIMING_H

#include <stdlib.h>
#include <time.h>

static double peer_now_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int peer_cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

#define PEER_REPS 21          /* repetitions timed (min and median reported) */
#define PEER_REP_NS 10e6      /* target length of one repetition: 10 ms */
#define PEER_WARMUP_NS 50e6   /* warm-up before timing: 50 ms */

typedef struct {
  double min_ns, median_ns; /* per call */
  long iters;               /* calls per repetition */
} peer_timing;

/* Times STMT: a warm-up of ≈ 50 ms that also sizes a repetition to ≈ 10 ms, then PEER_REPS
 * repetitions; min and median of the per-call time. A compiler barrier after each call keeps
 * the calls from being merged or hoisted. */
#define PEER_TIME(result, STMT)                                                        \
  do {                                                                                 \
    long peer_it_ = 1;                                                                 \
    double peer_t0_ = peer_now_ns(), peer_el_ = 0.0, peer_tot_ = 0.0;                  \
    for (;;) {                                                                         \
      peer_t0_ = peer_now_ns();                                                        \
      for (long peer_i_ = 0; peer_i_ < peer_it_; peer_i_++) {                          \
        STMT;                                                                          \
        __asm__ __volatile__("" ::: "memory");                                         \
      }                                                                                \
      peer_el_ = peer_now_ns() - peer_t0_;                                             \
      peer_tot_ += peer_el_;                                                           \
      if (peer_tot_ >= PEER_WARMUP_NS && peer_el_ >= PEER_REP_NS / 4) break;           \
      if (peer_el_ < PEER_REP_NS) peer_it_ *= 2;                                       \
    }                                                                                  \
    peer_it_ = (long)(peer_it_ * PEER_REP_NS / peer_el_) + 1;                          \
    double peer_per_[PEER_REPS];                                                       \
    for (int peer_r_ = 0; peer_r_ < PEER_REPS; peer_r_++) {                            \
      peer_t0_ = peer_now_ns();                                                        \
      for (long peer_i_ = 0; peer_i_ < peer_it_; peer_i_++) {                          \
        STMT;                                                                          \
        __asm__ __volatile__("" ::: "memory");                                         \
      }                                                                                \
      peer_per_[peer_r_] = (peer_now_ns() - peer_t0_) / (double)peer_it_;              \
    }                                                                                  \
    qsort(peer_per_, PEER_REPS, sizeof(double), peer_cmp_double);                      \
    (result).min_ns = peer_per_[0];                                                    \
    (result).median_ns = peer_per_[PEER_REPS / 2];                                     \
    (result).iters = peer_it_;                                                         \
  } while (0)

#endif
