/* sky_region.c - the visible sky's pieces as fan triangles to sample (see
 * the header). */
#include "solver/direct/sky_region.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "lights/environment/environment_peaks.h"
#include "lights/emitters/projected_solid_angle.h"

typedef struct region_triangle {
    cdl_vec3 a, ab, ac;   /* corner and edges, world */
    double height;        /* its face's distance from the apex */
    double psa;           /* Omega_p of the triangle about n */
    double area;          /* m^2 in the face's plane (the unit cube: a number) */
    double cdf;           /* sum of psa up to and including this one */
} region_triangle;

struct cdl_sky_region {
    cdl_vec3 p, n;
    region_triangle *tri;
    size_t count;
    double psa;
    double L_lo, L_hi, L_ref;
    const cdl_emitter *sky;
    double cut;            /* pixels brighter than this are summed exactly */
    cdl_env_peaks bright;  /* their sums over R */
    int too_bright;
};

void cdl_sky_region_release(cdl_sky_region *r)
{
    if (!r) return;
    free(r->tri);
    free(r);
}

/* The world point of a face's 2-D coordinates. */
static cdl_vec3 face_point(const cdl_visible_face *f, const double *xy)
{
    cdl_vec3 foot = cdl_vec3_madd(f->apex, -f->height, f->toward);
    return cdl_vec3_madd(cdl_vec3_madd(foot, xy[0], f->e1), xy[1], f->e2);
}

cdl_status cdl_sky_region_create(const cdl_visible_face *faces, int face_count, cdl_vec3 p, cdl_vec3 n,
                                 const cdl_emitter *sky, double L_cut, int max_bright, cdl_sky_region **out,
                                 cdl_error *err)
{
    *out = NULL;
    size_t cap = 0;
    for (int f = 0; f < face_count; ++f)
        for (size_t k = 0; k < faces[f].count; ++k)
            if (faces[f].pieces[k].count >= 3) cap += (size_t)faces[f].pieces[k].count - 2;
    cdl_sky_region *r = calloc(1, sizeof *r);
    if (!r || !(r->tri = malloc((cap ? cap : 1) * sizeof *r->tri))) {
        cdl_sky_region_release(r);
        return cdl_error_out_of_memory(err);
    }
    r->p = p;
    r->n = n;
    r->sky = sky;
    r->cut = L_cut;
    r->L_lo = INFINITY;
    r->L_hi = 0.0;
    size_t largest = 0;
    for (int f = 0; f < face_count; ++f) {
        const cdl_visible_face *face = &faces[f];
        for (size_t k = 0; k < face->count; ++k) {
            const cdl_visible_piece *piece = &face->pieces[k];
            if (piece->count < 3) continue;
            cdl_vec3 dirs[CDL_VISIBLE_MAX_VERTICES];
            for (int v = 0; v < piece->count; ++v)
                dirs[v] = cdl_vec3_normalize(cdl_vec3_sub(face_point(face, piece->v[v]), p));
            double piece_psa = 0.0;
            cdl_vec3 a = face_point(face, piece->v[0]);
            for (int v = 1; v + 1 < piece->count; ++v) {
                region_triangle t;
                cdl_vec3 b = face_point(face, piece->v[v]), c = face_point(face, piece->v[v + 1]);
                cdl_vec3 rel[3] = {cdl_vec3_sub(a, p), cdl_vec3_sub(b, p), cdl_vec3_sub(c, p)};
                t.a = a;
                t.ab = cdl_vec3_sub(b, a);
                t.ac = cdl_vec3_sub(c, a);
                t.height = face->height;
                t.psa = fabs(cdl_projected_solid_angle_polygon(rel, 3, n));
                /* area from the 2-D coordinates (pieces are counter-clockwise) */
                const double *u = piece->v[0], *q = piece->v[v], *s = piece->v[v + 1];
                t.area = 0.5 * fabs((q[0] - u[0]) * (s[1] - u[1]) - (s[0] - u[0]) * (q[1] - u[1]));
                if (!(t.psa > 0.0) || !(t.area > 0.0)) continue;
                r->psa += t.psa;
                t.cdf = r->psa;
                piece_psa += t.psa;
                if (r->count == 0 || t.psa > r->tri[largest].psa) largest = r->count;
                r->tri[r->count++] = t;
            }
            if (!(piece_psa > 0.0)) continue;
            cdl_luminance lo, hi;
            if (cdl_emitter_luminance_bounds(sky, dirs, piece->count, &lo, &hi)) {
                /* L' is at most the cut (brighter pixels stand at L_ref,
                 * which lies within these bounds) */
                /* (no pixel above the cut where the bound is below it) */
                double rest_hi = L_cut;
                if (hi.cd_m2 > L_cut && !r->too_bright &&
                    !cdl_env_peaks_add(sky, dirs, piece->count, n, L_cut, max_bright, &r->bright, &rest_hi))
                    r->too_bright = 1;
                r->L_lo = fmin(r->L_lo, fmin(lo.cd_m2, L_cut));
                r->L_hi = fmax(r->L_hi, fmin(hi.cd_m2, rest_hi));
            } else {
                r->L_lo = 0.0;
                r->L_hi = INFINITY;
            }
        }
    }
    if (r->count == 0) {
        r->L_lo = r->L_hi = r->L_ref = 0.0;
    } else {
        const region_triangle *t = &r->tri[largest];
        cdl_vec3 mid = cdl_vec3_add(t->a, cdl_vec3_scale(cdl_vec3_add(t->ab, t->ac), 1.0 / 3.0));
        r->L_ref = r->L_hi; /* what a middle in a bright pixel stands for */
        r->L_ref = cdl_sky_region_luminance(r, cdl_vec3_normalize(cdl_vec3_sub(mid, p)));
        /* A reference outside the bounds (a pixel at the edge of the
         * region) is still exact as a control variate; keep it within
         * them so that a region of one luminance is exact. */
        r->L_ref = fmin(fmax(r->L_ref, r->L_lo), r->L_hi);
    }
    *out = r;
    return CDL_OK;
}

