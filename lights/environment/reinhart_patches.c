/* reinhart_patches.c - Tregenza and Reinhart sky patches (see the header). */
#include "lights/environment/reinhart_patches.h"

#include <math.h>

#include "base/error_report.h"
#include "lights/environment/environment_pixels.h"
#include "radiometry/constants.h"

/* Tregenza's patches per row of 12 degrees, from the horizon (Tregenza
 * 1987, Table 1), the cap apart. */
static const int tregenza_row[7] = {30, 30, 24, 24, 18, 12, 6};

cdl_status cdl_reinhart_init(cdl_reinhart_patches *p, int mf, cdl_vec3 up, cdl_vec3 north, cdl_error *err)
{
    if (mf < 1 || mf > CDL_REINHART_MAX_MF)
        return cdl_error_set(err, CDL_ERR_INPUT, "expected a Reinhart subdivision (MF) in [1, %d], found %d",
                             CDL_REINHART_MAX_MF, mf);
    cdl_vec3 n = cdl_vec3_normalize(up);
    cdl_vec3 s = cdl_vec3_sub(north, cdl_vec3_scale(n, cdl_vec3_dot(north, n)));
    double len = cdl_vec3_length(s);
    if (!(len > 1e-9 * cdl_vec3_length(north)))
        return cdl_error_set(err, CDL_ERR_INPUT, "expected a direction of north not along up");
    p->mf = mf;
    p->frame.n = n;
    p->frame.s = cdl_vec3_scale(s, 1.0 / len);
    p->frame.t = cdl_vec3_cross(p->frame.n, p->frame.s);
    p->rows = 7 * mf + 1;
    p->alpha = (CDL_PI / 2.0) / (7.0 * mf + 0.5);
    p->row_first[0] = 1;
    for (int r = 0; r < p->rows; ++r) {
        p->row_count[r] = r == p->rows - 1 ? 1 : mf * tregenza_row[(int)floor((r + 0.5) / mf)];
        p->row_first[r + 1] = p->row_first[r] + p->row_count[r];
    }
    p->count = p->row_first[p->rows];
    return CDL_OK;
}

int cdl_reinhart_patch_at(const cdl_reinhart_patches *p, double altitude, double azimuth)
{
    if (altitude < 0.0) return CDL_REINHART_GROUND;
    int r = (int)floor(altitude / p->alpha);
    if (r >= p->rows - 1) return p->count - 1; /* the cap */
    int n = p->row_count[r];
    /* patch k spans [(k - 1/2) w, (k + 1/2) w) */
    double w = CDL_TWO_PI / n;
    int k = (int)floor(azimuth / w + 0.5);
    k %= n;
    if (k < 0) k += n;
    return p->row_first[r] + k;
}

int cdl_reinhart_patch_of(const cdl_reinhart_patches *p, cdl_vec3 w)
{
    cdl_vec3 l = cdl_frame_to_local(&p->frame, w);
    if (l.z < 0.0) return CDL_REINHART_GROUND;
    double altitude = atan2(l.z, sqrt(l.x * l.x + l.y * l.y));
    /* local x north, y west: eastward azimuth is clockwise from above */
    double azimuth = atan2(-l.y, l.x);
    return cdl_reinhart_patch_at(p, altitude, azimuth);
}

void cdl_reinhart_patch_bounds(const cdl_reinhart_patches *p, int k, double *alt_lo, double *alt_hi, double *az_lo,
                               double *az_hi)
{
    int r = 0;
    while (r + 1 < p->rows && k >= p->row_first[r + 1]) ++r;
    *alt_lo = r * p->alpha;
    *alt_hi = r == p->rows - 1 ? CDL_PI / 2.0 : (r + 1) * p->alpha;
    double w = CDL_TWO_PI / p->row_count[r];
    int j = k - p->row_first[r];
    *az_lo = (j - 0.5) * w;
    *az_hi = (j + 0.5) * w;
}

double cdl_reinhart_solid_angle(const cdl_reinhart_patches *p, int k)
{
    if (k == CDL_REINHART_GROUND) return CDL_TWO_PI;
    double a0, a1, z0, z1;
    cdl_reinhart_patch_bounds(p, k, &a0, &a1, &z0, &z1);
    return (sin(a1) - sin(a0)) * (z1 - z0);
}

cdl_vec3 cdl_reinhart_direction(const cdl_reinhart_patches *p, double altitude, double azimuth)
{
    double ca = cos(altitude);
    return cdl_frame_to_world(&p->frame, cdl_vec3_make(ca * cos(azimuth), -ca * sin(azimuth), sin(altitude)));
}

double cdl_reinhart_projected_solid_angle(const cdl_reinhart_patches *p, int k, cdl_vec3 n)
{
    cdl_vec3 nl = cdl_frame_to_local(&p->frame, n);
    if (k == CDL_REINHART_GROUND) return cdl_env_cell_projected_solid_angle(CDL_PI / 2.0, CDL_PI, 0.0, CDL_TWO_PI, nl);
    double a0, a1, z0, z1;
    cdl_reinhart_patch_bounds(p, k, &a0, &a1, &z0, &z1);
    /* polar angle from up; local azimuth phi = -azimuth */
    return cdl_env_cell_projected_solid_angle(CDL_PI / 2.0 - a1, CDL_PI / 2.0 - a0, -z1, -z0, nl);
}
