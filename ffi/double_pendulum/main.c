/* The double pendulum simulated from C through the library `export_c!` writes.
 *
 *   ./main          RK4 and Dopri5 runs: final states (17 digits) and energy checks; the pendulum
 *                   held upside down by a PD controller on its joint motors, computed here in C
 *                   and applied through dp_set_inputs every step; then the library's answers to
 *                   bad input; exits non-zero if a check fails.
 *   ./main bench N  the cost of N RK4 steps called one by one from C against the same N steps
 *                   in one call (a loop in Rust), in ns per step.
 *   ./main calls N  N RK4 steps, one call each, untimed (for instruction counts: callgrind);
 *   ./main loop N   the same N steps in one call.
 *
 * Build (tests/c_program.rs does this):
 *   cc -O2 -std=c11 main.c -I. libdouble_pendulum_ffi.a -lpthread -ldl -lm
 */
#define _POSIX_C_SOURCE 199309L
#include "double_pendulum.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static int failures = 0;

/* Reports and counts a failed check. */
static void check(int ok, const char *what) {
    if (!ok) {
        fprintf(stderr, "check failed: %s\n", what);
        failures++;
    }
}

/* Stops on a call that should have succeeded, with the library's message. */
static void must(lagrange_status status, const char *call) {
    if (status != LAGRANGE_OK) {
        fprintf(stderr, "%s failed with status %d: %s\n", call, (int)status, dp_last_error());
        exit(2);
    }
}

static double total_energy(const dp_simulation *sim) {
    double kinetic, potential;
    must(dp_energies(sim, &kinetic, &potential), "dp_energies");
    return kinetic + potential;
}

/* Prints `label t theta1 theta2 omega1 omega2 e0 e1` with every digit of a double. */
static void print_state(const char *label, const dp_simulation *sim, double e0) {
    double t, q[DP_DOF], v[DP_DOF];
    must(dp_get_state(sim, &t, q, v, DP_DOF), "dp_get_state");
    printf("%s %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", label, t, q[DP_THETA1], q[DP_THETA2],
           v[DP_THETA1], v[DP_THETA2], e0, total_energy(sim));
}

static dp_simulation *create(const double *params) {
    dp_simulation *sim = NULL;
    must(dp_create(params, DP_PARAMETER_COUNT, &sim), "dp_create");
    return sim;
}

/* The scene the Rust test repeats: m1 = m2 = 1, l1 = l2 = 1, g = 9.81, released at rest from
 * (theta1, theta2) = (1.0, 0.5). */
static const double PARAMS[DP_PARAMETER_COUNT] = {
    [DP_PARAM_M1] = 1.0, [DP_PARAM_M2] = 1.0, [DP_PARAM_L1] = 1.0, [DP_PARAM_L2] = 1.0,
    [DP_PARAM_G] = 9.81,
};
static const double Q0[DP_DOF] = {[DP_THETA1] = 1.0, [DP_THETA2] = 0.5};
static const double V0[DP_DOF] = {0.0, 0.0};

static int simulate(void) {
    /* RK4, 10^4 steps of 1e-3 (t = 10), one call per step. */
    dp_simulation *sim = create(PARAMS);
    must(dp_set_state(sim, 0.0, Q0, V0, DP_DOF), "dp_set_state");
    double e0 = total_energy(sim);
    for (int i = 0; i < 10000; i++) {
        must(dp_step(sim, LAGRANGE_RK4, 1e-3), "dp_step");
    }
    print_state("rk4", sim, e0);
    /* RK4's energy error here is 4.5e-12 (tests/c_program.rs prints it) and scales as h^4: the
     * bound 1e-10 leaves a factor 20 for another libm, and fails for a step 2.2 times too large
     * or for a wrong force. */
    check(fabs(total_energy(sim) - e0) < 1e-10, "RK4 conserves energy to 1e-10 over 10 s");
    dp_free(sim);

    /* Dopri5 to t = 20 with tight tolerances, in one call. */
    sim = create(PARAMS);
    must(dp_set_state(sim, 0.0, Q0, V0, DP_DOF), "dp_set_state");
    e0 = total_energy(sim);
    size_t accepted = 0;
    must(dp_integrate_dopri5(sim, 20.0, 1e-10, 1e-12, &accepted), "dp_integrate_dopri5");
    print_state("dopri5", sim, e0);
    printf("dopri5_accepted %zu\n", accepted);
    /* The controller keeps each step's local error near rtol |y| = 5e-10 (|y| <= 5); over about
     * 3000 steps such errors add like a random walk, sqrt(3000) 5e-10 = 3e-8 in the state, times
     * |grad E| <= 20: 6e-7. Measured: 4e-9 (printed above as e1 - e0). */
    check(fabs(total_energy(sim) - e0) < 1e-6, "Dopri5 conserves energy to 1e-6 over 20 s");
    check(accepted > 0, "Dopri5 took steps");

    /* No constraints: zero rows, nothing to write. */
    must(dp_constraint_forces(sim, NULL, DP_CONSTRAINT_COUNT, NULL, 0), "dp_constraint_forces");
    double qdd[DP_DOF];
    must(dp_accelerations(sim, qdd, DP_DOF), "dp_accelerations");
    check(isfinite(qdd[0]) && isfinite(qdd[1]), "accelerations are finite");
    dp_free(sim);
    return 0;
}

