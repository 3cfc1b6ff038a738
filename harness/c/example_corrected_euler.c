/* SPDX-License-Identifier: MIT OR Apache-2.0 */
/* An example of what you write to test your own shading code with phong_kit: the
 * paper's corrected Euler method in float, and a three-line main.
 *
 *   harness/c/run.sh harness/c/example_corrected_euler.c --method corrected-euler
 *
 * builds it with phong_kit.c, runs it on every published set and checks the results
 * with `phong-approx check`. Replace shade() with your own code (keep its signature)
 * and pass the method it implements to run.sh's --method.
 */
#include "phong_kit.h"

static float dot(const float a[3], const float b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Corrected Euler along one span: Phong's N(i)·L/|N(i)| (the normal interpolated,
 * not normalized) approximated by a second-order forward difference whose first
 * step t0 is corrected so that the span ends on p_b = N_b·L (the paper's eqs. 2-3,
 * 10-11, 14-17; docs/derivations.md §6). Writes out[0..c->n]. */
static int shade(const pk_case_f32 *c, float *out, void *user) {
    const float *na = c->na, *nb = c->nb, *l = c->l;
    float nf = (float)c->n, k[3];
    (void)user;
    if (c->part != PK_DIFFUSE) return 1; /* this example shades the diffuse part only */
    for (int j = 0; j < 3; j++) k[j] = (nb[j] - na[j]) / nf;
    float A = dot(k, l);                 /* eq. 2 */
    float C = dot(k, k);                 /* eq. 3 */
    float D = 2.0f * dot(k, na);
    float pa = dot(na, l), pb = dot(nb, l);
    float dqb = 2.0f * nf * C + D;       /* eqs. 10-11: q'(n) */
    float dia = A - pa / 2.0f * D;       /* the slope at pixel 0 */
    float dib = A - pb / 2.0f * dqb;     /* and at pixel n */
    float ds = (dib - dia) / nf;         /* its change per pixel */
    /* eq. 14: where plain Euler would end; n(n - 1)/2 is exact in a double */
    float pn = pa + nf * dia + (float)((double)c->n * (double)(c->n - 1) / 2) * ds;
    float eps = pn - pb;                 /* eq. 15: its error at pixel n */
    float t0 = dia - eps / nf;           /* eq. 17: the first step, corrected */
    float p = pa, t = t0;
    for (long i = 0; i <= c->n; i++) {   /* eqs. 16-17 */
        out[i] = p;
        p += t;
        t += ds;
    }
    return 0;
}

int main(int argc, char **argv) {
    return pk_main(argc, argv, shade, NULL, NULL);
}
