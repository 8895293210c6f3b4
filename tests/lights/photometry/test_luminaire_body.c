/* The body a file describes (lights/photometry/luminaire_body.h): an
 * EULUMDAT housing from lines 13-15 (CIE 190's example: 1100 x 400 x 100
 * mm over its 1000 x 316 mm luminous area), the flat rectangle and disk of
 * IES openings, an IES luminous box, and none for a point; each in the
 * luminaire's frame with the sizes the file gives. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "lights/photometry/luminaire_body.h"

#define DATA CANDELA_SOURCE_DIR "/tests/data/photometric/"

static char folder[512];

static int read_body(const char *path, cdl_luminaire_body *b)
{
    cdl_photometry *ph = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    if (cdl_photometry_read_file(path, &opt, &ph, &err) != CDL_OK) {
        fprintf(stderr, "%s: %s\n", path, err.message);
        CHECK(0);
        return 0;
    }
    cdl_luminaire_body_of(ph, b);
    cdl_photometry_release(ph);
    return 1;
}

/* An LM-63-2002 file with the opening "W L H" (m), one plane, 100 cd down. */
static int ies_with(const char *name, const char *opening, char *path, size_t size)
{
    snprintf(path, size, "%s/%s", folder, name);
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fprintf(f, "IESNA:LM-63-2002\n[TEST] body\nTILT=NONE\n1 -1 1 3 1 1 2 %s\n1 1 0\n0 90 180\n0\n100 0 0\n", opening);
    return fclose(f) == 0;
}

/* Sizes from the file's millimetres or metres, as a double holds them. */
static void check_box(const cdl_luminaire_body *b, double x0, double y0, double z0, double x1, double y1, double z1)
{
    const double tol = 1e-12;
    CHECK_MSG(fabs(b->lo.x - x0) < tol && fabs(b->lo.y - y0) < tol && fabs(b->lo.z - z0) < tol &&
                  fabs(b->hi.x - x1) < tol && fabs(b->hi.y - y1) < tol && fabs(b->hi.z - z1) < tol,
              "body [%g %g %g] .. [%g %g %g], expected [%g %g %g] .. [%g %g %g]", b->lo.x, b->lo.y, b->lo.z, b->hi.x,
              b->hi.y, b->hi.z, x0, y0, z0, x1, y1, z1);
}

int main(void)
{
    CHECK(fixture_folder("luminaire_body_file", folder, sizeof folder));
    cdl_luminaire_body b;
    char text[200], path[700];

    /* EULUMDAT: length 1100 mm along y (C90, as the luminous length maps),
     * width 400 along x, height 100 up from the luminous area */
    if (read_body(DATA "cie190_example.ldt", &b)) {
        CHECK(b.kind == CDL_BODY_BOX && b.housing == 1 && b.flat_axis == -1);
        check_box(&b, -0.2, -0.55, 0.0, 0.2, 0.55, 0.1);
        CHECK(cdl_luminaire_body_is_planar(&b));
        cdl_luminaire_body_describe(&b, text, sizeof text);
        CHECK_MSG(strcmp(text, "box 0.4 x 1.1 x 0.1 m (the luminaire's size (EULUMDAT))") == 0, "%s", text);
    }
    /* IES: the opening alone, a flat rectangle L (x) x W (y) reflecting up */
    if (ies_with("rect.ies", "0.3 1.2 0", path, sizeof path) && read_body(path, &b)) {
        CHECK(b.kind == CDL_BODY_BOX && b.housing == 0 && b.flat_axis == 2 && b.front_sign == 1);
        check_box(&b, -0.6, -0.15, 0.0, 0.6, 0.15, 0.0);
        cdl_luminaire_body_describe(&b, text, sizeof text);
        CHECK_MSG(strcmp(text, "rectangle 1.2 x 0.3 m (the luminous opening)") == 0, "%s", text);
    }
    /* a circle (negative sizes in LM-63-2002): a flat disk, curved */
    if (ies_with("circle.ies", "-0.15 -0.15 0", path, sizeof path) && read_body(path, &b)) {
        CHECK(b.kind == CDL_BODY_CYLINDER && b.flat_axis == 2 && b.front_sign == 1);
        check_box(&b, -0.075, -0.075, 0.0, 0.075, 0.075, 0.0);
        CHECK(!cdl_luminaire_body_is_planar(&b));
    }
    /* a luminous box about the photometric centre */
    if (ies_with("box.ies", "0.2 0.6 0.1", path, sizeof path) && read_body(path, &b)) {
        CHECK(b.kind == CDL_BODY_BOX && b.flat_axis == -1 && b.housing == 0);
        check_box(&b, -0.3, -0.1, -0.05, 0.3, 0.1, 0.05);
    }
    /* a point: no body */
    if (ies_with("point.ies", "0 0 0", path, sizeof path) && read_body(path, &b)) CHECK(b.kind == CDL_BODY_NONE);
    return check_finish();
}