/* The controlled run: both rods upright, theta1 = theta2 = pi. PI is the double nearest pi, as
 * in Rust's std::f64::consts::PI. */
static const double PI = 3.14159265358979323846;
static const double KP = 100.0; /* N m / rad */
static const double KD = 20.0;  /* N m s / rad */

/* PD control of each joint towards upright: the shoulder's angle from the upward vertical is
 * theta1 - pi, the elbow's bend theta2 - theta1. With m = l = 1 the closed loop linearized about
 * upright is stable for KP > 2 g / (2 - sqrt 2) = 33.5 (the stiffness KP K - g diag(2, 1), K the
 * joint-to-angle map [[2, -1], [-1, 1]], must be positive definite); with KP = 100, KD = 20 its
 * slowest modes decay as exp(-1.716 t). */
static void pd_torques(const double q[DP_DOF], const double v[DP_DOF], double u[DP_INPUT_COUNT]) {
    double shoulder = q[DP_THETA1] - PI, shoulder_rate = v[DP_THETA1];
    double elbow = q[DP_THETA2] - q[DP_THETA1], elbow_rate = v[DP_THETA2] - v[DP_THETA1];
    u[DP_INPUT_TAU1] = -KP * shoulder - KD * shoulder_rate;
    u[DP_INPUT_TAU2] = -KP * elbow - KD * elbow_rate;
}

/* Released at rest 0.5 rad and 0.3 rad off upright, the controller reads the state and sets the
 * motors' torques before each RK4 step of 1 ms (held over the step), for 10 s. Prints
 * `control t shoulder_error elbow_error tau1 tau2` at a few times, then the final state in full
 * (`control_final t theta1 theta2 omega1 omega2`). */
static void control(void) {
    dp_simulation *sim = create(PARAMS);
    const double q0[DP_DOF] = {[DP_THETA1] = PI - 0.5, [DP_THETA2] = PI + 0.3};
    must(dp_set_state(sim, 0.0, q0, V0, DP_DOF), "dp_set_state");
    double t, q[DP_DOF], v[DP_DOF], u[DP_INPUT_COUNT], last_set[DP_INPUT_COUNT];
    for (int i = 0; i <= 10000; i++) {
        must(dp_get_state(sim, &t, q, v, DP_DOF), "dp_get_state");
        pd_torques(q, v, u);
        if (i == 0 || i == 500 || i == 1000 || i == 2000 || i == 5000 || i == 10000) {
            printf("control %.1f %+.3e %+.3e %+.3e %+.3e\n", t, q[DP_THETA1] - PI,
                   q[DP_THETA2] - q[DP_THETA1], u[DP_INPUT_TAU1], u[DP_INPUT_TAU2]);
        }
        if (i == 10000) {
            break;
        }
        must(dp_set_inputs(sim, u, DP_INPUT_COUNT), "dp_set_inputs");
        memcpy(last_set, u, sizeof last_set);
        must(dp_step(sim, LAGRANGE_RK4, 1e-3), "dp_step");
    }
    printf("control_final %.17g %.17g %.17g %.17g %.17g\n", t, q[DP_THETA1], q[DP_THETA2],
           v[DP_THETA1], v[DP_THETA2]);
    /* The slowest modes' envelope from the initial error 0.5 rad after 10 s is
     * 0.5 exp(-17.16) = 1.8e-8 rad (tests/c_program.rs checks the printed error against 1e-6). */
    check(fabs(q[DP_THETA1] - PI) < 1e-6 && fabs(q[DP_THETA2] - PI) < 1e-6,
          "the PD controller holds both rods upright to 1e-6 rad after 10 s");
    double held[DP_INPUT_COUNT];
    must(dp_get_inputs(sim, held, DP_INPUT_COUNT), "dp_get_inputs");
    check(memcmp(held, last_set, sizeof held) == 0, "dp_get_inputs reads the inputs last set");
    dp_free(sim);
}

