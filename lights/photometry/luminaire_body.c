/* luminaire_body.c - the solid a luminaire occupies, from its file (luminaire_body.h). */
#include "lights/photometry/luminaire_body.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lights/photometry/photometry_metadata.h"

static void set_box(cdl_luminaire_body *b, double x, double y, double z_lo, double z_hi)
{
    b->lo = cdl_vec3_make(-0.5 * x, -0.5 * y, z_lo);
    b->hi = cdl_vec3_make(0.5 * x, 0.5 * y, z_hi);
}

/* Flat along the axis where the box has no extent, reflecting on the side
 * away from the opening: up for a horizontal one, towards -x for a
 * vertical one facing C0. */
static void finish(cdl_luminaire_body *b)
{
    b->flat_axis = -1;
    b->front_sign = 0;
    if (b->kind == CDL_BODY_NONE) return;
    if (b->hi.z == b->lo.z) {
        b->flat_axis = 2;
        b->front_sign = 1;
    } else if (b->hi.x == b->lo.x) {
        b->flat_axis = 0;
        b->front_sign = -1;
    }
}

/* EULUMDAT lines 13-15: the luminaire's length (or diameter), width (0:
 * round) and height in mm. The luminous area's sizes map as the reader
 * maps them (ldt_read.c: LDT length = the opening's width, along y; LDT
 * width = its length, along x), so the luminaire's do too. Returns 0 when
 * the file gives no luminaire size. */
static int ldt_housing(const cdl_photometry_metadata *m, cdl_luminaire_body *b)
{
    const cdl_luminous_opening *o = &m->opening;
    double along_y = fabs(m->ldt_luminaire_mm[0]) / 1000.0, along_x = fabs(m->ldt_luminaire_mm[1]) / 1000.0;
    double height = fabs(m->ldt_luminaire_mm[2]) / 1000.0;
    if (!(along_y > 0.0)) return 0;
    int round = !(along_x > 0.0);
    if (round) along_x = along_y;
    /* never smaller than its luminous area */
    along_x = fmax(along_x, o->length_m);
    along_y = fmax(along_y, o->width_m);
    /* a luminous solid (sides luminous to a height) is centred on the
     * photometric centre; the housing starts at its bottom */
    double solid = 0.0;
    if (o->shape == CDL_LUMINOUS_SHAPE_BOX)
        for (int k = 0; k < 4; ++k) solid = fmax(solid, cdl_luminous_opening_box_side_height_m(o, k));
    if (o->shape == CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER) solid = o->height_m;
    double bottom = -0.5 * solid;
    b->kind = round ? CDL_BODY_CYLINDER : CDL_BODY_BOX;
    b->axis = 2;
    set_box(b, along_x, along_y, bottom, bottom + fmax(height, solid));
    b->housing = 1;
    return 1;
}

void cdl_luminaire_body_of(const cdl_photometry *photometry, cdl_luminaire_body *b)
{
    memset(b, 0, sizeof *b);
    b->flat_axis = -1;
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(photometry);
    const cdl_luminous_opening *o = &m->opening;
    if (!cdl_luminous_opening_is_spread(o)) return;
    if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT && ldt_housing(m, b)) {
        finish(b);
        return;
    }
    double L = o->length_m, W = o->width_m, H = o->height_m;
    b->axis = 2;
    switch (o->shape) {
    case CDL_LUMINOUS_SHAPE_RECTANGLE: b->kind = CDL_BODY_BOX; set_box(b, L, W, 0.0, 0.0); break;
    case CDL_LUMINOUS_SHAPE_CIRCLE: b->kind = CDL_BODY_CYLINDER; set_box(b, W, W, 0.0, 0.0); break;
    case CDL_LUMINOUS_SHAPE_ELLIPSE: b->kind = CDL_BODY_CYLINDER; set_box(b, L, W, 0.0, 0.0); break;
    case CDL_LUMINOUS_SHAPE_VERTICAL_CIRCLE:
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPSE:
        /* in the y-z plane: width along y, height along z (emitter_opening.c) */
        b->kind = CDL_BODY_CYLINDER;
        b->axis = 0;
        set_box(b, 0.0, W, -0.5 * H, 0.5 * H);
        break;
    case CDL_LUMINOUS_SHAPE_BOX: {
        /* as tall as its tallest side (emitter_solid.c) */
        double h = H;
        for (int k = 0; k < 4; ++k) h = fmax(h, cdl_luminous_opening_box_side_height_m(o, k));
        b->kind = CDL_BODY_BOX;
        set_box(b, L, W, -0.5 * h, 0.5 * h);
        break;
    }
    case CDL_LUMINOUS_SHAPE_VERTICAL_CYLINDER: b->kind = CDL_BODY_CYLINDER; set_box(b, W, W, -0.5 * H, 0.5 * H); break;
    case CDL_LUMINOUS_SHAPE_VERTICAL_ELLIPTIC_CYLINDER:
        b->kind = CDL_BODY_CYLINDER;
        set_box(b, L, W, -0.5 * H, 0.5 * H);
        break;
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG:
    case CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ACROSS:
        b->kind = CDL_BODY_CYLINDER;
        b->axis = o->shape == CDL_LUMINOUS_SHAPE_HORIZONTAL_CYLINDER_ALONG ? 0 : 1;
        set_box(b, L, W, -0.5 * H, 0.5 * H);
        break;
    case CDL_LUMINOUS_SHAPE_SPHERE: b->kind = CDL_BODY_ELLIPSOID; set_box(b, W, W, -0.5 * W, 0.5 * W); break;
    case CDL_LUMINOUS_SHAPE_ELLIPSOID: b->kind = CDL_BODY_ELLIPSOID; set_box(b, L, W, -0.5 * H, 0.5 * H); break;
    default: b->kind = CDL_BODY_NONE; break;
    }
    finish(b);
}

int cdl_luminaire_body_is_planar(const cdl_luminaire_body *b)
{
    return b->kind == CDL_BODY_BOX;
}

void cdl_luminaire_body_describe(const cdl_luminaire_body *b, char *out, size_t size)
{
    double x = b->hi.x - b->lo.x, y = b->hi.y - b->lo.y, z = b->hi.z - b->lo.z;
    const char *whose = b->housing ? "the luminaire's size (EULUMDAT)" : "the luminous opening";
    const char *axes = "xyz";
    switch (b->kind) {
    case CDL_BODY_NONE: snprintf(out, size, "none (a point)"); return;
    case CDL_BODY_BOX:
        if (b->flat_axis == 2)
            snprintf(out, size, "rectangle %.4g x %.4g m (%s)", x, y, whose);
        else
            snprintf(out, size, "box %.4g x %.4g x %.4g m (%s)", x, y, z, whose);
        return;
    case CDL_BODY_CYLINDER:
        if (b->flat_axis == 2)
            snprintf(out, size, "%s %.4g x %.4g m (%s)", x == y ? "disk" : "ellipse", x, y, whose);
        else if (b->flat_axis == 0)
            snprintf(out, size, "vertical %s %.4g x %.4g m (%s)", y == z ? "disk" : "ellipse", y, z, whose);
        else
            snprintf(out, size, "cylinder along %c %.4g x %.4g x %.4g m (%s)", axes[b->axis], x, y, z, whose);
        return;
    case CDL_BODY_ELLIPSOID:
        snprintf(out, size, "%s %.4g x %.4g x %.4g m (%s)", x == y && y == z ? "sphere" : "ellipsoid", x, y, z, whose);
        return;
    }
}
