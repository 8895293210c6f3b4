/* info_json.c - `candela info --json`: one object per file (keys in `candela info --help`). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "info_output.h"
#include "lights/emitters/near_field_bound.h"
#include "solver/scene/scene.h"
#include "lights/photometry/photometry_metadata.h"

static void add_string(cJSON *obj, const char *key, const char *value)
{
    char *u = cdl_info_utf8(value ? value : "");
    cJSON_AddStringToObject(obj, key, u ? u : "");
    free(u);
}

/* A finite number, or null. */
static void add_number(cJSON *obj, const char *key, int known, double value)
{
    if (known && isfinite(value)) cJSON_AddNumberToObject(obj, key, value);
    else cJSON_AddNullToObject(obj, key);
}

static void add_planes(cJSON *obj, const char *key, const double angles[2], int about_peak)
{
    cJSON *o = cJSON_AddObjectToObject(obj, key);
    add_number(o, about_peak ? "vertical_plane" : "c0_c180", angles[0] >= 0.0, angles[0]);
    add_number(o, about_peak ? "across" : "c90_c270", angles[1] >= 0.0, angles[1]);
}

static void add_array(cJSON *obj, const char *key, const double *x, size_t n, double scale)
{
    cJSON *a = cJSON_AddArrayToObject(obj, key);
    for (size_t i = 0; i < n; ++i) cJSON_AddItemToArray(a, cJSON_CreateNumber(isfinite(x[i]) ? x[i] * scale : 0.0));
}

/* The viewing angles of the opening's luminance table: the C planes along
 * and across the luminaire, and the glare zone's gamma (CIE 117 tabulates
 * luminaire luminance at 45..85 degrees). */
static const double luminance_c_deg[4] = {0.0, 90.0, 180.0, 270.0};
static const double luminance_gamma_deg[6] = {0.0, 45.0, 55.0, 65.0, 75.0, 85.0};

/* What near-field light and glare need of the opening: its largest
 * dimension, the distance within which the solver spreads the light over
 * it, and its luminance (radiance for a radiometric file) at each viewing
 * angle, as the luminaire operates; null where the opening has no area. */
static void add_opening(cJSON *j, const cdl_photometry *p, const cdl_info_figures *f)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    const cdl_luminous_opening *o = &m->opening;
    cJSON *op = cJSON_AddObjectToObject(j, "opening");
    add_string(op, "shape", cdl_luminous_shape_name(o->shape));
    add_number(op, "width_m", 1, o->width_m);
    add_number(op, "length_m", 1, o->length_m);
    add_number(op, "height_m", 1, o->height_m);
    if (o->shape == CDL_LUMINOUS_SHAPE_BOX) {
        /* each side's luminous height: C0, C90, C180, C270 */
        cJSON *sides = cJSON_AddArrayToObject(op, "side_heights_m");
        for (int k = 0; k < 4; ++k)
            cJSON_AddItemToArray(sides, cJSON_CreateNumber(cdl_luminous_opening_box_side_height_m(o, k)));
    }
    if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) {
        /* the file's own names: length (line 16, along C90-C270), width (line 17, along C0-C180) */
        cJSON *area = cJSON_AddObjectToObject(op, "ldt_luminous_area_mm");
        add_number(area, "length", 1, m->ldt_luminous_mm[0]);
        add_number(area, "width", 1, m->ldt_luminous_mm[1]);
        cJSON *lum = cJSON_AddObjectToObject(op, "ldt_luminaire_mm");
        add_number(lum, "length", 1, m->ldt_luminaire_mm[0]);
        add_number(lum, "width", 1, m->ldt_luminaire_mm[1]);
        add_number(lum, "height", 1, m->ldt_luminaire_mm[2]);
    }
    double size = cdl_luminous_opening_largest_m(o);
    add_number(op, "largest_dimension_m", 1, size);
    cJSON_AddBoolToObject(op, "spread_by_solver", cdl_luminous_opening_is_spread(o));
    /* Where "auto" spreads the luminaire, per quality (the target decides it). */
    double targets[4] = {cdl_quality_target_error(CDL_QUALITY_DRAFT), cdl_quality_target_error(CDL_QUALITY_NORMAL),
                         cdl_quality_target_error(CDL_QUALITY_HIGH), cdl_quality_target_error(CDL_QUALITY_REFERENCE)};
    double d[4] = {0.0, 0.0, 0.0, 0.0};
    int spread = cdl_luminous_opening_is_spread(o) && cdl_near_field_switch_distances(p, targets, 4, d, NULL) == CDL_OK;
    add_number(op, "near_field_distance_m", spread, d[1]);
    cJSON *per = cJSON_AddObjectToObject(op, "near_field_distances_m");
    for (int q = 0; q < 4; ++q) add_number(per, cdl_quality_name((cdl_quality)q), spread, d[q]);
    const char *avg_key = f->s.radiometric ? "average_w_m2_sr" : "average_cd_m2";
    const char *max_key = f->s.radiometric ? "maximum_w_m2_sr" : "maximum_cd_m2";
    cJSON *rows = cJSON_AddArrayToObject(op, f->s.radiometric ? "radiance" : "luminance");
    for (int c = 0; c < 4; ++c)
        for (int g = 0; g < 6; ++g) {
            cdl_luminance avg, max;
            cdl_photometry_opening_luminance(p, luminance_c_deg[c], luminance_gamma_deg[g], &avg, &max);
            cJSON *row = cJSON_CreateObject();
            cJSON_AddNumberToObject(row, "c_deg", luminance_c_deg[c]);
            cJSON_AddNumberToObject(row, "gamma_deg", luminance_gamma_deg[g]);
            int has_area = cdl_luminous_opening_projected_area(
                               o, cdl_photometry_direction(CDL_PHOTOMETRIC_TYPE_C, luminance_c_deg[c],
                                                           luminance_gamma_deg[g])) > 0.0;
            add_number(row, avg_key, has_area, avg.cd_m2 * f->scale);
            add_number(row, max_key, has_area, max.cd_m2 * f->scale);
            cJSON_AddItemToArray(rows, row);
        }
}