/* Bad input is a status and a message, never a crash; the state is left as it was. */
static void bad_input(void) {
    double params[DP_PARAMETER_COUNT];
    memcpy(params, PARAMS, sizeof params);
    params[DP_PARAM_L1] = NAN;
    dp_simulation *sim = (dp_simulation *)(void *)params; /* must be overwritten with NULL */
    lagrange_status status = dp_create(params, DP_PARAMETER_COUNT, &sim);
    check(status == LAGRANGE_INVALID_PARAMETER, "NaN parameter: LAGRANGE_INVALID_PARAMETER");
    check(sim == NULL, "NaN parameter: no simulation");
    check(strstr(dp_last_error(), "parameter `l1` is not finite") != NULL,
          "NaN parameter: the message names l1");
    printf("nan_parameter %d %s\n", (int)status, dp_last_error());

    params[DP_PARAM_L1] = 1.0;
    params[DP_PARAM_M2] = -1.0;
    check(dp_create(params, DP_PARAMETER_COUNT, &sim) == LAGRANGE_INVALID_PARAMETER,
          "negative mass: LAGRANGE_INVALID_PARAMETER");
    check(dp_create(PARAMS, DP_PARAMETER_COUNT - 1, &sim) == LAGRANGE_INVALID_ARGUMENT,
          "too few parameters: LAGRANGE_INVALID_ARGUMENT");
    check(dp_create(NULL, DP_PARAMETER_COUNT, &sim) == LAGRANGE_NULL_POINTER,
          "NULL parameters: LAGRANGE_NULL_POINTER");
    check(dp_create(PARAMS, DP_PARAMETER_COUNT, NULL) == LAGRANGE_NULL_POINTER,
          "NULL out: LAGRANGE_NULL_POINTER");

    sim = create(PARAMS);
    must(dp_set_state(sim, 0.0, Q0, V0, DP_DOF), "dp_set_state");
    double nan_q[DP_DOF] = {NAN, 0.0};
    check(dp_set_state(sim, 0.0, nan_q, V0, DP_DOF) == LAGRANGE_INVALID_STATE,
          "NaN coordinate: LAGRANGE_INVALID_STATE");
    check(strstr(dp_last_error(), "theta1 = NaN") != NULL, "NaN coordinate: the message names theta1");
    check(dp_set_state(sim, 0.0, Q0, V0, DP_DOF + 1) == LAGRANGE_INVALID_ARGUMENT,
          "wrong dof: LAGRANGE_INVALID_ARGUMENT");
    check(dp_step(sim, LAGRANGE_RK4, -1e-3) == LAGRANGE_INVALID_STEP, "negative step: LAGRANGE_INVALID_STEP");
    check(dp_step(sim, LAGRANGE_RK4, NAN) == LAGRANGE_INVALID_STEP, "NaN step: LAGRANGE_INVALID_STEP");
    check(dp_step(sim, 99u, 1e-3) == LAGRANGE_INVALID_ARGUMENT, "unknown method: LAGRANGE_INVALID_ARGUMENT");
    check(dp_integrate_dopri5(sim, -1.0, 1e-8, 1e-8, NULL) == LAGRANGE_INVALID_STEP,
          "end time in the past: LAGRANGE_INVALID_STEP");
    check(dp_integrate_dopri5(sim, 1.0, -1e-8, 1e-8, NULL) == LAGRANGE_INVALID_STEP,
          "negative tolerance: LAGRANGE_INVALID_STEP");
    check(dp_step(sim, LAGRANGE_STORMER_VERLET, 1e-3) == LAGRANGE_UNSUPPORTED,
          "Stormer-Verlet on a varying mass matrix: LAGRANGE_UNSUPPORTED");
    check(dp_step(NULL, LAGRANGE_RK4, 1e-3) == LAGRANGE_NULL_POINTER, "NULL simulation: LAGRANGE_NULL_POINTER");
    const double torques[DP_INPUT_COUNT] = {[DP_INPUT_TAU1] = 1.0, [DP_INPUT_TAU2] = -1.0};
    must(dp_set_inputs(sim, torques, DP_INPUT_COUNT), "dp_set_inputs");
    const double nan_torques[DP_INPUT_COUNT] = {[DP_INPUT_TAU1] = 2.0, [DP_INPUT_TAU2] = NAN};
    check(dp_set_inputs(sim, nan_torques, DP_INPUT_COUNT) == LAGRANGE_INVALID_ARGUMENT,
          "NaN torque: LAGRANGE_INVALID_ARGUMENT");
    check(strstr(dp_last_error(), "input `tau2` is not finite") != NULL,
          "NaN torque: the message names tau2");
    check(dp_set_inputs(sim, torques, DP_INPUT_COUNT + 1) == LAGRANGE_INVALID_ARGUMENT,
          "too many torques: LAGRANGE_INVALID_ARGUMENT");
    check(dp_set_inputs(sim, NULL, DP_INPUT_COUNT) == LAGRANGE_NULL_POINTER,
          "NULL torques: LAGRANGE_NULL_POINTER");
    double held[DP_INPUT_COUNT];
    must(dp_get_inputs(sim, held, DP_INPUT_COUNT), "dp_get_inputs");
    check(held[DP_INPUT_TAU1] == 1.0 && held[DP_INPUT_TAU2] == -1.0,
          "the inputs are unchanged by every refused dp_set_inputs");
    double t, q[DP_DOF], v[DP_DOF];
    must(dp_get_state(sim, &t, q, v, DP_DOF), "dp_get_state");
    check(t == 0.0 && q[0] == Q0[0] && q[1] == Q0[1] && v[0] == 0.0 && v[1] == 0.0,
          "the state is unchanged by every refused call");
    dp_free(sim);
    dp_free(NULL);
    printf("bad_input %s\n", failures == 0 ? "ok" : "FAILED");
}

