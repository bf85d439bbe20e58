/* check.h -- the tiny test harness of the core tests: CHECK prints a FAIL line with the measured
 * value and counts; each test function prints one PASS/FAIL line. */
#ifndef CHECK_H
#define CHECK_H
#include <stdio.h>

extern int check_failures_in_test;
#define CHECK(cond, ...)                                                                                          \
    do {                                                                                                        \
        if (!(cond)) {                                                                                          \
            printf("    check failed at %s:%d: ", __FILE__, __LINE__);                                          \
            printf(__VA_ARGS__);                                                                                \
            printf("\n");                                                                                       \
            ++check_failures_in_test;                                                                           \
        }                                                                                                       \
    } while (0)

/* deterministic random numbers in [0, 1) (xorshift64*) */
static inline double rnd(unsigned long long *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return (double)((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}
#endif
