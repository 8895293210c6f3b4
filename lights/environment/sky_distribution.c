/* sky_distribution.c - gradation x indicatrix skies (CIE standard general
 * skies, Perez all-weather sky): luminance, exact illuminance by quadrature
 * about the sun, bounds over a region, sampling. See sky_distribution.h. */
#include "lights/environment/sky_distribution.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/environment/environment_bounds.h"
#include "radiometry/constants.h"
#include "radiometry/sampling.h"

/* ISO 15469:2004 (CIE S 011/E:2003), Table 1: the standard parameters of
 * the 15 sky types, gradation groups I-VI (a, b) and indicatrix groups
 * 1-6 (c, d, e) combined as the standard lists them. */
static const double cie_table[CDL_SKY_CIE_TYPES][5] = {
    /*  a      b      c     d     e */
    {4.0, -0.70, 0.0, -1.0, 0.00},   /*  1 I.1   overcast, steep gradation towards the zenith, azimuthal uniformity */
    {4.0, -0.70, 2.0, -1.5, 0.15},   /*  2 I.2   overcast, steep gradation, slight brightening towards the sun */
    {1.1, -0.80, 0.0, -1.0, 0.00},   /*  3 II.1  overcast, moderate gradation, azimuthal uniformity */
    {1.1, -0.80, 2.0, -1.5, 0.15},   /*  4 II.2  overcast, moderate gradation, slight brightening towards the sun */
    {0.0, -1.00, 0.0, -1.0, 0.00},   /*  5 III.1 sky of uniform luminance */
    {0.0, -1.00, 2.0, -1.5, 0.15},   /*  6 III.2 partly cloudy, no gradation, slight brightening towards the sun */
    {0.0, -1.00, 5.0, -2.5, 0.30},   /*  7 III.3 partly cloudy, no gradation, brighter circumsolar region */
    {0.0, -1.00, 10.0, -3.0, 0.45},  /*  8 III.4 partly cloudy, no gradation, distinct solar corona */
    {-1.0, -0.55, 2.0, -1.5, 0.15},  /*  9 IV.2  partly cloudy, obscured sun */
    {-1.0, -0.55, 5.0, -2.5, 0.30},  /* 10 IV.3  partly cloudy, brighter circumsolar region */
    {-1.0, -0.55, 10.0, -3.0, 0.45}, /* 11 IV.4  white-blue sky, distinct solar corona */
    {-1.0, -0.32, 10.0, -3.0, 0.45}, /* 12 V.4   CIE standard clear sky, low luminance turbidity */
    {-1.0, -0.32, 16.0, -3.0, 0.30}, /* 13 V.5   CIE standard clear sky, polluted atmosphere */
    {-1.0, -0.15, 16.0, -3.0, 0.30}, /* 14 VI.5  cloudless turbid sky, broad solar corona */
    {-1.0, -0.15, 24.0, -2.8, 0.15}, /* 15 VI.6  white-blue turbid sky, broad solar corona */
};

int cdl_sky_cie_parameters(int type, double out[5])
{
    if (type < 1 || type > CDL_SKY_CIE_TYPES) return 0;
    memcpy(out, cie_table[type - 1], 5 * sizeof(double));
    return 1;
}

int cdl_sky_cie_type_uses_sun(int type)
{
    return type >= 1 && type <= CDL_SKY_CIE_TYPES && (cie_table[type - 1][2] != 0.0 || cie_table[type - 1][4] != 0.0);
}

/* The gradation phi at cos Z (> 0) and the indicatrix f at chi. */
static double gradation(const cdl_sky_distribution *s, double cos_z)
{
    return 1.0 + s->a * exp(s->b / cos_z);
}

static double indicatrix(const cdl_sky_distribution *s, double chi)
{
    double c = cos(chi);
    return 1.0 + s->c * (exp(s->d * chi) - s->k) + s->e * c * c;
}

/* phi(Z) f(chi), 0 below the horizon, clamped at 0 for Perez. */
static double shape(const cdl_sky_distribution *s, double cos_z, double chi)
{
    if (!(cos_z > 0.0)) return 0.0;
    double v = gradation(s, cos_z) * indicatrix(s, chi);
    return s->clamp && v < 0.0 ? 0.0 : v;
}

static double angle_to_sun(const cdl_sky_distribution *s, cdl_vec3 w)
{
    /* atan2 of |s x w| and s.w: accurate near the sun, where acos is not */
    return atan2(cdl_vec3_length(cdl_vec3_cross(s->sun, w)), cdl_vec3_dot(s->sun, w));
}

double cdl_sky_distribution_luminance(const cdl_sky_distribution *s, cdl_vec3 w)
{
    return s->scale * shape(s, cdl_vec3_dot(w, s->frame.n), angle_to_sun(s, w));
}

