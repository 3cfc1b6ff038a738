/* SPDX-License-Identifier: MIT OR Apache-2.0 */
/* The six methods of methods.c in one floating type. methods.c includes this file
 * twice: with REAL float, SQRT sqrtf, POW powf and SUF f32, and with REAL double,
 * SQRT sqrt, POW pow and SUF f64. Each PK_SUF(name) becomes name_f32 or name_f64. */
#define PK_SUF(name) PK_PASTE(name, SUF)

static REAL PK_SUF(dot)(const REAL a[3], const REAL b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The paper's set-up (eqs. 2-3, 10-11, 14-17). */
typedef struct { REAL pa, pb, A, C, D, E, dia, ds, t0, dp; } PK_SUF(setup_t);

static PK_SUF(setup_t) PK_SUF(setup)(const REAL na[3], const REAL nb[3], const REAL l[3],
                                     long n) {
    PK_SUF(setup_t) s;
    REAL k[3], nf = (REAL)n;
    for (int j = 0; j < 3; j++) k[j] = (nb[j] - na[j]) / nf;
    s.A = PK_SUF(dot)(k, l);
    s.C = PK_SUF(dot)(k, k);
    s.D = (REAL)2 * PK_SUF(dot)(k, na);
    s.E = PK_SUF(dot)(na, na);
    s.pa = PK_SUF(dot)(na, l);
    s.pb = PK_SUF(dot)(nb, l);
    REAL dqb = (REAL)2 * nf * s.C + s.D;
    s.dia = s.A - s.pa / (REAL)2 * s.D;
    REAL dib = s.A - s.pb / (REAL)2 * dqb;
    s.ds = (dib - s.dia) / nf;
    /* eq. 14; n(n - 1)/2 is a whole number below 2^40, exact in a double */
    REAL pn = s.pa + nf * s.dia + (REAL)((double)n * (double)(n - 1) / 2) * s.ds;
    s.t0 = s.dia - (pn - s.pb) / nf; /* eq. 17 */
    s.dp = (s.pb - s.pa) / nf;
    return s;
}

static int PK_SUF(shade)(const PK_SUF(pk_case) *c, REAL *out, void *user) {
    int method = *(const int *)user;
    long n = c->n;
    /* Specular: the method run with H in place of L, then max(0, v)^s. */
    const REAL *l = c->part == PK_SPECULAR ? c->h : c->l;
    PK_SUF(setup_t) s = PK_SUF(setup)(c->na, c->nb, l, n);
    if (method == GOURAUD) {
        REAL g = s.pa;
        for (long i = 0; i <= n; i++) { out[i] = g; g += s.dp; }
    } else if (method == EULER || method == CORRECTED_EULER) {
        REAL p = s.pa, t = method == CORRECTED_EULER ? s.t0 : s.dia;
        for (long i = 0; i <= n; i++) { out[i] = p; p += t; t += s.ds; }
    } else if (method == PHONG) {
        REAL k[3];
        for (int j = 0; j < 3; j++) k[j] = (c->nb[j] - c->na[j]) / (REAL)n;
        for (long i = 0; i <= n; i++) {
            REAL N[3];
            for (int j = 0; j < 3; j++) N[j] = c->na[j] + (REAL)i * k[j];
            out[i] = PK_SUF(dot)(N, l) / SQRT(PK_SUF(dot)(N, N));
        }
    } else if (method == SQUARED) {
        /* §7.1 (b): corrected Euler (eqs. 15-17) on g = p^2/q, no square root in the
         * set-up, then the value sign(p) sqrt(max(0, g)) with p by its own recurrence. */
        REAL k[3], nf = (REAL)n, two = (REAL)2;
        for (int j = 0; j < 3; j++) k[j] = (c->nb[j] - c->na[j]) / nf;
        REAL A = PK_SUF(dot)(k, l), B = PK_SUF(dot)(c->na, l), C = PK_SUF(dot)(k, k);
        REAL D = two * PK_SUF(dot)(k, c->na), E = PK_SUF(dot)(c->na, c->na);
        REAL pb = PK_SUF(dot)(c->nb, l), qb = PK_SUF(dot)(c->nb, c->nb);
        REAL dqb = two * nf * C + D;
        REAL ga = B * B / E, gb = pb * pb / qb;
        REAL dga = B * (two * A * E - B * D) / (E * E);
        REAL dgb = pb * (two * A * qb - pb * dqb) / (qb * qb);
        REAL ds = (dgb - dga) / nf;
        REAL eps = ga + nf * dga + (REAL)((double)n * (double)(n - 1) / 2) * ds - gb;
        REAL g = ga, t = dga - eps / nf, p = B;
        for (long i = 0; i <= n; i++) {
            REAL v = g > 0 ? SQRT(g) : 0;
#ifndef PK_PLANT_SQUARED_NO_SIGN /* ci.sh's planted bug: the sign dropped */
            if (p < 0) v = -v;
            else if (p == 0) v = 0;
#endif
            out[i] = v;
            g += t; t += ds; p += A;
        }
    } else { /* duff: eqs. 5-7, forward differences of p and q */
        REAL p = s.pa, q = s.E, dq = s.C + s.D;
        for (long i = 0; i <= n; i++) {
            out[i] = p / SQRT(q);
            p += s.A; q += dq; dq += (REAL)2 * s.C;
        }
    }
    if (c->part == PK_SPECULAR)
        for (long i = 0; i <= n; i++) out[i] = out[i] > 0 ? POW(out[i], (REAL)c->s) : 0;
    return 0;
}

#undef PK_SUF