static double seconds(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ns per RK4 step: N calls from C, then one call looping N times in Rust, best of 5 each. */
static int bench(long n) {
    dp_simulation *sim = create(PARAMS);
    double best_calls = INFINITY, best_loop = INFINITY;
    for (int round = 0; round < 5; round++) {
        must(dp_set_state(sim, 0.0, Q0, V0, DP_DOF), "dp_set_state");
        double start = seconds();
        for (long i = 0; i < n; i++) {
            must(dp_step(sim, LAGRANGE_RK4, 1e-4), "dp_step");
        }
        double calls = (seconds() - start) / (double)n;
        must(dp_set_state(sim, 0.0, Q0, V0, DP_DOF), "dp_set_state");
        start = seconds();
        must(dp_steps(sim, LAGRANGE_RK4, 1e-4, (size_t)n), "dp_steps");
        double loop = (seconds() - start) / (double)n;
        best_calls = calls < best_calls ? calls : best_calls;
        best_loop = loop < best_loop ? loop : best_loop;
    }
    printf("rk4_step_from_c_ns %.1f\nrk4_step_in_rust_ns %.1f\ncall_overhead_ns %.1f\n",
           1e9 * best_calls, 1e9 * best_loop, 1e9 * (best_calls - best_loop));
    dp_free(sim);
    return 0;
}

/* N RK4 steps, one call each (`calls`) or all in one call (`loop`), untimed. */
static int run_steps(int one_call_each, long n) {
    dp_simulation *sim = create(PARAMS);
    must(dp_set_state(sim, 0.0, Q0, V0, DP_DOF), "dp_set_state");
    if (one_call_each) {
        for (long i = 0; i < n; i++) {
            must(dp_step(sim, LAGRANGE_RK4, 1e-4), "dp_step");
        }
    } else {
        must(dp_steps(sim, LAGRANGE_RK4, 1e-4, (size_t)n), "dp_steps");
    }
    dp_free(sim);
    return 0;
}

int main(int argc, char **argv) {
    if (argc == 3 && strcmp(argv[1], "bench") == 0) {
        return bench(atol(argv[2]));
    }
    if (argc == 3 && (strcmp(argv[1], "calls") == 0 || strcmp(argv[1], "loop") == 0)) {
        return run_steps(strcmp(argv[1], "calls") == 0, atol(argv[2]));
    }
    simulate();
    control();
    bad_input();
    return failures == 0 ? 0 : 1;
}
