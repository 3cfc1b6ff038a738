/* SPDX-License-Identifier: MIT OR Apache-2.0 */
/* A client of kit 0.1.0's API, as harness.c (d555039) used it: it includes
 * "exact_input.h", reads SET-inputs.csv from standard input, rounds each exact
 * fraction with exact_input_f32 / exact_input_f64, and shades corrected Euler in
 * float with harness.c's arithmetic. harness/c/ci.sh (step 5) builds it against
 * today's deprecated shim with -std=c99 -Wall -Wextra -Werror
 * -Wno-deprecated-declarations, and compares its output with methods.c's, which
 * gets the same inputs from phong_kit: equal, bit for bit. Built without
 * -Wno-deprecated-declarations it must not compile (the shim's marks).
 *
 *   old_client corrected-euler < SET-inputs.csv   case,pixel,value rows (%.9g)
 *   old_client inputs < SET-inputs.csv            case,component,precision,value
 *                                                 rows (%a), as `methods inputs`
 *
 * `inputs` also checks exact_input(text, 24 | 53, &ok) against the two. Exit 2 on
 * input that is not exact fractions (harness.c's "not exact inputs"), 1 if
 * exact_input disagrees or standard output cannot be written.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "exact_input.h"

static float dot(const float a[3], const float b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* harness.c's set-up (eqs. 2-3, 10-11, 14-17) and corrected Euler loop. */
static void corrected_euler(const char *id, const float na[3], const float nb[3],
                            const float l[3], int n) {
    float k[3], nf = (float)n;
    for (int j = 0; j < 3; j++) k[j] = (nb[j] - na[j]) / nf;
    float A = dot(k, l), C = dot(k, k), D = 2.0f * dot(k, na);
    float pa = dot(na, l), pb = dot(nb, l);
    float dqb = 2.0f * nf * C + D;
    float dia = A - pa / 2.0f * D;
    float dib = A - pb / 2.0f * dqb;
    float ds = (dib - dia) / nf;
    float pn = pa + nf * dia + (float)((long)n * (n - 1) / 2) * ds; /* eq. 14 */
    float t0 = dia - (pn - pb) / nf;                               /* eq. 17 */
    float p = pa, t = t0;
    for (int i = 0; i <= n; i++) { printf("%s,%d,%.9g\n", id, i, p); p += t; t += ds; }
}

static const char *const component_names[12] = {"na_x", "na_y", "na_z", "nb_x", "nb_y",
                                                 "nb_z", "l_x",  "l_y",  "l_z",  "h_x",
                                                 "h_y",  "h_z"};

int main(int argc, char **argv) {
    if (argc != 2 || (strcmp(argv[1], "corrected-euler") && strcmp(argv[1], "inputs"))) {
        fprintf(stderr, "usage: old_client corrected-euler|inputs < SET-inputs.csv\n");
        return 2;
    }
    int inputs = !strcmp(argv[1], "inputs"), disagree = 0;
    char line[8192];
    if (!fgets(line, sizeof line, stdin)) { fprintf(stderr, "old_client: no header\n"); return 2; }
    printf(inputs ? "case,component,precision,value\n" : "case,pixel,value\n");
    int row = 1;
    while (fgets(line, sizeof line, stdin)) {
        row++;
        char *f[16]; int k = 0;
        /* Fields may be empty (the specular columns): split on every comma. */
        char *p = line;
        while (k < 16) {
            f[k++] = p;
            char *c = strchr(p, ',');
            if (!c) break;
            *c = '\0'; p = c + 1;
        }
        if (k < 11) { fprintf(stderr, "old_client: line %d: %d fields\n", row, k); return 2; }
        int n = atoi(f[1]), ok = 1, okj;
        float na[3], nb[3], l[3];
        for (int j = 0; j < 3; j++) {
            na[j] = exact_input_f32(f[2 + j], &okj); ok &= okj;
            nb[j] = exact_input_f32(f[5 + j], &okj); ok &= okj;
            l[j] = exact_input_f32(f[8 + j], &okj); ok &= okj;
        }
        if (!ok || n < 1) { fprintf(stderr, "old_client: line %d: not exact inputs\n", row); return 2; }
        if (inputs) {
            /* The specular columns h_x, h_y, h_z follow l_z, when given. */
            int m = k >= 14 && f[11][0] ? 12 : 9;
            for (int j = 0; j < m; j++) {
                int o1, o2, o3, o4;
                float x = exact_input_f32(f[2 + j], &o1);
                double y = exact_input_f64(f[2 + j], &o2);
                double x2 = exact_input(f[2 + j], 24, &o3), y2 = exact_input(f[2 + j], 53, &o4);
                if (!o1 || !o2) { fprintf(stderr, "old_client: line %d: not exact inputs\n", row); return 2; }
                if (!o3 || !o4 || memcmp(&x2, &(double){x}, sizeof x2) || memcmp(&y2, &y, sizeof y)) {
                    fprintf(stderr, "old_client: %s %s: exact_input disagrees with exact_input_f32/_f64\n",
                            f[0], component_names[j]);
                    disagree = 1;
                }
                printf("%s,%s,f32,%a\n", f[0], component_names[j], (double)x);
                printf("%s,%s,f64,%a\n", f[0], component_names[j], y);
            }
            continue;
        }
        corrected_euler(f[0], na, nb, l, n);
    }
    if (fflush(stdout) != 0 || ferror(stdout)) { perror("old_client: standard output"); return 1; }
    return disagree;
}
