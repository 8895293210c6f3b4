/* The room in 3D (report/surface_view.h): which triangles each view shows
 * (those facing it, the room's near walls left out) and in what order, the
 * Gouraud colours read back from the rendered image against the vertices'
 * false colours, an unmapped table in grey, the legend, and the figure as
 * SVG and PDF. */
#include <cairo-pdf.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "radiometry/constants.h"
#include "report/surface_view.h"


/* A 6 x 5 x 2.8 m room as the six faces of a box seen from inside, each
 * face split in two triangles, and a 2 x 1 m table top; E = 100 + 20 x +
 * 10 y + 5 z lx on the room (linear: the Gouraud colours are exact), the
 * table unmapped. */
static const double W = 6, D = 5, H = 2.8;

typedef struct room {
    double xyz[24 * 3];
    uint32_t tri[12 * 3];
    double E[24];
    double table_xyz[12];
    uint32_t table_tri[6];
} room;

static void make_room(room *r)
{
    const double c[6][4][3] = {
        {{0, 0, 0}, {W, 0, 0}, {W, D, 0}, {0, D, 0}},   /* floor, facing +z */
        {{0, 0, H}, {0, D, H}, {W, D, H}, {W, 0, H}},   /* ceiling, -z */
        {{0, 0, 0}, {0, 0, H}, {W, 0, H}, {W, 0, 0}},   /* y = 0, +y */
        {{0, D, 0}, {W, D, 0}, {W, D, H}, {0, D, H}},   /* y = D, -y */
        {{0, 0, 0}, {0, D, 0}, {0, D, H}, {0, 0, H}},   /* x = 0, +x */
        {{W, 0, 0}, {W, 0, H}, {W, D, H}, {W, D, 0}},   /* x = W, -x */
    };
    for (int f = 0; f < 6; ++f) {
        for (int k = 0; k < 4; ++k) {
            memcpy(&r->xyz[3 * (4 * f + k)], c[f][k], 3 * sizeof(double));
            r->E[4 * f + k] = 100.0 + 20.0 * c[f][k][0] + 10.0 * c[f][k][1] + 5.0 * c[f][k][2];
        }
        const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; ++k) r->tri[6 * f + k] = (uint32_t)(4 * f) + q[k];
    }
    const double t[12] = {2, 2, 0.75, 4, 2, 0.75, 4, 3, 0.75, 2, 3, 0.75};
    memcpy(r->table_xyz, t, sizeof t);
    const uint32_t tt[6] = {0, 1, 2, 0, 2, 3};
    memcpy(r->table_tri, tt, sizeof tt);
}

/* The rendered image at 2 pixels per point. */
typedef struct image {
    cairo_surface_t *surface;
    const unsigned char *data;
    int stride;
} image;

static void render(const cdl_surface_view *v, image *img)
{
    cdl_figure f = cdl_surface_view_figure(v);
    img->surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)ceil(2 * f.width), (int)ceil(2 * f.height));
    cairo_t *cr = cairo_create(img->surface);
    cairo_scale(cr, 2.0, 2.0);
    f.draw(cr, f.user);
    cairo_destroy(cr);
    cairo_surface_flush(img->surface);
    img->data = cairo_image_surface_get_data(img->surface);
    img->stride = cairo_image_surface_get_stride(img->surface);
}

static void pixel(const image *img, double x_pt, double y_pt, int rgb[3])
{
    int x = (int)(2 * x_pt), y = (int)(2 * y_pt);
    uint32_t p;
    memcpy(&p, img->data + (size_t)y * (size_t)img->stride + 4 * (size_t)x, 4);
    rgb[0] = (int)(p >> 16 & 255);
    rgb[1] = (int)(p >> 8 & 255);
    rgb[2] = (int)(p & 255);
}

static int shows(const cdl_view_panel *p, uint32_t mesh, uint32_t triangle)
{
    for (size_t i = 0; i < p->count; ++i)
        if (p->order[i].mesh == mesh && p->order[i].triangle == triangle) return 1;
    return 0;
}

