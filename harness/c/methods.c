/* SPDX-License-Identifier: MIT OR Apache-2.0 */
/* This repository's own C implementations of six of the paper's methods, written
 * against phong_kit.h as a user would, in float and in double: what CI runs
 * (harness/c/ci.sh) on every published set.
 *
 *   cc -O2 -std=c99 -o methods methods.c phong_kit.c -lm
 *   ./methods corrected-euler [--precision f32|f64] [--specular] SET-inputs.csv > R.csv
 *   ./methods inputs SET-inputs.csv
 *
 * Methods: gouraud, euler, corrected-euler, phong, duff, squared-corrected-euler (the arithmetic of
 * methods_body.h, the paper's equations in the order of src/). `inputs` prints
 * every input of every case as the kit read it, as `case,component,precision,hex`
 * rows (C99 %a), for ci.sh to compare with the vector file's f32 and f64 forms.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "phong_kit.h"

enum { GOURAUD, EULER, CORRECTED_EULER, PHONG, DUFF, SQUARED, INPUTS };
static const char *const method_names[] = {"gouraud", "euler", "corrected-euler", "phong",
                                           "duff", "squared-corrected-euler", "inputs"};

#define PK_PASTE2(a, b) a##_##b
#define PK_PASTE(a, b) PK_PASTE2(a, b)

#define REAL float
#define SQRT sqrtf
#define POW powf
#define SUF f32
#include "methods_body.h"
#undef REAL
#undef SQRT
#undef POW
#undef SUF

#define REAL double
#define SQRT sqrt
#define POW pow
#define SUF f64
#include "methods_body.h"
#undef REAL
#undef SQRT
#undef POW
#undef SUF

static const char *const component_names[12] = {"na_x", "na_y", "na_z", "nb_x", "nb_y",
                                                 "nb_z", "l_x",  "l_y",  "l_z",  "h_x",
                                                 "h_y",  "h_z"};

/* `inputs`: print the case's inputs instead of shading (out is left as NaN). A
 * write to standard output that fails stops the printing, its errno in
 * *(int *)user (inputs() then says it, in one line). */
static int printed(int result, void *user) {
    if (result >= 0) return 0;
    *(int *)user = errno ? errno : -1;
    return 1;
}

static int print_f32(const pk_case_f32 *c, float *out, void *user) {
    const float *v[4] = {c->na, c->nb, c->l, c->h};
    (void)out;
    for (int j = 0; !*(int *)user && j < (c->has_specular ? 12 : 9); j++) {
        errno = 0;
        if (printed(printf("%s,%s,f32,%a\n", c->id, component_names[j], (double)v[j / 3][j % 3]), user))
            break;
    }
    return 0;
}

static int print_f64(const pk_case_f64 *c, double *out, void *user) {
    const double *v[4] = {c->na, c->nb, c->l, c->h};
    (void)out;
    for (int j = 0; !*(int *)user && j < (c->has_specular ? 12 : 9); j++) {
        errno = 0;
        if (printed(printf("%s,%s,f64,%a\n", c->id, component_names[j], v[j / 3][j % 3]), user))
            break;
    }
    return 0;
}

static int inputs(const char *path) {
    FILE *in = fopen(path, "r"), *sink = tmpfile();
    int rc = PK_BAD_INPUT, err = 0;
    if (!in || !sink) {
        fprintf(stderr, "methods: cannot open %s or a temporary file: %s\n", path, strerror(errno));
    } else {
        errno = 0;
        if (!printed(printf("case,component,precision,value\n"), &err)) {
            rc = pk_run_f32(in, path, sink, 0, print_f32, &err);
            rewind(in);
            if (rc == PK_OK) rc = pk_run_f64(in, path, sink, 0, print_f64, &err);
        }
    }
    if (in) fclose(in);
    if (sink) fclose(sink);
    errno = 0;
    if (!err && (fflush(stdout) != 0 || ferror(stdout))) err = errno ? errno : -1;
    if (err) {
        fprintf(stderr, "methods: cannot write to <stdout>: %s\n",
                err > 0 ? strerror(err) : "a write error, with no reason given by the C library");
        rc = PK_BAD_INPUT;
    }
    return rc;
}

int main(int argc, char **argv) {
    int method = -1;
    for (int m = 0; argc >= 2 && m <= INPUTS; m++)
        if (!strcmp(argv[1], method_names[m])) method = m;
    if (method < 0 || (method == INPUTS && argc != 3)) {
        fprintf(stderr, "usage: methods gouraud|euler|corrected-euler|phong|duff|"
                        "squared-corrected-euler "
                        "[--precision f32|f64] [--specular] [SET-inputs.csv]\n"
                        "       methods inputs SET-inputs.csv\n");
        return PK_BAD_INPUT;
    }
    if (method == INPUTS) return inputs(argv[2]);
    argv[1] = argv[0]; /* pk_main reads the rest: options and the inputs file */
    return pk_main(argc - 1, argv + 1, shade_f32, shade_f64, &method);
}
