/* The CIE 190 UGR table (glare/ugr_table.h): a Lambertian opening against
 * the table computed here independently from closed forms; CIE 190's own
 * worked example against the table it prints; the flux scaling law. */
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "file_fixture.h"
#include "glare/position_index.h"
#include "glare/room_flux.h"
#include "glare/ugr_table.h"
#include "glare/ugr_table_conditions.h"
#include "polygon_factor.h"
#include "radiometry/constants.h"

#define PHOTOMETRIC CANDELA_SOURCE_DIR "/tests/data/photometric"

/* An IES file: I0 cos(gamma) below the horizontal, none above, on a flat
 * rectangular opening w x l (m), the table every 0.5 degree. */
static int write_lambertian(const char *path, double I0, double multiplier, double w, double l)
{
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fprintf(f, "IESNA:LM-63-2002\n[TEST] lambertian opening\nTILT=NONE\n1 -1 %g 181 1 1 2 %g %g 0\n1 1 0\n",
            multiplier, w, l);
    for (int k = 0; k <= 180; ++k) fprintf(f, "%g%s", 0.5 * k, k % 10 == 9 ? "\n" : " ");
    fprintf(f, "\n0\n");
    for (int k = 0; k <= 180; ++k) fprintf(f, "%.17g%s", I0 * cos(0.5 * k * CDL_DEG_TO_RAD), k % 6 == 5 ? "\n" : " ");
    fprintf(f, "\n");
    return fclose(f) == 0;
}

static cdl_photometry *read_photometry(const char *path)
{
    cdl_photometry_read_options ro = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    cdl_photometry *p = NULL;
    cdl_error err;
    if (cdl_photometry_read_file(path, &ro, &p, &err) != CDL_OK) fprintf(stderr, "%s\n", err.message);
    return p;
}

/* Lumens the walls receive after interreflection per lumen received
 * directly by surface `from` (0 floor, 1 walls, 2 ceiling), the direct one
 * excluded: the bounce series summed term by term (each bounce the flux
 * leaving surface i, rho_i times what it received, spreads by the
 * configuration factors), an independent route to the library's solve. */
static double walls_received(double X, double Y, double H, const double rho[3], int from)
{
    double Af = X * Y, Aw = 2.0 * H * (X + Y);
    double f_fc = cdl_room_parallel_factor(X, Y, H), f_wf = (1.0 - f_fc) * Af / Aw;
    double f[3][3] = {{0.0, 1.0 - f_fc, f_fc}, {f_wf, 1.0 - 2.0 * f_wf, f_wf}, {f_fc, 1.0 - f_fc, 0.0}};
    double now[3] = {0.0, 0.0, 0.0}, total = 0.0;
    now[from] = 1.0;
    for (int bounce = 0; bounce < 400; ++bounce) {
        double next[3] = {0.0, 0.0, 0.0};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) next[j] += rho[i] * now[i] * f[i][j];
        total += next[1];
        memcpy(now, next, sizeof now);
    }
    return total;
}

/* The table of a Lambertian opening (luminance I0 / A seen from anywhere
 * below), computed here: each luminaire's direct share on the eye's plane
 * by Lambert's factor from a point facing down, interreflection by the
 * bounce series, and the glare sum with L = I0 / A and omega = A cos(gamma)
 * / r^2. */
static double lambertian_cell(double I0, double A, double xh, double yh, int set, double *Lb_out)
{
    const double H = 2.0, S = 0.5, flux = CDL_PI * I0;
    double X = xh * H, Y = yh * H;
    int nx = (int)lround(X / S), ny = (int)lround(Y / S);
    cdl_vec3 plane[4] = {{0, 0, 0}, {X, 0, 0}, {X, Y, 0}, {0, Y, 0}};
    double share = 0.0, sum = 0.0;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) {
            cdl_vec3 at = {(i + 0.5) * S, (j + 0.5) * S, H};
            share += lambert_polygon(plane, 4, 1.0, at, cdl_vec3_make(0, 0, -1)) / CDL_PI;
            double R = (j + 0.5) * S, T = (i + 0.5) * S - 0.5 * X, r2 = R * R + T * T + H * H, p;
            if (cdl_glare_position_index(R, T, H, &p) != CDL_GLARE_IN_VIEW) continue;
            double L = I0 / A, omega = A * (H / sqrt(r2)) / r2;
            sum += L * L * omega / (p * p);
        }
    share /= nx * ny;
    const double *rho = cdl_ugr_table_reflectances[set];
    double r3[3] = {rho[2], rho[1], rho[0]}; /* floor, walls, ceiling */
    double E = nx * ny * flux * (share * walls_received(X, Y, H, r3, 0) + (1.0 - share) * walls_received(X, Y, H, r3, 1)) /
               (2.0 * H * (X + Y));
    *Lb_out = E / CDL_PI;
    return 8.0 * log10(0.25 * sum / *Lb_out);
}

