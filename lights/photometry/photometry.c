/* photometry.c - the photometric model: construction, validation, accessors,
 * metadata, warnings, tilt and output factors. Interpolation lives in
 * photometry_intensity.c, integration in photometry_flux.c. */
#include "base/error_report.h"
#include "lights/photometry/photometry_internal.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Largest table accepted: far above any real file (the 1.3 MB corpus file
 * has 263 x 361 values) and small enough that a hostile header cannot make
 * us allocate gigabytes. */
#define MAX_TABLE_VALUES 20000000u
#define MAX_ANGLES 1000000u

const char *cdl_photometry_symmetry_name(cdl_photometry_symmetry s)
{
    switch (s) {
    case CDL_PHOTOMETRY_SYMMETRY_NONE: return "none";
    case CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL: return "rotational";
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180: return "bilateral-c0-c180";
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270: return "bilateral-c90-c270";
    case CDL_PHOTOMETRY_SYMMETRY_QUADRANT: return "quadrant";
    case CDL_PHOTOMETRY_SYMMETRY_LATERAL: return "lateral";
    case CDL_PHOTOMETRY_SYMMETRY_VERTICAL: return "vertical";
    case CDL_PHOTOMETRY_SYMMETRY_LATERAL_VERTICAL: return "lateral-vertical";
    }
    return "unknown";
}

const char *cdl_luminous_shape_name(cdl_luminous_shape shape)
{
    switch (shape) {
    case CDL_LUMINOUS_SHAPE_POINT: return "point";
    case CDL_LUMINOUS_SHAPE_RECTANGLE: return "rectangle";
    case CDL_LUMINOUS_SHAPE_BOX: return "rectangle with luminous sides";
    case CDL_LUMINOUS_SHAPE_CIRCLE: return "circle";
    case CDL_LUMINOUS_SHAPE_ELLIPSE: return "ellipse";
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER: return "vertical cylinder";
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER: return "vertical elliptic cylinder";
    case CDL_LUMINOUS_SHAPE_SPHERE: return "sphere";
    case CDL_LUMINOUS_SHAPE_ELLIPSOID: return "ellipsoid";
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG: return "horizontal cylinder along C0-C180";
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS: return "horizontal cylinder along C90-C270";
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE: return "vertical circle";
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE: return "vertical ellipse";
    case CDL_LUMINOUS_SHAPE_UNKNOWN: return "unknown";
    }
    return "unknown";
}

cdl_photometry *cdl_photometry_alloc(void)
{
    cdl_photometry *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->type = CDL_PHOTOMETRIC_TYPE_C;
    p->meta.format = CDL_PHOTOMETRY_FORMAT_TABLE;
    p->meta.absolute = 1;
    p->meta.candela_multiplier = 1.0;
    p->meta.ballast_factor = 1.0;
    p->meta.ballast_lamp_factor = 1.0;
    return p;
}

void cdl_photometry_release(cdl_photometry *p)
{
    if (!p) return;
    free(p->h);
    free(p->v);
    free(p->cd);
    free(p->tilt_angles);
    free(p->tilt_factors);
    for (size_t i = 0; i < p->meta.keyword_count; ++i) {
        free(p->meta.keywords[i].key);
        free(p->meta.keywords[i].value);
    }
    free(p->meta.keywords);
    for (size_t i = 0; i < p->warning_count; ++i) free(p->warnings[i].message);
    free(p->warnings);
    free(p);
}

/* ---- validation helpers ---------------------------------------------------- */

static cdl_status check_ascending(const double *x, size_t n, double lo, double hi, const char *what, cdl_error *err)
{
    for (size_t i = 0; i < n; ++i) {
        if (!isfinite(x[i]))
            return cdl_error_set(err, CDL_ERR_INPUT, "%s %zu: expected a finite angle, found %g", what, i + 1, x[i]);
        if (x[i] < lo || x[i] > hi)
            return cdl_error_set(err, CDL_ERR_INPUT, "%s %zu: expected an angle within [%g, %g] degrees, found %g",
                                 what, i + 1, lo, hi, x[i]);
        if (i > 0 && !(x[i] > x[i - 1]))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s %zu: expected angles in increasing order, found %g after %g", what, i + 1,
                                 x[i], x[i - 1]);
    }
    return CDL_OK;
}

