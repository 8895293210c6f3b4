/* check.h - a minimal test harness: checks that report and count failures.
 *
 * Each test program includes this once, calls checks, and returns
 * check_finish(). Tolerances are always given explicitly at the call site,
 * with a comment there saying why that tolerance is right.
 */
#ifndef CANDELA_TESTS_CHECK_H
#define CANDELA_TESTS_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int check_failures_;
static int check_count_;

#define CHECK(cond)                                                                       \
    do {                                                                                  \
        ++check_count_;                                                                   \
        if (!(cond)) {                                                                    \
            ++check_failures_;                                                            \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);      \
        }                                                                                 \
    } while (0)

#define CHECK_MSG(cond, ...)                                                              \
    do {                                                                                  \
        ++check_count_;                                                                   \
        if (!(cond)) {                                                                    \
            ++check_failures_;                                                            \
            fprintf(stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__, #cond);      \
            fprintf(stderr, __VA_ARGS__);                                                 \
            fputc('\n', stderr);                                                          \
        }                                                                                 \
    } while (0)

/* |actual - expected| <= rel * |expected| (and both finite). */
#define CHECK_REL(actual, expected, rel)                                                  \
    do {                                                                                  \
        double a_ = (double)(actual), e_ = (double)(expected), r_ = (double)(rel);        \
        ++check_count_;                                                                   \
        if (!(isfinite(a_) && isfinite(e_) && fabs(a_ - e_) <= r_ * fabs(e_))) {          \
            ++check_failures_;                                                            \
            fprintf(stderr, "%s:%d: %s = %.17g, expected %.17g (rel err %.3g > %.3g)\n",  \
                    __FILE__, __LINE__, #actual, a_, e_, fabs(a_ - e_) / fabs(e_), r_);   \
        }                                                                                 \
    } while (0)

/* |actual - expected| <= abs_tol (and both finite). */
#define CHECK_ABS(actual, expected, abs_tol)                                              \
    do {                                                                                  \
        double a_ = (double)(actual), e_ = (double)(expected), t_ = (double)(abs_tol);    \
        ++check_count_;                                                                   \
        if (!(isfinite(a_) && isfinite(e_) && fabs(a_ - e_) <= t_)) {                     \
            ++check_failures_;                                                            \
            fprintf(stderr, "%s:%d: %s = %.17g, expected %.17g (abs err %.3g > %.3g)\n",  \
                    __FILE__, __LINE__, #actual, a_, e_, fabs(a_ - e_), t_);              \
        }                                                                                 \
    } while (0)

/* A fallible call must succeed; prints the error message if not. */
#define CHECK_OK(call, err)                                                               \
    do {                                                                                  \
        ++check_count_;                                                                   \
        cdl_status s_ = (call);                                                           \
        if (s_ != CDL_OK) {                                                               \
            ++check_failures_;                                                            \
            fprintf(stderr, "%s:%d: %s failed (%d): %s\n", __FILE__, __LINE__, #call,     \
                    (int)s_, (err)->message);                                             \
        }                                                                                 \
    } while (0)

static inline int check_finish(void)
{
    if (check_count_ == 0) {
        fprintf(stderr, "no checks ran\n");
        return 1;
    }
    fprintf(stderr, "%d checks, %d failed\n", check_count_, check_failures_);
    return check_failures_ ? 1 : 0;
}

#endif
