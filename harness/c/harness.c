/* A C harness for phong-approx's published vectors: reads SET-inputs.csv (exact
 * fractions, rounded once to float by exact_input.h), shades every span with one of
 * the paper's methods in float, and writes `case,pixel,value` rows for
 * `phong-approx check`.
 *
 *   cc -O2 -o harness harness.c -lm
 *   ./harness corrected-euler < vectors/typical-inputs.csv > ce.csv
 *   phong-approx check --vectors vectors/typical.json --results ce.csv --method corrected-euler
 *
 * Methods: gouraud, euler, corrected-euler, phong, duff; `inputs` prints each case's
 * nine inputs as rounded to float and to double (hex), to check exact_input.h.
 * Exit 2 on bad input.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "exact_input.h"

static float dot(const float a[3], const float b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The paper's set-up (eqs. 2-3, 10-11, 14-17). */
typedef struct { float pa, pb, A, C, D, E, dia, ds, t0, dp; } setup_t;

static setup_t setup(const float na[3], const float nb[3], const float l[3], int n) {
    setup_t s;
    float k[3], nf = (float)n;
    for (int j = 0; j < 3; j++) k[j] = (nb[j] - na[j]) / nf;
    s.A = dot(k, l);
    s.C = dot(k, k);
    s.D = 2.0f * dot(k, na);
    s.E = dot(na, na);
    s.pa = dot(na, l);
    s.pb = dot(nb, l);
    float dqb = 2.0f * nf * s.C + s.D;
    s.dia = s.A - s.pa / 2.0f * s.D;
    float dib = s.A - s.pb / 2.0f * dqb;
    s.ds = (dib - s.dia) / nf;
    float pn = s.pa + nf * s.dia + (float)((long)n * (n - 1) / 2) * s.ds; /* eq. 14 */
    s.t0 = s.dia - (pn - s.pb) / nf;                                     /* eq. 17 */
    s.dp = (s.pb - s.pa) / nf;
    return s;
}

static void shade(const char *method, const char *id, const float na[3], const float nb[3],
                  const float l[3], int n) {
    setup_t s = setup(na, nb, l, n);
    if (!strcmp(method, "gouraud")) {
        float g = s.pa;
        for (int i = 0; i <= n; i++) { printf("%s,%d,%.9g\n", id, i, g); g += s.dp; }
    } else if (!strcmp(method, "euler") || !strcmp(method, "corrected-euler")) {
        float p = s.pa, t = strcmp(method, "euler") ? s.t0 : s.dia;
        for (int i = 0; i <= n; i++) { printf("%s,%d,%.9g\n", id, i, p); p += t; t += s.ds; }
    } else if (!strcmp(method, "phong")) {
        float k[3];
        for (int j = 0; j < 3; j++) k[j] = (nb[j] - na[j]) / (float)n;
        for (int i = 0; i <= n; i++) {
            float N[3];
            for (int j = 0; j < 3; j++) N[j] = na[j] + (float)i * k[j];
            printf("%s,%d,%.9g\n", id, i, dot(N, l) / sqrtf(dot(N, N)));
        }
    } else { /* duff: eqs. 5-7, forward differences of p and q */
        float p = s.pa, q = s.E, dq = s.C + s.D;
        for (int i = 0; i <= n; i++) {
            printf("%s,%d,%.9g\n", id, i, p / sqrtf(q));
            p += s.A; q += dq; dq += 2.0f * s.C;
        }
    }
}

int main(int argc, char **argv) {
    const char *methods[] = {"gouraud", "euler", "corrected-euler", "phong", "duff", "inputs"};
    int known = 0;
    for (int m = 0; argc == 2 && m < 6; m++) known |= !strcmp(argv[1], methods[m]);
    if (!known) {
        fprintf(stderr, "usage: harness gouraud|euler|corrected-euler|phong|duff|inputs < SET-inputs.csv\n");
        return 2;
    }
    char line[8192];
    if (!fgets(line, sizeof line, stdin)) { fprintf(stderr, "harness: no header\n"); return 2; }
    int inputs = !strcmp(argv[1], "inputs");
    printf(inputs ? "case,component,f32,f64\n" : "case,pixel,value\n");
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
        if (k < 11) { fprintf(stderr, "harness: line %d: %d fields\n", row, k); return 2; }
        int n = atoi(f[1]), ok = 1, okj;
        float na[3], nb[3], l[3];
        for (int j = 0; j < 3; j++) {
            na[j] = exact_input_f32(f[2 + j], &okj); ok &= okj;
            nb[j] = exact_input_f32(f[5 + j], &okj); ok &= okj;
            l[j] = exact_input_f32(f[8 + j], &okj); ok &= okj;
        }
        if (!ok || n < 1) { fprintf(stderr, "harness: line %d: not exact inputs\n", row); return 2; }
        if (inputs) {
            for (int j = 0; j < 9; j++) {
                int o1, o2;
                float x = exact_input_f32(f[2 + j], &o1);
                double y = exact_input_f64(f[2 + j], &o2);
                printf("%s,%d,%a,%a\n", f[0], j, (double)x, y);
            }
            continue;
        }
        shade(argv[1], f[0], na, nb, l, n);
    }
    return 0;
}