/* Equal steps (to 1e-9 of the span): lookups become one division. */
static int is_uniform(const double *x, size_t n, double *inv_step)
{
    *inv_step = 0.0;
    if (n < 2) return 0;
    double step = (x[n - 1] - x[0]) / (double)(n - 1);
    double tol = 1e-9 * fmax(1.0, fabs(x[n - 1] - x[0]));
    for (size_t i = 0; i < n; ++i)
        if (fabs(x[i] - (x[0] + step * (double)i)) > tol) return 0;
    *inv_step = 1.0 / step;
    return 1;
}

static cdl_photometry_symmetry infer_type_c_symmetry(const double *c, size_t n)
{
    if (n == 1) return CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
    if (c[0] == 0.0 && c[n - 1] == 90.0) return CDL_PHOTOMETRY_SYMMETRY_QUADRANT;
    if (c[0] == 0.0 && c[n - 1] == 180.0) return CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180;
    if (c[0] == 90.0 && c[n - 1] == 270.0) return CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270;
    return CDL_PHOTOMETRY_SYMMETRY_NONE;
}

static cdl_status check_type_c_symmetry(cdl_photometry_symmetry s, const double *c, size_t n, cdl_error *err)
{
    double lo = 0.0, hi = 0.0;
    switch (s) {
    case CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL:
        if (n != 1)
            return cdl_error_set(err, CDL_ERR_INPUT, "expected exactly one C-plane for rotational symmetry, found %zu", n);
        return CDL_OK;
    case CDL_PHOTOMETRY_SYMMETRY_QUADRANT: lo = 0.0; hi = 90.0; break;
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C0_C180: lo = 0.0; hi = 180.0; break;
    case CDL_PHOTOMETRY_SYMMETRY_BILATERAL_C90_C270: lo = 90.0; hi = 270.0; break;
    case CDL_PHOTOMETRY_SYMMETRY_NONE:
        if (n >= 2 && c[n - 1] - c[0] >= 360.0)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "expected each C-plane once in a full-circle table, found C = %g and C = %g (the "
                                 "same plane)",
                                 c[0], c[n - 1]);
        return CDL_OK;
    default:
        return cdl_error_set(err, CDL_ERR_INPUT, "expected a type C symmetry, found '%s' (a type A/B symmetry)",
                             cdl_photometry_symmetry_name(s));
    }
    if (n < 2 || c[0] != lo || c[n - 1] != hi)
        return cdl_error_set(err, CDL_ERR_INPUT, "expected C-planes from %g to %g for %s symmetry, found %g to %g",
                             lo, hi, cdl_photometry_symmetry_name(s), c[0], c[n - 1]);
    return CDL_OK;
}

