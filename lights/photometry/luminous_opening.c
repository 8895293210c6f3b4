/* luminous_opening.c - the luminous opening of a luminaire (LM-63-2019 Table 1):
 * flat or solid, its sizes, its projected area, the luminance it implies. */
#include <math.h>
#include <string.h>

#include "lights/photometry/photometry_internal.h"
#include "radiometry/constants.h"

int cdl_luminous_opening_is_flat(const cdl_luminous_opening *o)
{
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_RECTANGLE:
    case CDL_LUMINOUS_SHAPE_ELLIPSE: return o->width_m > 0.0 && o->length_m > 0.0;
    case CDL_LUMINOUS_SHAPE_CIRCLE: return o->width_m > 0.0;
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE: return o->width_m > 0.0 && o->height_m > 0.0;
    default: return 0;
    }
}

int cdl_luminous_opening_is_spread(const cdl_luminous_opening *o)
{
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_BOX:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER:
    case CDL_LUMINOUS_SHAPE_ELLIPSOID:
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG:
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS:
        return o->width_m > 0.0 && o->length_m > 0.0 && o->height_m > 0.0;
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER: return o->width_m > 0.0 && o->height_m > 0.0;
    case CDL_LUMINOUS_SHAPE_SPHERE: return o->width_m > 0.0;
    default: return cdl_luminous_opening_is_flat(o);
    }
}

/* The height of a box's sides: its tallest side where they differ, else
 * height_m. */
static double box_height(const cdl_luminous_opening *o)
{
    double h = fmax(fmax(o->side_height_m[0], o->side_height_m[1]), fmax(o->side_height_m[2], o->side_height_m[3]));
    return h > 0.0 ? h : o->height_m;
}

double cdl_luminous_opening_box_side_height_m(const cdl_luminous_opening *o, int side)
{
    if (side < 0 || side > 3) return 0.0;
    int differ = o->side_height_m[0] > 0.0 || o->side_height_m[1] > 0.0 || o->side_height_m[2] > 0.0 ||
                 o->side_height_m[3] > 0.0;
    return differ ? o->side_height_m[side] : o->height_m;
}

double cdl_luminous_opening_largest_m(const cdl_luminous_opening *o)
{
    double W = o->width_m, L = o->length_m, H = o->shape == CDL_LUMINOUS_SHAPE_BOX ? box_height(o) : o->height_m;
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_POINT: return 0.0;
    case CDL_LUMINOUS_SHAPE_CIRCLE: return W;
    case CDL_LUMINOUS_SHAPE_ELLIPSE:
    case CDL_LUMINOUS_SHAPE_SPHERE:
    case CDL_LUMINOUS_SHAPE_ELLIPSOID:
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE: return fmax(W, fmax(L, H));
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER: return hypot(W, H);
    default: return sqrt(W * W + L * L + H * H);
    }
}

/* The width of an ellipse of semi-axes a (along s) and b (along t) seen
 * along the in-plane direction (ds, dt), times the length of (ds, dt):
 * the silhouette 2 sqrt(a^2 dt^2 + b^2 ds^2). */
static double silhouette(double a, double b, double ds, double dt)
{
    return 2.0 * sqrt(a * a * dt * dt + b * b * ds * ds);
}

double cdl_luminous_opening_projected_area(const cdl_luminous_opening *o, cdl_vec3 dir)
{
    double len = cdl_vec3_length(dir);
    if (!(len > 0.0) || !isfinite(len)) return 0.0;
    double x = fabs(dir.x / len), y = fabs(dir.y / len), z = fabs(dir.z / len);
    /* the box's side facing dir along x (C0 when dir.x > 0, else C180) and
     * along y (C90 or C270), each at its own luminous height */
    double hx = cdl_luminous_opening_box_side_height_m(o, dir.x > 0.0 ? 0 : 2);
    double hy = cdl_luminous_opening_box_side_height_m(o, dir.y > 0.0 ? 1 : 3);
    /* luminaire frame: length L along x, width W along y, height H along z */
    double a = 0.5 * o->length_m, b = 0.5 * o->width_m, c = 0.5 * o->height_m;
    double W = o->width_m, L = o->length_m, H = o->height_m;
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_RECTANGLE: return W * L * z;
    case CDL_LUMINOUS_SHAPE_BOX: return W * L * z + L * hy * y + W * hx * x;
    case CDL_LUMINOUS_SHAPE_CIRCLE: return 0.25 * CDL_PI * W * W * z;
    case CDL_LUMINOUS_SHAPE_ELLIPSE: return CDL_PI * a * b * z;
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER: return 0.25 * CDL_PI * W * W * z + W * H * hypot(x, y);
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER: return CDL_PI * a * b * z + H * silhouette(a, b, x, y);
    case CDL_LUMINOUS_SHAPE_SPHERE: return 0.25 * CDL_PI * W * W;
    case CDL_LUMINOUS_SHAPE_ELLIPSOID:
        return CDL_PI * sqrt(b * b * c * c * x * x + a * a * c * c * y * y + a * a * b * b * z * z);
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG: return CDL_PI * b * c * x + L * silhouette(b, c, y, z);
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS: return CDL_PI * a * c * y + W * silhouette(a, c, x, z);
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE: return CDL_PI * b * c * x;
    case CDL_LUMINOUS_SHAPE_POINT:
    case CDL_LUMINOUS_SHAPE_UNKNOWN: return 0.0;
    }
    return 0.0;
}

void cdl_photometry_opening_luminance(const cdl_photometry *p, double c_deg, double gamma_deg,
                                      cdl_luminance *average, cdl_luminance *maximum)
{
    cdl_vec3 dir = cdl_photometry_direction(CDL_PHOTOMETRIC_TYPE_C, c_deg, gamma_deg);
    double A = cdl_luminous_opening_projected_area(&cdl_photometry_get_metadata(p)->opening, dir);
    /* L = I / A_projected (luminance of a source seen as a whole) */
    double L = A > 0.0 ? cdl_photometry_intensity(p, dir).cd / A : 0.0;
    *average = cdl_nits(L);
    *maximum = cdl_nits(L);
}
