/* reinhart_patches.c - Tregenza and Reinhart sky patches (see the header). */
#include "lights/environment/reinhart_patches.h"

#include <math.h>

#include "base/error_report.h"
#include "lights/environment/environment_peaks.h"
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

/* ---- a polygon over the patches ------------------------------------------------ */

/* The extent of a polygon (local unit vectors): z along its arcs, and its
 * local azimuth unwrapped along its boundary. Along a great-circle arc
 * shorter than pi the horizontal part traces an ellipse about the axis, so
 * the azimuth turns one way by less than pi: the arcs' turns summed go
 * round 2 pi exactly when the polygon holds a pole. */
typedef struct poly_extent {
    double z_lo, z_hi;
    double phi_lo, phi_hi;                /* unwrapped; meaningless when it holds a pole */
    int pole;                             /* 1: holds the zenith or the nadir */
} poly_extent;

static void arc_z_range(cdl_vec3 a, cdl_vec3 b, double *lo, double *hi)
{
    cdl_vec3 cr = cdl_vec3_cross(a, b);
    double sn = cdl_vec3_length(cr), cs = cdl_vec3_dot(a, b);
    if (!(sn > 1e-15)) return;
    /* w(t) = a cos t + u sin t, t in [0, angle]: z = R cos(t - t0) */
    cdl_vec3 u = cdl_vec3_scale(cdl_vec3_madd(b, -cs, a), 1.0 / sn);
    double angle = atan2(sn, cs), R = hypot(a.z, u.z), t0 = atan2(u.z, a.z);
    if (t0 < 0.0) t0 += CDL_TWO_PI;
    if (t0 <= angle && R > *hi) *hi = R;
    double t1 = t0 >= CDL_PI ? t0 - CDL_PI : t0 + CDL_PI;
    if (t1 <= angle && -R < *lo) *lo = -R;
}

static void polygon_extent(const cdl_vec3 *l, int count, poly_extent *e)
{
    e->z_lo = e->z_hi = l[0].z;
    double phi = atan2(l[0].y, l[0].x), prev = phi;
    e->phi_lo = e->phi_hi = phi;
    for (int i = 0; i < count; ++i) {
        cdl_vec3 a = l[i], b = l[(i + 1) % count];
        if (b.z < e->z_lo) e->z_lo = b.z;
        if (b.z > e->z_hi) e->z_hi = b.z;
        arc_z_range(a, b, &e->z_lo, &e->z_hi);
        double next = atan2(b.y, b.x), d = next - prev;
        d -= CDL_TWO_PI * floor((d + CDL_PI) / CDL_TWO_PI);
        phi += d;
        prev = next;
        if (phi < e->phi_lo) e->phi_lo = phi;
        if (phi > e->phi_hi) e->phi_hi = phi;
    }
    /* back at the start: 0 or +-2 pi; a pole inside reaches z = +-1 */
    e->pole = fabs(phi - atan2(l[0].y, l[0].x)) > CDL_PI;
    if (e->pole) {
        if (e->z_hi > -e->z_lo) e->z_hi = 1.0;
        else e->z_lo = -1.0;
    }
}

/* Q of the polygon's part in a cell spanning all azimuths (the cap, the
 * ground), in four quarters (cdl_env_cell_polygon takes cells narrower
 * than pi). */
static double full_ring(double theta_a, double theta_b, const cdl_vec3 *l, int count, cdl_vec3 nl)
{
    double q = 0.0;
    for (int k = 0; k < 4; ++k)
        q += cdl_env_cell_polygon(theta_a, theta_b, k * CDL_PI / 2.0, (k + 1) * CDL_PI / 2.0, l, count, nl);
    return q;
}

/* Row r's patches the extent reaches, each added. */
static void add_row(const cdl_reinhart_patches *p, int r, const poly_extent *e, const cdl_vec3 *l, int count,
                    cdl_vec3 nl, double weight, double *out)
{
    double theta_a = CDL_PI / 2.0 - (r + 1) * p->alpha, theta_b = CDL_PI / 2.0 - r * p->alpha;
    int n = p->row_count[r];
    double w = CDL_TWO_PI / n;
    /* azimuth = -phi: the polygon spans azimuths [-phi_hi, -phi_lo] */
    int j0 = 0, j1 = n - 1;
    if (!e->pole) {
        j0 = (int)floor(-e->phi_hi / w + 0.5);
        j1 = (int)floor(-e->phi_lo / w + 0.5);
        if (j1 - j0 >= n) j1 = j0 + n - 1;
    }
    for (int j = j0; j <= j1; ++j) {
        /* patch j spans azimuths [(j - 1/2) w, (j + 1/2) w]: phi [-(j + 1/2) w, -(j - 1/2) w] */
        double q = cdl_env_cell_polygon(theta_a, theta_b, -(j + 0.5) * w, -(j - 0.5) * w, l, count, nl);
        int k = ((j % n) + n) % n;
        out[p->row_first[r] + k] += weight * q;
    }
}

int cdl_reinhart_add_polygon(const cdl_reinhart_patches *p, const cdl_vec3 *poly, int count, cdl_vec3 n,
                             double weight, double *out)
{
    if (count < 3 || count > CDL_REINHART_POLYGON_MAX) return 0;
    cdl_vec3 l[CDL_REINHART_POLYGON_MAX];
    cdl_vec3 centre = cdl_vec3_make(0.0, 0.0, 0.0);
    for (int i = 0; i < count; ++i) {
        l[i] = cdl_frame_to_local(&p->frame, cdl_vec3_normalize(poly[i]));
        centre = cdl_vec3_add(centre, l[i]);
    }
    /* counter-clockwise seen from outside, as the cell contour wants */
    double turn = 0.0;
    for (int i = 0; i < count; ++i) turn += cdl_vec3_dot(cdl_vec3_cross(l[i], l[(i + 1) % count]), centre);
    if (turn < 0.0)
        for (int i = 0, j = count - 1; i < j; ++i, --j) {
            cdl_vec3 t = l[i];
            l[i] = l[j];
            l[j] = t;
        }
    cdl_vec3 nl = cdl_frame_to_local(&p->frame, n);
    poly_extent e;
    polygon_extent(l, count, &e);
    if (e.z_lo < 0.0) out[CDL_REINHART_GROUND] += weight * full_ring(CDL_PI / 2.0, CDL_PI, l, count, nl);
    if (e.z_hi <= 0.0) return 1;
    double alt_lo = e.z_lo > 0.0 ? asin(fmin(1.0, e.z_lo)) : 0.0, alt_hi = asin(fmin(1.0, e.z_hi));
    int r0 = (int)floor(alt_lo / p->alpha), r1 = (int)floor(alt_hi / p->alpha);
    if (r1 > p->rows - 1) r1 = p->rows - 1;
    for (int r = r0; r <= r1 && r < p->rows - 1; ++r) add_row(p, r, &e, l, count, nl, weight, out);
    if (r1 >= p->rows - 1)
        out[p->count - 1] += weight * full_ring(0.0, CDL_PI / 2.0 - (p->rows - 1) * p->alpha, l, count, nl);
    return 1;
}