cdl_status cdl_photometry_set_table(cdl_photometry *p, cdl_photometric_type type, cdl_photometry_symmetry symmetry,
                                    const double *h, size_t nh, const double *v, size_t nv, const double *cd,
                                    cdl_error *err)
{
    if (type != CDL_PHOTOMETRIC_TYPE_A && type != CDL_PHOTOMETRIC_TYPE_B && type != CDL_PHOTOMETRIC_TYPE_C)
        return cdl_error_set(err, CDL_ERR_INPUT, "expected photometric type 1 (C), 2 (B) or 3 (A), found %d",
                             (int)type);
    if (!h || !v || !cd || nh == 0 || nv == 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "expected at least one horizontal and one vertical angle");
    if (nv < 2)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected at least 2 vertical angles (one angle encloses no solid angle), found %zu", nv);
    if (nh > MAX_ANGLES || nv > MAX_ANGLES || nh * nv > MAX_TABLE_VALUES)
        return cdl_error_set(err, CDL_ERR_INPUT, "table of %zu x %zu values is larger than the %u supported", nh, nv,
                             MAX_TABLE_VALUES);
    cdl_status st;
    if (type == CDL_PHOTOMETRIC_TYPE_C) {
        if ((st = check_ascending(h, nh, 0.0, 360.0, "C-plane", err)) != CDL_OK) return st;
        if ((st = check_ascending(v, nv, 0.0, 180.0, "gamma angle", err)) != CDL_OK) return st;
        if (symmetry == CDL_PHOTOMETRY_SYMMETRY_INFER) symmetry = infer_type_c_symmetry(h, nh);
        if (symmetry == CDL_PHOTOMETRY_SYMMETRY_NONE && nh >= 2 && h[0] == 0.0 && h[nh - 1] == 360.0) {
            /* C = 360 is the C = 0 plane again: keep the 0 row (FORMAT_NOTES 1.6). */
            const double *r0 = cd, *r1 = cd + (nh - 1) * nv;
            for (size_t j = 0; j < nv; ++j)
                if (r0[j] != r1[j]) {
                    if (cdl_photometry_add_warning(p, "seam-differs", 0, "the C = 0 and C = 360 planes differ (%g and %g cd at gamma "
                                                      "%g); the C = 0 plane is used",
                                                   r0[j], r1[j], v[j]) != CDL_OK)
                        return cdl_error_out_of_memory(err);
                    break;
                }
            --nh;
            if (nh == 1) symmetry = CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
        }
        if ((st = check_type_c_symmetry(symmetry, h, nh, err)) != CDL_OK) return st;
    } else {
        /* B: H is a latitude (|H| <= 90), V a longitude; A the other way round. */
        double hmax = type == CDL_PHOTOMETRIC_TYPE_B ? 90.0 : 180.0;
        double vmax = type == CDL_PHOTOMETRIC_TYPE_B ? 180.0 : 90.0;
        if ((st = check_ascending(h, nh, -hmax, hmax, "horizontal angle", err)) != CDL_OK) return st;
        if ((st = check_ascending(v, nv, -vmax, vmax, "vertical angle", err)) != CDL_OK) return st;
        if (nh < 2)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "expected at least 2 horizontal angles for type %c data, found %zu",
                                 type == CDL_PHOTOMETRIC_TYPE_B ? 'B' : 'A', nh);
        int hm = h[0] == 0.0 && h[nh - 1] == 90.0;
        int vm = v[0] == 0.0 && v[nv - 1] == 90.0;
        cdl_photometry_symmetry inferred = hm && vm ? CDL_PHOTOMETRY_SYMMETRY_LATERAL_VERTICAL
                                           : hm     ? CDL_PHOTOMETRY_SYMMETRY_LATERAL
                                           : vm     ? CDL_PHOTOMETRY_SYMMETRY_VERTICAL
                                                    : CDL_PHOTOMETRY_SYMMETRY_NONE;
        if (symmetry != CDL_PHOTOMETRY_SYMMETRY_INFER && symmetry != inferred)
            return cdl_error_set(err, CDL_ERR_INPUT, "expected symmetry '%s' (what the angle ranges mean), found '%s'",
                                 cdl_photometry_symmetry_name(inferred), cdl_photometry_symmetry_name(symmetry));
        symmetry = inferred;
        p->h_mirror = hm;
        p->v_mirror = vm;
    }
    size_t count = nh * nv;
    double max_cd = -1.0;
    size_t max_k = 0;
    for (size_t k = 0; k < count; ++k) {
        if (!isfinite(cd[k]))
            return cdl_error_set(err, CDL_ERR_INPUT, "candela value %zu (plane %zu, angle %zu): expected a finite number, found %g",
                                 k + 1, k / nv + 1, k % nv + 1, cd[k]);
        if (cd[k] < 0.0)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "candela value %zu (plane %zu, angle %zu): expected a value >= 0, found %g", k + 1,
                                 k / nv + 1, k % nv + 1, cd[k]);
        if (cd[k] > max_cd) {
            max_cd = cd[k];
            max_k = k;
        }
    }
    double *nh_copy = malloc(nh * sizeof *nh_copy);
    double *nv_copy = malloc(nv * sizeof *nv_copy);
    double *cd_copy = malloc(count * sizeof *cd_copy);
    if (!nh_copy || !nv_copy || !cd_copy) {
        free(nh_copy);
        free(nv_copy);
        free(cd_copy);
        return cdl_error_out_of_memory(err);
    }
    memcpy(nh_copy, h, nh * sizeof *h);
    memcpy(nv_copy, v, nv * sizeof *v);
    memcpy(cd_copy, cd, count * sizeof *cd);
    free(p->h);
    free(p->v);
    free(p->cd);
    p->h = nh_copy;
    p->v = nv_copy;
    p->cd = cd_copy;
    p->type = type;
    p->symmetry = symmetry;
    p->nh = nh;
    p->nv = nv;
    p->h_uniform = is_uniform(p->h, nh, &p->h_inv_step);
    p->v_uniform = is_uniform(p->v, nv, &p->v_inv_step);
    p->max_cd = max_cd;
    p->max_i = max_k / nv;
    p->max_j = max_k % nv;
    p->flux_lm = cdl_photometry_compute_flux(p);
    if (!isfinite(p->flux_lm))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected candela values whose flux is a finite number, found values up to %g cd", max_cd);
    if (p->meta.format == CDL_PHOTOMETRY_FORMAT_TABLE) {
        p->meta.file_horizontal_count = nh;
        p->meta.file_vertical_count = nv;
    }
    return CDL_OK;
}