/* Flux and intensity: the luminaire's (times the output factor) and the table's. */
static void add_light(cJSON *j, const cdl_photometry *p, const cdl_info_figures *f)
{
    const cdl_photometry_summary *s = &f->s;
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    int lum = !s->radiometric;
    add_number(j, "lamp_flux_lm", s->lamp_flux_known && lum, s->lamp_flux.lm);
    cJSON_AddNumberToObject(j, "lamps", (double)(m->lamp_set_count ? m->lamp_sets[0].count : 0));
    add_number(j, "flux_lm", lum, s->luminaire_flux.lm);
    add_number(j, "table_flux_lm", lum, s->flux.lm);
    add_number(j, "lor", s->lor_known, s->lor);
    add_number(j, "max_intensity_cd", lum, s->luminaire_max_intensity.cd);
    add_number(j, "table_max_intensity_cd", lum, s->max_intensity.cd);
    cJSON_AddBoolToObject(j, "radiometric", s->radiometric);
    if (s->radiometric) {
        add_number(j, "radiant_flux_w", 1, s->radiant_flux.W * s->output_factor);
        add_number(j, "max_radiant_intensity_w_sr", 1, s->max_radiant_intensity.W_sr * s->output_factor);
    }
    double zones[18];
    for (int k = 0; k < 18; ++k) zones[k] = s->radiometric ? s->radiant_zone_flux[k].W : s->zone_flux[k].lm;
    add_array(j, s->radiometric ? "zone_flux_w" : "zone_flux_lm", zones, 18, s->output_factor);
    add_number(j, "efficacy_lm_per_w", s->efficacy_known, s->efficacy.lm_W);
    add_number(j, "input_watts", m->input_watts > 0.0, m->input_watts);
    add_number(j, "ballast_factor", 1, m->ballast_factor);
    add_number(j, "output_factor", 1, s->output_factor);
    add_number(j, "candela_multiplier", 1, m->candela_multiplier);
}

static void add_classification(cJSON *j, const cdl_photometry *p, const cdl_info_figures *f)
{
    if (!f->classified) return;
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    cJSON *dr = cJSON_AddObjectToObject(j, "direct_ratios");
    double k[CDL_DIRECT_RATIO_COUNT];
    for (int i = 0; i < CDL_DIRECT_RATIO_COUNT; ++i) k[i] = cdl_direct_ratio_room_index(i);
    add_array(dr, "room_index", k, CDL_DIRECT_RATIO_COUNT, 1.0);
    add_array(dr, "computed", f->direct_ratio, CDL_DIRECT_RATIO_COUNT, 1.0);
    if (m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT) add_array(dr, "stated", m->ldt_direct_ratios, CDL_DIRECT_RATIO_COUNT, 1.0);
    cJSON *code = cJSON_AddArrayToObject(j, "cie_flux_code");
    for (int i = 0; i < 5; ++i) cJSON_AddItemToArray(code, cJSON_CreateNumber(round(f->flux_code[i])));
    add_array(j, "cie_flux_code_exact", f->flux_code, 5, 1.0);
    if (!f->bug_known) {
        cJSON_AddNullToObject(j, "bug_rating");
        return;
    }
    cJSON *bug = cJSON_AddObjectToObject(j, "bug_rating");
    char text[16];
    snprintf(text, sizeof text, "B%d-U%d-G%d", f->bug.b, f->bug.u, f->bug.g);
    cJSON_AddStringToObject(bug, "rating", text);
    cJSON_AddNumberToObject(bug, "b", f->bug.b);
    cJSON_AddNumberToObject(bug, "u", f->bug.u);
    cJSON_AddNumberToObject(bug, "g", f->bug.g);
    cJSON *zones = cJSON_AddObjectToObject(bug, "zone_lm");
    for (int z = 0; z < CDL_BUG_ZONES; ++z) add_number(zones, cdl_bug_zone_name(z), 1, f->bug.zone_lm[z]);
}

