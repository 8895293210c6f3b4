/* ies_opening.c - the luminous opening in LM-63: sign codes of W, L, H <-> shapes.
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

#include "lights/formats/photometry_io.h"
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