int cdl_sky_region_too_bright(const cdl_sky_region *r)
{
    return r->too_bright;
}

double cdl_sky_region_bright_solid_angle(const cdl_sky_region *r)
{
    return r->bright.Q;
}

double cdl_sky_region_exact_part(const cdl_sky_region *r)
{
    /* L_ref Omega_p(R) + sum_b (L_b - L_ref) Q_b(R) (the header) */
    return r->L_ref * r->psa + r->bright.LQ - r->L_ref * r->bright.Q;
}

double cdl_sky_region_luminance(const cdl_sky_region *r, cdl_vec3 w)
{
    double pdf;
    double L = cdl_emitter_radiance(r->sky, r->p, r->n, w, &pdf).cd_m2;
    return L > r->cut ? r->L_ref : L;
}

double cdl_sky_region_projected_solid_angle(const cdl_sky_region *r)
{
    return r->psa;
}

void cdl_sky_region_luminance_bounds(const cdl_sky_region *r, double *lo, double *hi)
{
    *lo = r->L_lo;
    *hi = r->L_hi;
}

double cdl_sky_region_reference_luminance(const cdl_sky_region *r)
{
    return r->L_ref;
}

int cdl_sky_region_sample(const cdl_sky_region *r, double u1, double u2, cdl_vec3 *w, double *weight)
{
    *weight = 0.0;
    if (r->count == 0) return 0;
    /* the triangle: the first whose cdf exceeds u1 Omega_p(R) */
    double x = u1 * r->psa;
    size_t lo = 0, hi = r->count - 1;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (r->tri[mid].cdf > x) hi = mid;
        else lo = mid + 1;
    }
    const region_triangle *t = &r->tri[lo];
    double before = t->cdf - t->psa;
    double v = fmin(fmax((x - before) / t->psa, 0.0), 1.0);
    /* uniform in the triangle's area: barycentrics (1 - s, s (1 - u2), s u2), s = sqrt v */
    double s = sqrt(v);
    cdl_vec3 q = cdl_vec3_madd(cdl_vec3_madd(t->a, s * (1.0 - u2), t->ab), s * u2, t->ac);
    cdl_vec3 d = cdl_vec3_sub(q, r->p);
    double dist = cdl_vec3_length(d);
    if (!(dist > 0.0)) return 0;
    *w = cdl_vec3_scale(d, 1.0 / dist);
    double c = cdl_vec3_dot(*w, r->n);
    if (!(c > 0.0)) return 0;
    /* cos / pdf, pdf = (psa_k / psa) (1 / A_k) d^3 / h */
    *weight = c * t->height * r->psa * t->area / (t->psa * dist * dist * dist);
    return 1;
}
