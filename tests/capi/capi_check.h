/* The check macros of the C API tests (test_capi.c, test_capi_documents.c): each failed check
 * prints its file, line and what failed, and counts in `failures`, which main() turns into the
 * exit status. C99; include once per test program. */
#ifndef CASTELJAU_TESTS_CAPI_CHECK_H
#define CASTELJAU_TESTS_CAPI_CHECK_H

#include <stdio.h>
#include <string.h>

#include "casteljau/casteljau.h"

static int failures = 0;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                              \
        }                                                                            \
    } while (0)

#define CHECK_OK(call)                                                                                    \
    do {                                                                                                  \
        casteljau_status s_ = (call);                                                                     \
        if (s_ != CASTELJAU_OK) {                                                                         \
            fprintf(stderr, "%s:%d: %s failed: %s\n", __FILE__, __LINE__, #call, casteljau_last_error()); \
            ++failures;                                                                                   \
        }                                                                                                 \
    } while (0)

/* Expects `call` to fail with `status` and a non-empty last-error message containing `needle`. */
#define CHECK_ERROR(call, status, needle)                                                                           \
    do {                                                                                                            \
        casteljau_status s_ = (call);                                                                               \
        if (s_ != (status)) {                                                                                       \
            fprintf(stderr, "%s:%d: %s gave %d, expected %d\n", __FILE__, __LINE__, #call, (int)s_, (int)(status)); \
            ++failures;                                                                                             \
        }                                                                                                           \
        if (strstr(casteljau_last_error(), (needle)) == NULL || casteljau_last_error()[0] == '\0') {                \
            fprintf(stderr, "%s:%d: message \"%s\" lacks \"%s\"\n", __FILE__, __LINE__, casteljau_last_error(),     \
                    (needle));                                                                                      \
            ++failures;                                                                                             \
        }                                                                                                           \
    } while (0)

#endif /* CASTELJAU_TESTS_CAPI_CHECK_H */
