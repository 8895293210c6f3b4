/* photometry_opening.c - the luminous opening: IES sign codes <-> shapes.
 *
 * LM-63 encodes the shape in the signs of width W, length L and height H
 * (FORMAT_NOTES 1.7; Radiance ies2rad's tables; eulumdat-rs for 2019):
 *   1995:  point (0,0,0); rectangle (+,+,0); box (+,+,+); disk (-d,0,0);
 *          vertical cylinder (-d,0,+h); sphere (-d,0,-d); horizontal
 *          cylinder along the length (0,+L,-d) or the width (+W,0,-d);
 *          ellipse / elliptic cylinder / ellipsoid (-w,+l | +w,-l ; 0|+h|-h).
 *   2002/2019: point; rectangle; box; circle/ellipse (-,-,0); vertical
 *          (elliptic) cylinder (-,-,+); sphere/ellipsoid (-,-,-); horizontal
 *          cylinder along (-,+,-) or across (+,-,-); vertical circle/ellipse
 *          (-,0,-).
 * Files often use the other era's codes (many "2002" files write the 1995
 * disk), so the file's own table is tried first, then the other one.
 */
#include <math.h>
#include <string.h>

#include "lights/photometry_io.h"
#include "radiometry/constants.h"

static int sgn(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }

static int same(double a, double b) { return fabs(fabs(a) - fabs(b)) <= 1e-9 * fmax(fabs(a), fabs(b)); }

static cdl_luminous_shape table_1995(int w, int l, int h)
{
    if (w == 0 && l == 0 && h == 0) return CDL_LUMINOUS_SHAPE_POINT;
    if (w > 0 && l > 0) return h == 0 ? CDL_LUMINOUS_SHAPE_RECTANGLE : h > 0 ? CDL_LUMINOUS_SHAPE_BOX : CDL_LUMINOUS_SHAPE_UNKNOWN;
    if (w < 0 && l == 0)
        return h == 0 ? CDL_LUMINOUS_SHAPE_CIRCLE : h > 0 ? CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER : CDL_LUMINOUS_SHAPE_SPHERE;
    if (w == 0 && l > 0 && h < 0) return CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG;
    if (w > 0 && l == 0 && h < 0) return CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS;
    if ((w < 0 && l > 0) || (w > 0 && l < 0))
        return h == 0 ? CDL_LUMINOUS_SHAPE_ELLIPSE
               : h > 0 ? CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER
                       : CDL_LUMINOUS_SHAPE_ELLIPSOID;
    return CDL_LUMINOUS_SHAPE_UNKNOWN;
}

static cdl_luminous_shape table_2002(int w, int l, int h, double W, double L, double H)
{
    if (w == 0 && l == 0 && h == 0) return CDL_LUMINOUS_SHAPE_POINT;
    if (w > 0 && l > 0) return h == 0 ? CDL_LUMINOUS_SHAPE_RECTANGLE : h > 0 ? CDL_LUMINOUS_SHAPE_BOX : CDL_LUMINOUS_SHAPE_UNKNOWN;
    if (w < 0 && l < 0) {
        int round = same(W, L);
        if (h == 0) return round ? CDL_LUMINOUS_SHAPE_CIRCLE : CDL_LUMINOUS_SHAPE_ELLIPSE;
        if (h > 0) return round ? CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER : CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER;
        return round && same(W, H) ? CDL_LUMINOUS_SHAPE_SPHERE : CDL_LUMINOUS_SHAPE_ELLIPSOID;
    }
    if (w < 0 && l > 0 && h < 0) return CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG;
    if (w > 0 && l < 0 && h < 0) return CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS;
    if (w < 0 && l == 0 && h < 0) return same(W, H) ? CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE : CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE;
    return CDL_LUMINOUS_SHAPE_UNKNOWN;
}

void cdl_photometry_opening_from_ies(int version, double W, double L, double H, int units_type,
                                     cdl_luminous_opening *o)
{
    memset(o, 0, sizeof *o);
    o->raw[0] = W;
    o->raw[1] = L;
    o->raw[2] = H;
    o->units_type = units_type;
    double k = units_type == 1 ? CDL_METRES_PER_FOOT : 1.0;
    int w = sgn(W), l = sgn(L), h = sgn(H);
    int is_1995_era = version < 2002;
    cdl_luminous_shape s = is_1995_era ? table_1995(w, l, h) : table_2002(w, l, h, W, L, H);
    int from_1995 = is_1995_era;
    if (s == CDL_LUMINOUS_SHAPE_UNKNOWN) {
        s = is_1995_era ? table_2002(w, l, h, W, L, H) : table_1995(w, l, h);
        from_1995 = !is_1995_era;
    }
    /* a degenerate non-negative opening (a line) is still a rectangle */
    if (s == CDL_LUMINOUS_SHAPE_UNKNOWN && w >= 0 && l >= 0 && h >= 0)
        s = h > 0 ? CDL_LUMINOUS_SHAPE_BOX : CDL_LUMINOUS_SHAPE_RECTANGLE;
    o->shape = s;
    double aw = fabs(W) * k, al = fabs(L) * k, ah = fabs(H) * k;
    o->width_m = aw;
    o->length_m = al;
    o->height_m = ah;
    if (!from_1995) return;
    /* 1995 codes carry a diameter in one field and 0 in another. */
    switch (s) {
    case CDL_LUMINOUS_SHAPE_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER: o->length_m = aw; break;
    case CDL_LUMINOUS_SHAPE_SPHERE: o->length_m = aw; o->height_m = aw; break;
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG: o->width_m = ah; break;
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS: o->length_m = ah; break;
    default: break;
    }
}

void cdl_photometry_opening_to_ies(const cdl_luminous_opening *o, double out[3])
{
    double W = o->width_m, L = o->length_m, H = o->height_m;
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_POINT: out[0] = 0.0; out[1] = 0.0; out[2] = 0.0; return;
    case CDL_LUMINOUS_SHAPE_RECTANGLE: out[0] = W; out[1] = L; out[2] = 0.0; return;
    case CDL_LUMINOUS_SHAPE_BOX: out[0] = W; out[1] = L; out[2] = H; return;
    case CDL_LUMINOUS_SHAPE_CIRCLE: out[0] = -W; out[1] = -W; out[2] = 0.0; return;
    case CDL_LUMINOUS_SHAPE_ELLIPSE: out[0] = -W; out[1] = -L; out[2] = 0.0; return;
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER: out[0] = -W; out[1] = -W; out[2] = H; return;
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER: out[0] = -W; out[1] = -L; out[2] = H; return;
    case CDL_LUMINOUS_SHAPE_SPHERE: out[0] = -W; out[1] = -W; out[2] = -W; return;
    case CDL_LUMINOUS_SHAPE_ELLIPSOID: out[0] = -W; out[1] = -L; out[2] = -H; return;
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG: out[0] = -W; out[1] = L; out[2] = -H; return;
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS: out[0] = W; out[1] = -L; out[2] = -H; return;
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE: out[0] = -W; out[1] = 0.0; out[2] = -H; return;
    case CDL_LUMINOUS_SHAPE_UNKNOWN: {
        /* keep the file's own numbers, in metres */
        double k = o->units_type == 1 ? CDL_METRES_PER_FOOT : 1.0;
        out[0] = o->raw[0] * k;
        out[1] = o->raw[1] * k;
        out[2] = o->raw[2] * k;
        return;
    }
    }
    out[0] = out[1] = out[2] = 0.0;
}

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
