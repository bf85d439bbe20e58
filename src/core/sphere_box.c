/*
 * sphere_box.c -- exact volume of sphere ∩ axis-aligned box, the reference for the other kernels.
 *
 * Slice the sphere along x: the slice is a disk of radius rho(x) = sqrt(R^2 - (x-cx)^2), and its
 * intersection with the rectangle [y0,y1]x[z0,z1] has a closed-form area (inclusion-exclusion of
 * quarter-plane areas, each an integral of sqrt(rho^2 - y^2)). The volume is the integral of that
 * area over x, done by adaptive Gauss-Kronrod (7-15) between the x where the slice area stops
 * being smooth (rho crossing a rectangle edge or corner distance).
 */
#include "internal.h"

#include <math.h>
#include <stdlib.h>

/* Primitive of sqrt(rho^2 - y^2), valid on [-rho, rho]. */
static double prim(double y, double rho)
{
    if (y <= -rho) return -0.25 * CDC_PI * rho * rho;
    if (y >= rho) return 0.25 * CDC_PI * rho * rho;
    return 0.5 * (y * sqrt(rho * rho - y * y) + rho * rho * asin(y / rho));
}

/* Area of {y^2 + z^2 < rho^2, y < a, z < b}. */
static double quarter_area(double a, double b, double rho)
{
    if (a <= -rho || b <= -rho) return 0.0;
    if (a > rho) a = rho;
    if (b >= rho) return 2.0 * (prim(a, rho) - prim(-rho, rho)); /* only the y-limit cuts */
    /* Chord length in z at height y is min(b, s) + s where s = sqrt(rho^2 - y^2), clipped at 0.
     * Inside |y| < yb (s > |b|) it is b + s; outside it is 2 s for b >= 0 and 0 for b < 0. */
    const double yb = sqrt(rho * rho - b * b);
    double area = 0.0;
    /* part y in [-rho, -yb]: outer region */
    if (b >= 0.0) area += 2.0 * (prim(fmin(a, -yb), rho) - prim(-rho, rho));
    if (a <= -yb) return area;
    /* part y in [-yb, min(a, yb)]: inner region */
    const double hi = fmin(a, yb);
    area += b * (hi + yb) + prim(hi, rho) - prim(-yb, rho);
    if (a <= yb) return area;
    /* part y in [yb, a]: outer region */
    if (b >= 0.0) area += 2.0 * (prim(a, rho) - prim(yb, rho));
    return area;
}

typedef struct { double cx, R, y0, y1, z0, z1; } slice_geom;

static double slice_area(const slice_geom *g, double x)
{
    const double h2 = g->R * g->R - (x - g->cx) * (x - g->cx);
    if (h2 <= 0.0) return 0.0;
    const double rho = sqrt(h2);
    return quarter_area(g->y1, g->z1, rho) - quarter_area(g->y0, g->z1, rho) - quarter_area(g->y1, g->z0, rho) +
           quarter_area(g->y0, g->z0, rho);
}

static const double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                              0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
static const double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                              0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                              0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                              0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                             0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

static double gk15(const slice_geom *g, double a, double b, double *err)
{
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    const double fc = slice_area(g, c);
    double k = fc * wgk[7], gs = fc * wg[3];
    for (int j = 0; j < 7; ++j) {
        const double f = slice_area(g, c - h * xgk[j]) + slice_area(g, c + h * xgk[j]);
        k += wgk[j] * f;
        if (j % 2 == 1) gs += wg[j / 2] * f;
    }
    *err = fabs((k - gs) * h);
    return k * h;
}

static double adapt(const slice_geom *g, double a, double b, double tol, int depth)
{
    double err;
    const double v = gk15(g, a, b, &err);
    if (err <= tol || depth >= 12) return v;
    const double m = 0.5 * (a + b);
    return adapt(g, a, m, 0.5 * tol, depth + 1) + adapt(g, m, b, 0.5 * tol, depth + 1);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double cdc_sphere_box_volume(const double c[3], double R, const double lo[3], const double hi[3])
{
    const double xa = fmax(lo[0], c[0] - R), xb = fmin(hi[0], c[0] + R);
    if (!(R > 0.0) || xa >= xb || lo[1] >= hi[1] || lo[2] >= hi[2]) return 0.0;
    const slice_geom g = {c[0], R, lo[1] - c[1], hi[1] - c[1], lo[2] - c[2], hi[2] - c[2]};

    /* x where rho(x) equals an edge distance or a corner distance: the area's kinks. */
    double brk[2 + 2 * 8];
    int nb = 0;
    brk[nb++] = xa;
    brk[nb++] = xb;
    const double ys[2] = {g.y0, g.y1}, zs[2] = {g.z0, g.z1};
    double dist[8];
    int nd = 0;
    for (int i = 0; i < 2; ++i) {
        dist[nd++] = fabs(ys[i]);
        dist[nd++] = fabs(zs[i]);
        for (int j = 0; j < 2; ++j) dist[nd++] = sqrt(ys[i] * ys[i] + zs[j] * zs[j]);
    }
    for (int k = 0; k < nd; ++k)
        if (dist[k] < R) {
            const double dx = sqrt(R * R - dist[k] * dist[k]);
            for (int s = -1; s <= 1; s += 2) {
                const double x = c[0] + s * dx;
                if (x > xa && x < xb) brk[nb++] = x;
            }
        }
    qsort(brk, (size_t)nb, sizeof brk[0], cmp_double);
    /* absolute tolerance per segment; the 15-point rule is far more accurate than its error estimate */
    const double tol = 1e-13 * R * R * R;
    double v = 0.0;
    for (int k = 0; k + 1 < nb; ++k)
        if (brk[k + 1] > brk[k]) v += adapt(&g, brk[k], brk[k + 1], tol, 0);
    return v;
}