cdl_status cdl_photometry_create(cdl_photometric_type type, const double *h_deg, size_t nh, const double *v_deg,
                                 size_t nv, const double *candela, cdl_photometry **out, cdl_error *err)
{
    *out = NULL;
    cdl_photometry *p = cdl_photometry_alloc();
    if (!p) return cdl_error_out_of_memory(err);
    cdl_status st = cdl_photometry_set_table(p, type, CDL_PHOTOMETRY_SYMMETRY_INFER, h_deg, nh, v_deg, nv, candela, err);
    if (st != CDL_OK) {
        cdl_photometry_release(p);
        return st;
    }
    *out = p;
    return CDL_OK;
}

cdl_status cdl_photometry_create_type_c(const double *c_deg, size_t nc, const double *gamma_deg, size_t ng,
                                        const double *candela, cdl_photometry **out, cdl_error *err)
{
    return cdl_photometry_create(CDL_PHOTOMETRIC_TYPE_C, c_deg, nc, gamma_deg, ng, candela, out, err);
}

cdl_status cdl_photometry_set_tilt(cdl_photometry *p, int geometry, const double *angles, const double *factors,
                                   size_t count, cdl_error *err)
{
    double *a = malloc((count ? count : 1) * sizeof *a);
    double *f = malloc((count ? count : 1) * sizeof *f);
    if (!a || !f) {
        free(a);
        free(f);
        return cdl_error_out_of_memory(err);
    }
    if (count) {
        memcpy(a, angles, count * sizeof *a);
        memcpy(f, factors, count * sizeof *f);
    }
    free(p->tilt_angles);
    free(p->tilt_factors);
    p->tilt_angles = a;
    p->tilt_factors = f;
    p->meta.tilt_geometry = geometry;
    p->meta.tilt_count = count;
    p->meta.tilt_angles_deg = a;
    p->meta.tilt_factors = f;
    return CDL_OK;
}

/* ---- accessors --------------------------------------------------------------- */

cdl_luminous_flux cdl_photometry_flux(const cdl_photometry *p)
{
    /* A radiant intensity table integrates to watts, never lumens (photometry_units.c). */
    return cdl_lumens(p->meta.radiometric ? NAN : p->flux_lm);
}

cdl_status cdl_photometry_luminous_flux(const cdl_photometry *p, cdl_luminous_flux *flux, cdl_error *err)
{
    if (p->meta.radiometric)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected photometric data (candela), found radiant intensity in %s ([%s]): a "
                             "radiometric file has no lumens without a spectrum",
                             cdl_photometry_intensity_unit(p), p->meta.units_keyword);
    *flux = cdl_lumens(p->flux_lm);
    return CDL_OK;
}