int main(void)
{
    cdl_error err;
    room r;
    make_room(&r);
    cdl_view_mesh meshes[2] = {{"room", r.xyz, 24, r.tri, 12, r.E}, {"table", r.table_xyz, 4, r.table_tri, 2, NULL}};
    cdl_vec3 lamp = {3, 2.5, 2.7};
    cdl_surface_view v;
    CHECK_OK(cdl_surface_view_prepare(&v, meshes, 2, &lamp, 1, &err), &err);

    /* From above (panel 0, looking along +x +y and down): the floor, the
     * far walls (y = D, x = W) and the table; from below (panel 1): the
     * ceiling and the walls y = 0, x = 0. Face f's triangles are 2f, 2f + 1. */
    const int above[6] = {1, 0, 0, 1, 0, 1}, below[6] = {0, 1, 1, 0, 1, 0};
    size_t wrong = 0;
    for (uint32_t f = 0; f < 6; ++f)
        for (uint32_t t = 2 * f; t < 2 * f + 2; ++t) {
            wrong += shows(&v.panel[0], 0, t) != above[f];
            wrong += shows(&v.panel[1], 0, t) != below[f];
        }
    CHECK(wrong == 0);
    CHECK(shows(&v.panel[0], 1, 0) && shows(&v.panel[0], 1, 1) && !shows(&v.panel[1], 1, 0));
    CHECK(v.panel[0].count == 8 && v.panel[1].count == 6);
    /* Farthest first: the table (0.75 m up) is painted after the floor. */
    size_t floor_at = 0, table_at = 0;
    for (size_t i = 0; i < v.panel[0].count; ++i) {
        if (v.panel[0].order[i].mesh == 0 && v.panel[0].order[i].triangle == 0) floor_at = i;
        if (v.panel[0].order[i].mesh == 1 && v.panel[0].order[i].triangle == 0) table_at = i;
    }
    CHECK(table_at > floor_at);

    image img;
    render(&v, &img);
    /* Gouraud: at a triangle's centroid the colour is the mean of its
     * corners' false colours (a parallel projection keeps barycentric
     * coordinates), within 3 levels of rounding and cairo's patch
     * subdivision. The far wall y = D (face 3) and the ceiling (face 1). */
    const int faces[2] = {3, 1};
    for (int k = 0; k < 2; ++k) {
        uint32_t t = 2 * (uint32_t)faces[k];
        cdl_vec3 c = cdl_vec3_make(0, 0, 0);
        double mean[3] = {0, 0, 0};
        for (int j = 0; j < 3; ++j) {
            uint32_t i = r.tri[3 * t + j];
            c = cdl_vec3_add(c, cdl_vec3_make(r.xyz[3 * i], r.xyz[3 * i + 1], r.xyz[3 * i + 2]));
            for (int ch = 0; ch < 3; ++ch) mean[ch] += v.rgb[0][3 * i + ch] / 3.0;
        }
        double x, y;
        cdl_surface_view_project(&v, k, cdl_vec3_scale(c, 1.0 / 3.0), &x, &y);
        int got[3];
        pixel(&img, x, y, got);
        CHECK_MSG(fabs(got[0] - mean[0]) <= 3 && fabs(got[1] - mean[1]) <= 3 && fabs(got[2] - mean[2]) <= 3,
                  "panel %d: (%d %d %d) against (%.1f %.1f %.1f)", k, got[0], got[1], got[2], mean[0], mean[1],
                  mean[2]);
    }
    /* The table is grey where it covers the floor. */
    double x, y;
    cdl_surface_view_project(&v, 0, cdl_vec3_make(3, 2.5, 0.75), &x, &y);
    int got[3];
    pixel(&img, x, y, got);
    CHECK(got[0] == got[1] && got[1] == got[2] && got[0] > 150 && got[0] < 250);
    /* The legend: its colours left to right are the ramp's. */
    pixel(&img, v.legend_x + 0.75 * v.legend_w, v.legend_y + 5.0, got);
    const uint8_t *want = &v.legend_rgb[3 * 192];
    CHECK(abs(got[0] - want[0]) <= 3 && abs(got[1] - want[1]) <= 3 && abs(got[2] - want[2]) <= 3);
    cairo_surface_destroy(img.surface);

    /* The figure as SVG (the HTML report's) and on a PDF page. */
    cdl_figure f = cdl_surface_view_figure(&v);
    char *svg = NULL;
    size_t size = 0;
    CHECK_OK(cdl_figure_svg(&f, &svg, &size, &err), &err);
    CHECK(svg && size > 1000 && strstr(svg, "The surfaces in 3D"));
    free(svg);
    cairo_surface_t *pdf = cairo_pdf_surface_create_for_stream(NULL, NULL, f.width, f.height);
    cairo_t *cr = cairo_create(pdf);
    f.draw(cr, f.user);
    CHECK(cairo_status(cr) == CAIRO_STATUS_SUCCESS);
    cairo_destroy(cr);
    cairo_surface_destroy(pdf);
    cdl_surface_view_release(&v);
    return check_finish();
}
