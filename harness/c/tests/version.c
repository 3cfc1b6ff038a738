/* SPDX-License-Identifier: MIT OR Apache-2.0 */
/* The kit's version, as harness/c/ci.sh (step 5) checks it: pk_version() of the
 * phong_kit.c linked in is the header's PK_VERSION, which is
 * PK_VERSION_MAJOR.PK_VERSION_MINOR.PK_VERSION_PATCH. Prints it; exit 1 if not. */
#include <stdio.h>
#include <string.h>

#include "phong_kit.h"

#define STR2(x) #x
#define STR(x) STR2(x)

int main(void) {
    const char *parts = STR(PK_VERSION_MAJOR) "." STR(PK_VERSION_MINOR) "." STR(PK_VERSION_PATCH);
    if (strcmp(pk_version(), PK_VERSION) != 0 || strcmp(PK_VERSION, parts) != 0) {
        fprintf(stderr, "version: pk_version() %s, PK_VERSION %s, PK_VERSION_MAJOR.MINOR.PATCH %s\n",
                pk_version(), PK_VERSION, parts);
        return 1;
    }
    if (printf("%s\n", pk_version()) < 0 || fflush(stdout) != 0) return 1;
    return 0;
}