static void test_lambertian_opening(const char *folder)
{
    char path[600], path2[600];
    snprintf(path, sizeof path, "%s/lambert.ies", folder);
    snprintf(path2, sizeof path2, "%s/lambert_x2.ies", folder);
    const double I0 = 1000.0, w = 0.5, l = 0.6;
    CHECK(write_lambertian(path, I0, 1.0, w, l));
    CHECK(write_lambertian(path2, I0, 2.0, w, l));
    cdl_photometry *p = read_photometry(path), *p2 = read_photometry(path2);
    CHECK(p && p2);
    if (!p || !p2) return;
    cdl_ugr_table t = CDL_UGR_TABLE_INIT, t2 = CDL_UGR_TABLE_INIT;
    cdl_error err;
    CHECK_OK(cdl_ugr_table_compute(p, NULL, &t, &err), &err);
    CHECK_OK(cdl_ugr_table_compute(p2, NULL, &t2, &err), &err);
    CHECK(t.spacing_to_height == 0.25);
    /* the table's interpolation of cos(gamma) at 0.5 degree steps is within
     * 1e-5 of the cosine: flux and luminance to 1e-5, UGR to 1e-4 */
    CHECK_REL(t.flux_lm, CDL_PI * I0, 2e-5);
    double worst = 0.0;
    for (int i = 0; i < CDL_UGR_TABLE_ROOMS; ++i) {
        const cdl_ugr_table_room *r = &t.rooms[i];
        CHECK(r->luminaires == (size_t)lround(16.0 * r->x_h * r->y_h));
        for (int s = 0; s < CDL_UGR_TABLE_REFLECTANCE_SETS; ++s) {
            double Lb, expected = lambertian_cell(I0, w * l, r->x_h, r->y_h, s, &Lb);
            CHECK_REL(r->background_cd_m2[s], Lb, 1e-4);
            for (int view = 0; view < 2; ++view) {
                CHECK(r->defined[view]);
                CHECK_ABS(r->ugr[view][s], expected, 1e-3);
                worst = fmax(worst, fabs(r->ugr[view][s] - expected));
                /* twice the candela: L^2 / Lb doubles, + 8 log10(2) */
                CHECK_ABS(t2.rooms[i].ugr[view][s] - r->ugr[view][s], 8.0 * log10(2.0), 1e-9);
            }
        }
    }
    fprintf(stderr, "lambertian opening: worst |table - independent| %.2g UGR\n", worst);
    /* a sanity anchor: a 3333 cd/m2 opening in 4H x 8H, 70/50/20 */
    CHECK(t.rooms[10].ugr[0][0] > 10.0 && t.rooms[10].ugr[0][0] < 30.0);
    cdl_photometry_release(p);
    cdl_photometry_release(p2);
}

/* A table of 19 rows by 10 columns as printed, after '#' comment lines. */
static int read_reference(const char *path, double ref[19][10])
{
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    char line[512];
    int rows = 0;
    while (rows < 19 && fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[0] == '\n') continue;
        char *at = line;
        for (int c = 0; c < 10; ++c) {
            char *end;
            ref[rows][c] = strtod(at, &end);
            if (end == at) {
                fclose(f);
                return 0;
            }
            at = end + (*end == ',');
        }
        ++rows;
    }
    fclose(f);
    return rows == 19;
}

/* |table - reference| over every cell: each within `cell_tol`, their RMS
 * within `rms_tol`. */
static void compare_table(const char *ldt, const char *csv, double shr, double cell_tol, double rms_tol)
{
    cdl_photometry *p = read_photometry(ldt);
    double ref[19][10];
    CHECK(p != NULL);
    CHECK_MSG(read_reference(csv, ref), "%s", csv);
    if (!p) return;
    cdl_ugr_table t = CDL_UGR_TABLE_INIT;
    cdl_error err;
    cdl_ugr_table_options o = CDL_UGR_TABLE_OPTIONS_INIT;
    o.spacing_to_height = shr;
    CHECK_OK(cdl_ugr_table_compute(p, &o, &t, &err), &err);
    double ss = 0.0, worst = 0.0, bias = 0.0;
    for (int i = 0; i < 19; ++i)
        for (int c = 0; c < 10; ++c) {
            double d = t.rooms[i].ugr[c / 5][c % 5] - ref[i][c];
            CHECK_MSG(fabs(d) <= cell_tol, "%s room %d column %d: %.2f, printed %.1f", csv, i, c, ref[i][c] + d, ref[i][c]);
            ss += d * d;
            bias += d;
            worst = fmax(worst, fabs(d));
        }
    double rms = sqrt(ss / 190.0);
    CHECK_MSG(rms <= rms_tol, "%s: rms %.3f", csv, rms);
    fprintf(stderr, "%s: mean %+.3f, rms %.3f, worst %.3f\n", strrchr(csv, '/') + 1, bias / 190.0, rms, worst);
    cdl_photometry_release(p);
}

int main(void)
{
    char folder[512];
    CHECK(fixture_folder("glare_ugr_table", folder, sizeof folder));
    test_lambertian_opening(folder);
    /* CIE 190:2010's worked example (its SHR 1 arrangement): the printed
     * table rounds to 0.1 (0.05), and CIE 190 sums 10-degree zones at their
     * mid-angles where we integrate the table exactly; measured: rms 0.05,
     * worst 0.12. A transcription slip in either file would show as a cell
     * off by more. */
    compare_table(PHOTOMETRIC "/cie190_example.ldt", PHOTOMETRIC "/cie190_example_ugr.csv", 1.0, 0.15, 0.07);
    return check_finish();
}