cdl_status cdl_photometry_radiant_flux(const cdl_photometry *p, cdl_radiant_flux *flux, cdl_error *err)
{
    if (!p->meta.radiometric)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "expected radiometric data (W/sr), found a table in candela: its radiant flux needs "
                             "the light's spectrum");
    /* the table's integral is in its own unit times sr: W/sr x scale x sr = W */
    *flux = cdl_watts(p->flux_lm * p->meta.radiometric_scale);
    return CDL_OK;
}

cdl_luminous_intensity cdl_photometry_max_intensity(const cdl_photometry *p) { return cdl_candelas(p->max_cd); }

double cdl_photometry_output_factor(const cdl_photometry *p)
{
    double f = p->meta.ballast_factor;
    if (p->meta.format == CDL_PHOTOMETRY_FORMAT_IES && p->meta.ies_version <= 1995) f *= p->meta.ballast_lamp_factor;
    return f;
}

double cdl_photometry_tilt_factor(const cdl_photometry *p, double tilt_deg)
{
    size_t n = p->meta.tilt_count;
    if (n == 0 || !isfinite(tilt_deg)) return 1.0;
    const double *a = p->tilt_angles, *f = p->tilt_factors;
    if (tilt_deg <= a[0]) return f[0];
    if (tilt_deg >= a[n - 1]) return f[n - 1];
    size_t lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (a[mid] <= tilt_deg) lo = mid;
        else hi = mid;
    }
    /* Linear interpolation between the two bracketing tilt angles (LM-63 section "TILT"). */
    double t = (tilt_deg - a[lo]) / (a[hi] - a[lo]);
    return f[lo] + t * (f[hi] - f[lo]);
}

void cdl_photometry_get_table(const cdl_photometry *p, cdl_photometry_table *t)
{
    t->type = p->type;
    t->symmetry = p->symmetry;
    t->horizontal_count = p->nh;
    t->vertical_count = p->nv;
    t->horizontal_deg = p->h;
    t->vertical_deg = p->v;
    t->candela = p->cd;
}

const cdl_photometry_metadata *cdl_photometry_get_metadata(const cdl_photometry *p) { return &p->meta; }

size_t cdl_photometry_warning_count(const cdl_photometry *p) { return p->warning_count; }

const char *cdl_photometry_warning(const cdl_photometry *p, size_t i)
{
    return i < p->warning_count ? p->warnings[i].message : NULL;
}

const char *cdl_photometry_warning_code(const cdl_photometry *p, size_t i)
{
    return i < p->warning_count ? p->warnings[i].code : NULL;
}

unsigned cdl_photometry_warning_line(const cdl_photometry *p, size_t i)
{
    return i < p->warning_count ? p->warnings[i].line : 0;
}

/* ---- warnings and keywords --------------------------------------------------- */

cdl_status cdl_photometry_add_warning(cdl_photometry *p, const char *code, unsigned line, const char *fmt, ...)
{
    char buf[CDL_ERROR_MESSAGE_SIZE];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    if (p->warning_count == p->warning_capacity) {
        size_t cap = p->warning_capacity ? 2 * p->warning_capacity : 8;
        cdl_photometry_warning_item *w = realloc(p->warnings, cap * sizeof *w);
        if (!w) return CDL_ERR_INTERNAL;
        p->warnings = w;
        p->warning_capacity = cap;
    }
    size_t len = strlen(buf);
    char *copy = malloc(len + 1);
    if (!copy) return CDL_ERR_INTERNAL;
    memcpy(copy, buf, len + 1);
    p->warnings[p->warning_count++] = (cdl_photometry_warning_item){code, line, copy};
    return CDL_OK;
}

static char *dup_span(const char *s, size_t n)
{
    char *c = malloc(n + 1);
    if (!c) return NULL;
    if (n) memcpy(c, s, n);
    c[n] = '\0';
    return c;
}