/* ---- illuminance ------------------------------------------------------------ */

/* Gauss-Legendre nodes and weights on [0, 1] (Newton's method on the
 * Legendre polynomial P_N from the Chebyshev-like first guesses, Press et
 * al., "Numerical Recipes", 3rd ed., 4.6). */
static void gauss_legendre(double *x, double *w, int N)
{
    for (int i = 0; i < N; ++i) {
        double z = cos(CDL_PI * (i + 0.75) / (N + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = 0.0;
            for (int j = 1; j <= N; ++j) {
                double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
            }
            dp = N * (z * p0 - p1) / (z * z - 1.0);
            double dz = p0 / dp;
            z -= dz;
            if (fabs(dz) < 1e-16) break;
        }
        x[i] = 0.5 * (1.0 - z);
        w[i] = 1.0 / ((1.0 - z * z) * dp * dp); /* 2 / ((1 - z^2) P'^2), halved for [0, 1] */
    }
}

/* The arc of [0, pi] where A cos chi + B sin chi > 0 (one arc: two half
 * circles meet in one); 0 when empty. A > 0: from 0 to the zero
 * atan2(A, -B); A < 0: from the zero atan2(-A, B) to pi. */
static int positive_arc(double A, double B, double *lo, double *hi)
{
    if (A > 0.0) {
        *lo = 0.0;
        *hi = atan2(A, -B);
    } else if (A < 0.0) {
        *lo = atan2(-A, B);
        *hi = CDL_PI;
    } else if (B > 0.0) {
        *lo = 0.0;
        *hi = CDL_PI;
    } else {
        return 0;
    }
    return *hi > *lo;
}

/* A vector in the sun's frame: its component along the sun (A) and across
 * it (B(psi) = p cos psi + q sin psi). */
typedef struct sun_components {
    double A, p, q;
} sun_components;

static sun_components components(const cdl_sky_distribution *s, cdl_vec3 v)
{
    sun_components c = {cdl_vec3_dot(v, s->sun_frame.n), cdl_vec3_dot(v, s->sun_frame.s),
                        cdl_vec3_dot(v, s->sun_frame.t)};
    return c;
}

/* The meridian psi: int over chi of phi f (n.w) sin chi. */
static double meridian(const cdl_sky_distribution *s, const sun_components *up, const sun_components *n, double psi)
{
    double cp = cos(psi), sp = sin(psi);
    double Bu = up->p * cp + up->q * sp, Bn = n->p * cp + n->q * sp;
    double lo_u, hi_u, lo_n, hi_n;
    if (!positive_arc(up->A, Bu, &lo_u, &hi_u) || !positive_arc(n->A, Bn, &lo_n, &hi_n)) return 0.0;
    double lo = fmax(lo_u, lo_n), hi = fmin(hi_u, hi_n);
    if (!(hi > lo)) return 0.0;
    /* the interval in parts: more where it is long (the horizon's steep
     * gradation of the turbid skies, the sun's peak) */
    int parts = hi - lo > 1.0 ? 6 : 3;
    double h = 1.0 / parts, span = hi - lo, sum = 0.0;
    for (int k = 0; k < parts; ++k)
        for (int i = 0; i < CDL_SKY_QUADRATURE_POINTS; ++i) {
            double t = h * (k + s->gl_x[i]);
            double chi = lo + span * t * t * (3.0 - 2.0 * t), jac = span * 6.0 * t * (1.0 - t);
            double c = cos(chi), si = sin(chi);
            double cos_z = up->A * c + Bu * si, cos_n = n->A * c + Bn * si;
            if (!(cos_n > 0.0)) continue;
            sum += s->gl_w[i] * jac * shape(s, cos_z, chi) * cos_n * si;
        }
    return sum * h;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Add psi (any value) reduced to [0, 2 pi). */
static void add_break(double *breaks, int *count, double psi)
{
    double r = fmod(psi, CDL_TWO_PI);
    breaks[(*count)++] = r < 0.0 ? r + CDL_TWO_PI : r;
}

double cdl_sky_distribution_illuminance(const cdl_sky_distribution *s, cdl_vec3 n)
{
    sun_components up = components(s, s->frame.n), nc = components(s, n);
    /* psi where the binding constraint may change: +-(up x n), and where
     * either constraint's B(psi) is 0 */
    double breaks[8];
    int count = 0;
    const sun_components *both[2] = {&up, &nc};
    for (int k = 0; k < 2; ++k)
        if (hypot(both[k]->p, both[k]->q) > 1e-12) {
            double psi = atan2(both[k]->q, both[k]->p);
            add_break(breaks, &count, psi + 0.5 * CDL_PI);
            add_break(breaks, &count, psi - 0.5 * CDL_PI);
        }
    cdl_vec3 l = cdl_vec3_cross(s->frame.n, n);
    if (cdl_vec3_length(l) > 1e-12) {
        sun_components lc = components(s, l);
        if (hypot(lc.p, lc.q) > 1e-12) {
            double psi = atan2(lc.q, lc.p);
            add_break(breaks, &count, psi);
            add_break(breaks, &count, psi + CDL_PI);
        }
    }
    if (count == 0) add_break(breaks, &count, 0.0);
    qsort(breaks, (size_t)count, sizeof *breaks, cmp_double);
    double total = 0.0;
    for (int b = 0; b < count; ++b) {
        double a0 = breaks[b], a1 = b + 1 < count ? breaks[b + 1] : breaks[0] + CDL_TWO_PI;
        if (!(a1 - a0 > 1e-15)) continue;
        /* the panel in parts of at most pi / 4 */
        int parts = (int)ceil((a1 - a0) / (0.25 * CDL_PI));
        double h = (a1 - a0) / parts;
        for (int k = 0; k < parts; ++k)
            for (int i = 0; i < CDL_SKY_QUADRATURE_POINTS; ++i)
                total += s->gl_w[i] * h * meridian(s, &up, &nc, a0 + h * (k + s->gl_x[i]));
    }
    return s->scale * total;
}

/* ---- bounds -------------------------------------------------------------------- */

static void interval_product(double a_lo, double a_hi, double b_lo, double b_hi, double *lo, double *hi)
{
    double p[4] = {a_lo * b_lo, a_lo * b_hi, a_hi * b_lo, a_hi * b_hi};
    *lo = *hi = p[0];
    for (int i = 1; i < 4; ++i) {
        *lo = fmin(*lo, p[i]);
        *hi = fmax(*hi, p[i]);
    }
}

void cdl_sky_distribution_bounds(const cdl_sky_distribution *s, const cdl_vec3 *dirs, int count, double *lo,
                                 double *hi)
{
    cdl_env_extent ez, ec;
    cdl_env_extent_of_polygon(&s->frame, dirs, count, &ez);
    cdl_env_extent_of_polygon(&s->sun_frame, dirs, count, &ec);
    if (!(ez.cos_hi > 0.0)) {
        *lo = *hi = 0.0; /* wholly below the horizon */
        return;
    }
    /* gradation: monotone in cos Z (b < 0); towards the horizon it tends to 1 */
    double g1 = ez.cos_lo > 0.0 ? gradation(s, ez.cos_lo) : 1.0, g2 = gradation(s, ez.cos_hi);
    double g_lo = fmin(g1, g2), g_hi = fmax(g1, g2);
    /* indicatrix: exp(d chi) monotone; cos^2 chi over [chi_1, chi_2] */
    double chi1 = acos(fmin(1.0, ec.cos_hi)), chi2 = acos(fmax(-1.0, ec.cos_lo));
    double x1 = s->c * exp(s->d * chi1), x2 = s->c * exp(s->d * chi2);
    double c1 = ec.cos_hi * ec.cos_hi, c2 = ec.cos_lo * ec.cos_lo;
    double q_lo = ec.cos_lo <= 0.0 && ec.cos_hi >= 0.0 ? 0.0 : fmin(c1, c2), q_hi = fmax(c1, c2);
    double f_lo = 1.0 - s->c * s->k + fmin(x1, x2) + fmin(s->e * q_lo, s->e * q_hi);
    double f_hi = 1.0 - s->c * s->k + fmax(x1, x2) + fmax(s->e * q_lo, s->e * q_hi);
    interval_product(g_lo, g_hi, f_lo, f_hi, lo, hi);
    *lo = fmax(0.0, *lo) * s->scale;
    *hi = fmax(0.0, *hi) * s->scale;
    /* the region reaches below the horizon: 0 is among its values */
    if (ez.cos_lo <= 0.0) *lo = 0.0;
}

/* ---- sampling ------------------------------------------------------------------ */

static double sun_lambda(const cdl_sky_distribution *s)
{
    return fmax(1.0, fabs(s->d));
}

/* the part about the sun: chi with density lambda e^(-lambda chi) / (1 -
 * e^(-lambda pi)) on [0, pi], psi uniform; in solid angle that over
 * 2 pi sin chi */
static double sun_part_pdf(const cdl_sky_distribution *s, cdl_vec3 w)
{
    double lambda = sun_lambda(s), chi = angle_to_sun(s, w), sin_chi = sin(chi);
    if (!(sin_chi > 0.0)) return INFINITY;
    return lambda * exp(-lambda * chi) / ((1.0 - exp(-lambda * CDL_PI)) * CDL_TWO_PI * sin_chi);
}

double cdl_sky_distribution_pdf(const cdl_sky_distribution *s, cdl_vec3 n, cdl_vec3 w)
{
    double cos_part = fmax(0.0, cdl_vec3_dot(n, w)) * CDL_INV_PI;
    if (!(s->sun_weight > 0.0)) return cos_part;
    return (1.0 - s->sun_weight) * cos_part + s->sun_weight * sun_part_pdf(s, w);
}

cdl_vec3 cdl_sky_distribution_sample(const cdl_sky_distribution *s, cdl_vec3 n, double u1, double u2, double *pdf)
{
    cdl_vec3 w;
    if (s->sun_weight > 0.0 && u1 < s->sun_weight) {
        /* the sun's part, u1 rescaled to [0, 1) */
        double v = u1 / s->sun_weight, lambda = sun_lambda(s);
        double chi = -log(1.0 - v * (1.0 - exp(-lambda * CDL_PI))) / lambda, psi = CDL_TWO_PI * u2;
        w = cdl_frame_to_world(&s->sun_frame,
                               cdl_vec3_make(sin(chi) * cos(psi), sin(chi) * sin(psi), cos(chi)));
    } else {
        double v = s->sun_weight > 0.0 ? (u1 - s->sun_weight) / (1.0 - s->sun_weight) : u1;
        cdl_frame f = cdl_frame_from_normal(n);
        w = cdl_frame_to_world(&f, cdl_sample_cosine_hemisphere(fmin(v, 0x1.fffffffffffffp-1), u2));
    }
    *pdf = cdl_sky_distribution_pdf(s, n, w);
    return w;
}

/* ---- set up -------------------------------------------------------------------- */

/* phi(0) f(Z_s): the formula at the zenith */
static double zenith_shape(const cdl_sky_distribution *s)
{
    double z_s = acos(fmax(-1.0, fmin(1.0, cdl_vec3_dot(s->sun, s->frame.n))));
    return gradation(s, 1.0) * indicatrix(s, z_s);
}

double cdl_sky_distribution_zenith(const cdl_sky_distribution *s)
{
    return s->scale * fmax(0.0, zenith_shape(s));
}

cdl_status cdl_sky_distribution_scale_to(cdl_sky_distribution *s, double zenith_cd_m2, double horizontal_lx,
                                         cdl_error *err)
{
    if (horizontal_lx >= 0.0) {
        s->scale = 1.0;
        double I = cdl_sky_distribution_illuminance(s, s->frame.n);
        s->scale = horizontal_lx / I; /* I > 0: cdl_sky_distribution_init checked */
        return CDL_OK;
    }
    double z = zenith_shape(s);
    if (!(z > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected a sky brighter than 0 at its zenith to scale by its zenith luminance, found "
                             "phi(0) f(Z_s) = %.6g",
                             z);
    s->scale = zenith_cd_m2 / z;
    return CDL_OK;
}

cdl_status cdl_sky_distribution_init(cdl_sky_distribution *s, cdl_vec3 up, cdl_vec3 azimuth_ref, cdl_vec3 sun,
                                     const double coefficients[5], double k, int clamp, cdl_error *err)
{
    memset(s, 0, sizeof *s);
    s->frame.n = up;
    s->frame.s = azimuth_ref;
    s->frame.t = cdl_vec3_cross(up, azimuth_ref);
    s->sun = sun;
    s->sun_frame = cdl_frame_from_normal(sun);
    s->a = coefficients[0];
    s->b = coefficients[1];
    s->c = coefficients[2];
    s->d = coefficients[3];
    s->e = coefficients[4];
    s->k = k;
    s->clamp = clamp;
    s->scale = 1.0;
    gauss_legendre(s->gl_x, s->gl_w, CDL_SKY_QUADRATURE_POINTS);
    int constant_indicatrix = s->c == 0.0 && s->e == 0.0;
    if (!constant_indicatrix && !(cdl_vec3_dot(sun, up) > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "sun: expected the sun above the horizon (this sky brightens towards it), found it %.4g "
                             "degrees below",
                             asin(fmax(-1.0, fmin(1.0, -cdl_vec3_dot(sun, up)))) * CDL_RAD_TO_DEG);
    if (!(s->b < 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected a gradation coefficient b < 0, found b = %.6g: the luminance would grow "
                             "without bound towards the horizon",
                             s->b);
    /* samples about the sun where the indicatrix peaks there */
    s->sun_weight = s->c > 0.0 ? 0.5 : 0.0;
    if (!(cdl_sky_distribution_illuminance(s, up) > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected a sky that gives light, found a luminance of 0 or below everywhere "
                             "(a = %.4g, b = %.4g, c = %.4g, d = %.4g, e = %.4g)",
                             s->a, s->b, s->c, s->d, s->e);
    return CDL_OK;
}
