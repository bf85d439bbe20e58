/*
 * program_util.h -- helpers shared by the programs built on the core (the benchmarks, the
 * particleDistribution tutorial): a monotonic wall clock, a small fixed-seed random number
 * generator (so that runs are reproducible on every platform) and the median of timings. Not part
 * of the core library, which never reads a clock of its own.
 */
#ifndef CDC_PROGRAM_UTIL_H
#define CDC_PROGRAM_UTIL_H

#include <stdint.h>
#include <stdlib.h>
#include <time.h>

/* seconds on the monotonic clock (needs _POSIX_C_SOURCE >= 199309L) */
static inline double program_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* splitmix64 (Steele, Lea and Flood 2014): a uniform double in [0, 1) from a 64-bit state */
static inline double program_uniform(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static inline int program_compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the median of v[0..n), n > 0 (sorts v) */
static inline double program_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, program_compare_doubles);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

#endif