static void add_warnings(cJSON *j, const cdl_photometry *p)
{
    cJSON *w = cJSON_AddArrayToObject(j, "warnings");
    for (size_t i = 0; i < cdl_photometry_warning_count(p); ++i) {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "code", cdl_photometry_warning_code(p, i));
        unsigned line = cdl_photometry_warning_line(p, i);
        if (line) cJSON_AddNumberToObject(o, "line", line);
        else cJSON_AddNullToObject(o, "line");
        add_string(o, "message", cdl_photometry_warning(p, i));
        cJSON_AddItemToArray(w, o);
    }
}

cJSON *cdl_info_json(const char *path, const cdl_photometry *p, const cdl_info_figures *f)
{
    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    const cdl_photometry_summary *s = &f->s;
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    char version[32];
    cdl_info_version_text(m, version, sizeof version);
    cJSON *j = cJSON_CreateObject();
    if (!j) return NULL;
    add_string(j, "file", path);
    add_string(j, "format", m->format == CDL_PHOTOMETRY_FORMAT_IES        ? "IES"
                            : m->format == CDL_PHOTOMETRY_FORMAT_EULUMDAT ? "EULUMDAT"
                                                                          : "table");
    add_string(j, "version", version);
    add_string(j, "version_tag", m->version_tag);
    add_string(j, "photometric_type", cdl_info_type_letter(t.type));
    add_string(j, "symmetry", cdl_photometry_symmetry_name(t.symmetry));
    cJSON_AddNumberToObject(j, "c_planes", (double)m->file_horizontal_count);
    cJSON_AddNumberToObject(j, "gamma_angles", (double)m->file_vertical_count);
    cJSON_AddNumberToObject(j, "stored_planes", (double)t.horizontal_count);
    cJSON_AddBoolToObject(j, "absolute_photometry", m->absolute);
    add_light(j, p, f);
    cJSON *dir = cJSON_AddObjectToObject(j, "max_intensity_direction");
    add_number(dir, "c_deg", 1, s->max_c_deg);
    add_number(dir, "gamma_deg", 1, s->max_gamma_deg);
    add_planes(j, "beam_angle_deg", s->beam_angle_deg, s->spread_about_peak);
    add_planes(j, "field_angle_deg", s->field_angle_deg, s->spread_about_peak);
    cJSON_AddStringToObject(j, "spread_about", s->spread_about_peak ? "peak" : "nadir");
    if (s->spread_about_peak) {
        cJSON *axis = cJSON_AddObjectToObject(j, "spread_axis");
        add_number(axis, "c_deg", 1, s->spread_axis_c_deg);
        add_number(axis, "gamma_deg", 1, s->spread_axis_gamma_deg);
    }
    add_number(j, "downward_fraction", 1, s->downward_fraction);
    add_number(j, "upward_fraction", 1, s->upward_fraction);
    add_classification(j, p, f);
    if (m->tilt_count > 0) {
        cJSON *tilt = cJSON_AddObjectToObject(j, "tilt");
        cJSON_AddNumberToObject(tilt, "geometry", m->tilt_geometry);
        add_array(tilt, "angles_deg", m->tilt_angles_deg, m->tilt_count, 1.0);
        add_array(tilt, "factors", m->tilt_factors, m->tilt_count, 1.0);
    } else {
        cJSON_AddNullToObject(j, "tilt");
    }
    add_opening(j, p, f);
    cJSON *kw = cJSON_AddArrayToObject(j, "keywords");
    for (size_t i = 0; i < m->keyword_count; ++i) {
        cJSON *pair = cJSON_CreateObject();
        add_string(pair, "key", m->keywords[i].key);
        add_string(pair, "value", m->keywords[i].value);
        cJSON_AddItemToArray(kw, pair);
    }
    add_warnings(j, p);
    return j;
}