cdl_status cdl_photometry_add_keyword(cdl_photometry *p, const char *key, size_t key_len, const char *value,
                                      size_t value_len)
{
    size_t n = p->meta.keyword_count;
    if ((n & (n - 1)) == 0) { /* grow at powers of two */
        size_t cap = n ? 2 * n : 8;
        cdl_photometry_keyword *k = realloc(p->meta.keywords, cap * sizeof *k);
        if (!k) return CDL_ERR_INTERNAL;
        p->meta.keywords = k;
    }
    char *kc = dup_span(key, key_len), *vc = dup_span(value, value_len);
    if (!kc || !vc) {
        free(kc);
        free(vc);
        return CDL_ERR_INTERNAL;
    }
    p->meta.keywords[n].key = kc;
    p->meta.keywords[n].value = vc;
    p->meta.keywords[n].line = 0;
    p->meta.keyword_count = n + 1;
    return CDL_OK;
}

cdl_status cdl_photometry_append_keyword(cdl_photometry *p, const char *value, size_t value_len)
{
    if (p->meta.keyword_count == 0) return cdl_photometry_add_keyword(p, "MORE", 4, value, value_len);
    cdl_photometry_keyword *k = &p->meta.keywords[p->meta.keyword_count - 1];
    size_t old = strlen(k->value);
    char *v = realloc(k->value, old + 1 + value_len + 1);
    if (!v) return CDL_ERR_INTERNAL;
    v[old] = '\n';
    if (value_len) memcpy(v + old + 1, value, value_len);
    v[old + 1 + value_len] = '\0';
    k->value = v;
    return CDL_OK;
}

const char *cdl_photometry_keyword_value(const cdl_photometry *p, const char *key)
{
    for (size_t i = 0; i < p->meta.keyword_count; ++i)
        if (cdl_photometry_strcaseeq(p->meta.keywords[i].key, key)) return p->meta.keywords[i].value;
    return NULL;
}

cdl_status cdl_photometry_copy_metadata(cdl_photometry *dst, const cdl_photometry *src)
{
    cdl_photometry_keyword *keep_keywords = dst->meta.keywords;
    dst->meta = src->meta;
    dst->meta.keywords = keep_keywords;
    dst->meta.keyword_count = 0;
    dst->meta.tilt_angles_deg = NULL;
    dst->meta.tilt_factors = NULL;
    dst->meta.tilt_count = 0;
    for (size_t i = 0; i < src->meta.keyword_count; ++i) {
        const cdl_photometry_keyword *k = &src->meta.keywords[i];
        if (cdl_photometry_add_keyword(dst, k->key, strlen(k->key), k->value, strlen(k->value)) != CDL_OK)
            return CDL_ERR_INTERNAL;
        dst->meta.keywords[i].line = k->line;
    }
    if (src->meta.tilt_count &&
        cdl_photometry_set_tilt(dst, src->meta.tilt_geometry, src->tilt_angles, src->tilt_factors,
                                src->meta.tilt_count, NULL) != CDL_OK)
        return CDL_ERR_INTERNAL;
    for (size_t i = 0; i < src->warning_count; ++i)
        if (cdl_photometry_add_warning(dst, src->warnings[i].code, src->warnings[i].line, "%s",
                                       src->warnings[i].message) != CDL_OK)
            return CDL_ERR_INTERNAL;
    return CDL_OK;
}

/* ---- small text helpers -------------------------------------------------------- */

void cdl_photometry_copy_text(char *dst, size_t dst_size, const char *src, size_t len)
{
    if (dst_size == 0) return;
    while (len > 0 && (unsigned char)*src <= ' ' && *src != '\0') {
        ++src;
        --len;
    }
    while (len > 0 && (unsigned char)src[len - 1] <= ' ') --len;
    size_t n = len < dst_size - 1 ? len : dst_size - 1;
    for (size_t i = 0; i < n; ++i) dst[i] = src[i] == '\0' ? ' ' : src[i];
    dst[n] = '\0';
}

int cdl_photometry_strcaseeq(const char *a, const char *b)
{
    for (; *a && *b; ++a, ++b)
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) return 0;
    return *a == *b;
}
