/* scene_lights.c - emitters from the scene's luminaires and emitting surfaces. */
#include "solver/scene/scene_lights.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/strings.h"
#include "lights/emitters/near_field_bound.h"
#include "lights/photometry/photometry_metadata.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "solver/scene/exr_image.h"
#include "solver/scene/scene_sky.h"

static const char *luminaire_kind_name(cdl_luminaire_kind k)
{
    switch (k) {
    case CDL_LUMINAIRE_POINT: return "point";
    case CDL_LUMINAIRE_SPOT: return "spot";
    case CDL_LUMINAIRE_GONIOMETRIC: return "goniometric";
    case CDL_LUMINAIRE_AREA: return "area";
    case CDL_LUMINAIRE_DIRECTIONAL: return "directional";
    case CDL_LUMINAIRE_ENVIRONMENT: return "environment";
    }
    return "unknown";
}

static void bounds_add(cdl_scene_light *l, cdl_vec3 p)
{
    if (!l->bounded) l->bounds = cdl_bounds3_empty();
    l->bounded = 1;
    cdl_bounds3_grow(&l->bounds, p);
}

/* 2D convex hull (Andrew's monotone chain) of n points, counter-clockwise;
 * returns the hull size. `hull` has room for n + 1 indices. */
static int cmp_xy(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    if (p[1] != q[1]) return p[1] < q[1] ? -1 : 1;
    return 0;
}

static double cross2(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

static int convex_hull_2d(double *pts, int n, double *hull)
{
    qsort(pts, (size_t)n, 2 * sizeof(double), cmp_xy);
    int k = 0;
    for (int i = 0; i < n; ++i) {
        while (k >= 2 && cross2(&hull[2 * (k - 2)], &hull[2 * (k - 1)], &pts[2 * i]) <= 0) k--;
        hull[2 * k] = pts[2 * i];
        hull[2 * k + 1] = pts[2 * i + 1];
        k++;
    }
    for (int i = n - 2, t = k + 1; i >= 0; --i) {
        while (k >= t && cross2(&hull[2 * (k - 2)], &hull[2 * (k - 1)], &pts[2 * i]) <= 0) k--;
        hull[2 * k] = pts[2 * i];
        hull[2 * k + 1] = pts[2 * i + 1];
        k++;
    }
    return k > 1 ? k - 1 : k;
}

/* Outline of a triangle-set emitter: its convex hull in its plane (or the
 * bounding rectangle of the hull if that has too many corners). Leaves
 * outline_count = 0 for non-planar sets (then the light is always sampled). */
static cdl_status outline_of_triangles(cdl_scene_light *l, const cdl_shape *s, cdl_error *err)
{
    if (s->vertex_count < 3) return CDL_OK;
    const double *v = s->vertices;
    cdl_vec3 o = cdl_vec3_make(v[0], v[1], v[2]);
    cdl_vec3 nrm = cdl_vec3_make(0, 0, 0);
    double size = 0.0;
    for (size_t t = 0; t < s->triangle_count; ++t) {
        const uint32_t *tri = &s->triangles[3 * t];
        cdl_vec3 a = cdl_vec3_make(v[3 * tri[0]], v[3 * tri[0] + 1], v[3 * tri[0] + 2]);
        cdl_vec3 b = cdl_vec3_make(v[3 * tri[1]], v[3 * tri[1] + 1], v[3 * tri[1] + 2]);
        cdl_vec3 c = cdl_vec3_make(v[3 * tri[2]], v[3 * tri[2] + 1], v[3 * tri[2] + 2]);
        nrm = cdl_vec3_add(nrm, cdl_vec3_cross(cdl_vec3_sub(b, a), cdl_vec3_sub(c, a)));
    }
    for (size_t i = 0; i < s->vertex_count; ++i)
        size = fmax(size, cdl_vec3_distance(o, cdl_vec3_make(v[3 * i], v[3 * i + 1], v[3 * i + 2])));
    if (!(cdl_vec3_length(nrm) > 0.0)) return CDL_OK;
    nrm = cdl_vec3_normalize(nrm);
    for (size_t i = 0; i < s->vertex_count; ++i) {
        cdl_vec3 p = cdl_vec3_make(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
        if (fabs(cdl_vec3_dot(cdl_vec3_sub(p, o), nrm)) > 1e-9 * size) return CDL_OK; /* not planar */
    }
    cdl_frame plane = cdl_frame_from_normal(nrm);
    cdl_vec3 e1 = plane.s, e2 = plane.t;
    double *pts = malloc(s->vertex_count * 2 * sizeof(double));
    double *hull = malloc((s->vertex_count + 2) * 2 * sizeof(double));
    if (!pts || !hull) {
        free(pts);
        free(hull);
        return cdl_error_out_of_memory(err);
    }
    for (size_t i = 0; i < s->vertex_count; ++i) {
        cdl_vec3 d = cdl_vec3_sub(cdl_vec3_make(v[3 * i], v[3 * i + 1], v[3 * i + 2]), o);
        pts[2 * i] = cdl_vec3_dot(d, e1);
        pts[2 * i + 1] = cdl_vec3_dot(d, e2);
    }
    int h = convex_hull_2d(pts, (int)s->vertex_count, hull);
    const int max_outline = CDL_SCENE_LIGHT_OUTLINE_MAX;
    if (h >= 3 && h <= max_outline) {
        for (int i = 0; i < h; ++i)
            l->outline[i] = cdl_vec3_add(o, cdl_vec3_add(cdl_vec3_scale(e1, hull[2 * i]), cdl_vec3_scale(e2, hull[2 * i + 1])));
        l->outline_count = h;
    } else if (h > max_outline) {
        double lo[2] = {DBL_MAX, DBL_MAX}, hi[2] = {-DBL_MAX, -DBL_MAX};
        for (int i = 0; i < h; ++i)
            for (int k = 0; k < 2; ++k) {
                lo[k] = fmin(lo[k], hull[2 * i + k]);
                hi[k] = fmax(hi[k], hull[2 * i + k]);
            }
        const double corner[4][2] = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
        for (int i = 0; i < 4; ++i)
            l->outline[i] = cdl_vec3_add(o, cdl_vec3_add(cdl_vec3_scale(e1, corner[i][0]), cdl_vec3_scale(e2, corner[i][1])));
        l->outline_count = 4;
    }
    free(pts);
    free(hull);
    return CDL_OK;
}

/* Outline, bounds and closed-form flag of an area emitter from its shape. */
static cdl_status describe_area(cdl_scene_light *l, const cdl_shape *s, cdl_error *err)
{
    l->has_closed_form = 1;
    l->outline = malloc(CDL_SCENE_LIGHT_OUTLINE_MAX * sizeof *l->outline);
    if (!l->outline) return cdl_error_out_of_memory(err);
    switch (s->kind) {
    case CDL_SHAPE_RECT: {
        cdl_vec3 c[4] = {s->origin, cdl_vec3_add(s->origin, s->u), cdl_vec3_add(cdl_vec3_add(s->origin, s->u), s->v),
                         cdl_vec3_add(s->origin, s->v)};
        for (int i = 0; i < 4; ++i) {
            l->outline[i] = c[i];
            bounds_add(l, c[i]);
        }
        l->outline_count = 4;
        return CDL_OK;
    }
    case CDL_SHAPE_DISK: {
        /* Circumscribed 16-gon: contains the disk. */
        const int sides = 16;
        double R = s->radius / cos(CDL_PI / sides);
        cdl_frame disk = cdl_frame_from_normal(cdl_vec3_normalize(s->normal));
        for (int i = 0; i < sides; ++i) {
            double a = CDL_TWO_PI * i / sides;
            l->outline[i] = cdl_vec3_add(s->center, cdl_frame_to_world(&disk, cdl_vec3_make(R * cos(a), R * sin(a), 0.0)));
            bounds_add(l, l->outline[i]);
        }
        l->outline_count = sides;
        return CDL_OK;
    }
    case CDL_SHAPE_SPHERE:
        l->outline_is_sphere = 1;
        l->sphere_center = s->center;
        l->sphere_radius = s->radius;
        bounds_add(l, cdl_vec3_sub(s->center, cdl_vec3_make(s->radius, s->radius, s->radius)));
        bounds_add(l, cdl_vec3_add(s->center, cdl_vec3_make(s->radius, s->radius, s->radius)));
        return CDL_OK;
    case CDL_SHAPE_TRIANGLES:
        for (size_t i = 0; i < s->vertex_count; ++i)
            bounds_add(l, cdl_vec3_make(s->vertices[3 * i], s->vertices[3 * i + 1], s->vertices[3 * i + 2]));
        return outline_of_triangles(l, s, err);
    }
    return CDL_OK;
}

static cdl_status fail_at(cdl_error *err, const cdl_scene *scene, const char *json_path, cdl_status st)
{
    cdl_error_prefix(err, "%s: %s: ", scene->path, json_path);
    return st;
}

/* Environment image -> luminance per pixel (Y, or Rec. 709 luma of RGB), x scale. */
static cdl_status read_environment_image(const cdl_scene *scene, const cdl_luminaire_spec *spec, float **out, int *w,
                                         int *h, cdl_error *err)
{
    cdl_exr_image img;
    cdl_status st = cdl_exr_read(spec->file, &img, err);
    if (st != CDL_OK) {
        cdl_error_prefix(err, "%s: %s.file: ", scene->path, spec->json_path);
        return st;
    }
    const float *Y = cdl_exr_image_channel(&img, "Y");
    const float *R = cdl_exr_image_channel(&img, "R"), *G = cdl_exr_image_channel(&img, "G"),
                *B = cdl_exr_image_channel(&img, "B");
    if (!Y && !(R && G && B)) {
        cdl_exr_image_release(&img);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: %s.file: %s: expected a Y channel or R, G and B channels",
                             scene->path, spec->json_path, spec->file);
    }
    size_t n = (size_t)img.width * (size_t)img.height;
    float *lum = malloc(n * sizeof(float));
    if (!lum) {
        cdl_exr_image_release(&img);
        return cdl_error_out_of_memory(err);
    }
    for (size_t i = 0; i < n; ++i) {
        /* DESIGN.md: Y, or else 0.2126 R + 0.7152 G + 0.0722 B (ITU-R BT.709 luma). */
        double v = Y ? Y[i] : 0.2126 * R[i] + 0.7152 * G[i] + 0.0722 * B[i];
        v *= spec->scale;
        if (!isfinite(v) || v < 0.0) {
            int x = (int)(i % (size_t)img.width), y = (int)(i / (size_t)img.width);
            cdl_exr_image_release(&img);
            free(lum);
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s: %s.file: %s: pixel (%d, %d): expected a finite luminance >= 0, found %g",
                                 scene->path, spec->json_path, spec->file, x, y, v);
        }
        lum[i] = (float)v;
    }
    *w = img.width;
    *h = img.height;
    *out = lum;
    cdl_exr_image_release(&img);
    return CDL_OK;
}

/* Find the geometry piece of area luminaire k. */
static size_t find_luminaire_piece(const cdl_scene_geometry *g, size_t k)
{
    size_t n = cdl_scene_geometry_piece_count(g);
    for (size_t i = 0; i < n; ++i) {
        const cdl_geometry_piece *p = cdl_scene_geometry_piece(g, i);
        if (p->is_luminaire && !p->is_body && p->source_index == k) return i;
    }
    return SIZE_MAX;
}

/* Append a light; takes the emitter and the prototype's outline, releasing
 * both if it fails. */
static cdl_status add_light(cdl_scene_lights *L, cdl_emitter *e, const char *kind, const cdl_scene_light *proto,
                            cdl_error *err)
{
    cdl_scene_light light = *proto;
    double cos_min;
    if (cdl_emitter_emission_cone(e, &light.cone_position, &light.cone_axis, &cos_min)) {
        /* The solver culls with cosines computed in double precision, a few
         * ulps off at the cone's edge: widen the cone by 8 ulps of 1 so that
         * rounding never culls a lit point. Without it a beam narrower than
         * about 1e-8 rad, whose cosine rounds to 1, culled even its own axis. */
        double c = fmin(1.0, cos_min) - 8.0 * DBL_EPSILON;
        if (c > -1.0) {
            light.has_cone = 1;
            light.cone_angle = acos(c);
            light.cone_cos = c;
            light.cone_sin = sin(light.cone_angle);
            light.cone_cos2 = c * c;
        }
    }
    cdl_scene_light *nl = realloc(L->lights, (L->count + 1) * sizeof *nl);
    if (!nl) {
        cdl_emitter_release(e);
        free(light.outline);
        free(light.model);
        return cdl_error_out_of_memory(err);
    }
    L->lights = nl;
    cdl_emitter **ne = realloc(L->emitters, (L->count + 1) * sizeof *ne);
    if (!ne) {
        cdl_emitter_release(e);
        free(light.outline);
        free(light.model);
        return cdl_error_out_of_memory(err);
    }
    L->emitters = ne;
    const char **nk = realloc(L->kinds, (L->count + 1) * sizeof *nk);
    if (!nk) {
        cdl_emitter_release(e);
        free(light.outline);
        free(light.model);
        return cdl_error_out_of_memory(err);
    }
    L->kinds = nk;
    L->lights[L->count] = light;
    L->lights[L->count].emitter = e;
    L->emitters[L->count] = e;
    L->kinds[L->count] = kind;
    L->count++;
    return CDL_OK;
}

/* A goniometric luminaire with a flat opening or a luminous solid
 * (cdl_luminous_opening_is_spread): its opening as an extended
 * emitter, everywhere ("always", replacing the point `point`) or within
 * CDL_NEAR_FIELD_DISTANCES opening sizes ("auto", the point beyond: two
 * adjacent lights of the same label, kinds "goniometric" and "goniometric
 * opening", the point first). */
static cdl_status add_near_field(const cdl_scene *scene, const cdl_luminaire_spec *sp, const cdl_goniometric_params *p,
                                 cdl_emitter *point, const cdl_scene_light *point_proto, cdl_scene_lights *L,
                                 cdl_error *err)
{
    cdl_scene_light proto = *point_proto;
    cdl_status st;
    if (sp->near_field == CDL_NEAR_FIELD_AUTO) {
        /* The point model beyond where its error stays below a share of
         * the target (near_field_bound.h): a property of the file, measured
         * once in the luminaire's frame for all its copies (the scale,
         * rotation and position of a copy change no relative error). */
        size_t index = L->photometry_count - 1;
        if (!L->near_bound_known[index]) {
            cdl_goniometric_params own = CDL_GONIOMETRIC_PARAMS_DEFAULT;
            own.photometry = p->photometry;
            st = cdl_near_field_bound_measure(&own, &L->near_bounds[index], err);
            if (st != CDL_OK) {
                cdl_emitter_release(point);
                return fail_at(err, scene, sp->json_path, st);
            }
            L->near_bound_known[index] = 1;
        }
        const cdl_near_field_bound bound = L->near_bounds[index];
        cdl_scene_light far = *point_proto;
        far.near_part = -1;
        far.near_center = sp->position;
        far.near_radius = cdl_near_field_switch_distance(&bound, cdl_solver_settings_target(&scene->settings));
        far.near_model_error = cdl_near_field_bound_error(&bound, far.near_radius);
        st = add_light(L, point, "goniometric", &far, err);
        if (st != CDL_OK) return fail_at(err, scene, sp->json_path, st);
        proto.near_part = 1;
        proto.near_center = sp->position;
        proto.near_radius = far.near_radius;
        proto.near_model_error = far.near_model_error;
    } else {
        cdl_emitter_release(point);
    }
    cdl_emitter *e = NULL;
    st = cdl_emitter_create_goniometric_opening(p, &e, err);
    if (st != CDL_OK) return fail_at(err, scene, sp->json_path, st);
    /* The cubature to 1/50 of the solve's target: its error estimate
     * (which bounds the error generously) then adds at most (1/50)^2 =
     * 0.04 % to a point's variance, and the value stands as exact. */
    cdl_emitter_opening_set_tolerance(e, cdl_solver_settings_target(&scene->settings) / 50.0);
    proto.bounded = 0;
    cdl_shape face;
    cdl_emitter_opening_face(e, &face);
    st = describe_area(&proto, &face, err);
    if (st != CDL_OK) {
        cdl_emitter_release(e);
        free(proto.outline);
        return fail_at(err, scene, sp->json_path, st);
    }
    /* describe_area bounds the lower face of a flat opening, all of it, or a solid's bounding sphere */
    proto.has_closed_form = cdl_emitter_has_exact_illuminance(e);
    proto.costly_exact = !cdl_emitter_opening_is_lambertian(e);
    return add_light(L, e, "goniometric opening", &proto, err);
}

/* A directional emitter with a disk (the sun) is an extended light: what
 * the exact route needs of it. */
static void describe_sun_disk(cdl_scene_light *proto, const cdl_emitter *e)
{
    if (!cdl_emitter_directional_disk(e, &proto->sun_dir, &proto->sun_half_angle)) return;
    proto->is_sun_disk = 1;
    proto->has_closed_form = 1;
}

/* A "cie" or "perez" sky: the sky, then its sun (scene_sky.h), the sky's
 * model in words on both. */
static cdl_status add_daylight(const cdl_scene *scene, const cdl_luminaire_spec *sp, const cdl_scene_light *proto,
                               cdl_scene_lights *L, cdl_error *err)
{
    cdl_scene_sky_emitters built;
    cdl_status st = cdl_scene_sky_build(sp, &built, err);
    if (st != CDL_OK) return fail_at(err, scene, sp->json_path, st);
    cdl_scene_light sky = *proto;
    sky.is_environment = 1;
    sky.sky_varies = 1;
    sky.upper_only = 1;
    sky.up = cdl_vec3_normalize(sp->up);
    sky.has_closed_form = 1;
    sky.costly_exact = 1; /* a quadrature of 0.2 ms: path vertices take a sample instead */
    sky.model = cdl_string_copy(built.description);
    L->has_environment = 1;
    st = add_light(L, built.sky, "environment", &sky, err);
    if (st != CDL_OK || !built.sun) {
        if (st != CDL_OK) cdl_emitter_release(built.sun);
        return st;
    }
    cdl_scene_light sun = *proto;
    size_t used = strlen(sun.label);
    if (used + 7 < sizeof sun.label) memcpy(sun.label + used, " (sun)", 7);
    describe_sun_disk(&sun, built.sun);
    sun.model = cdl_string_copy(built.description);
    return add_light(L, built.sun, "sun", &sun, err);
}

static cdl_status build_luminaire(const cdl_scene *scene, const cdl_scene_geometry *geometry, size_t k,
                                  cdl_scene_lights *L, cdl_error *err)
{
    const cdl_luminaire_spec *sp = &scene->luminaires[k];
    cdl_scene_light proto;
    memset(&proto, 0, sizeof proto);
    cdl_luminaire_spec_label(sp, proto.label, sizeof proto.label);
    proto.owner = UINT32_MAX;
    proto.body = geometry ? cdl_scene_geometry_luminaire_body(geometry, k) : UINT32_MAX;
    proto.has_body = proto.body != UINT32_MAX;
    proto.luminaire = k;
    double mf = sp->maintenance_factor;
    cdl_emitter *e = NULL;
    cdl_status st = CDL_OK;

    switch (sp->kind) {
    case CDL_LUMINAIRE_POINT: {
        cdl_point_params p = {sp->position, cdl_candelas(sp->has_flux ? sp->flux_lm / CDL_FOUR_PI : sp->intensity_cd)};
        p.intensity = cdl_luminous_intensity_scale(p.intensity, mf);
        st = cdl_emitter_create_point(&p, &e, err);
        bounds_add(&proto, sp->position);
        break;
    }
    case CDL_LUMINAIRE_SPOT: {
        cdl_spot_params p;
        memset(&p, 0, sizeof p);
        p.position = sp->position;
        p.direction = sp->direction;
        p.use_exponent = sp->has_exponent;
        p.exponent = sp->exponent;
        p.half_angle_deg = sp->half_angle_deg;
        p.falloff_start_deg = sp->falloff_start_deg;
        p.intensity = cdl_candelas(1.0);
        if (sp->has_flux) {
            /* I0 from the closed-form flux of the same spot at 1 cd. */
            cdl_emitter *unit = NULL;
            st = cdl_emitter_create_spot(&p, &unit, err);
            if (st != CDL_OK) break;
            double per_cd = cdl_emitter_flux(unit).lm;
            cdl_emitter_release(unit);
            if (!(per_cd > 0.0)) {
                st = cdl_error_set(err, CDL_ERR_INPUT, "flux_lm: this spot emits no light at any intensity");
                break;
            }
            p.intensity = cdl_candelas(sp->flux_lm / per_cd);
            if (!isfinite(p.intensity.cd)) {
                st = cdl_error_set(err, CDL_ERR_INPUT,
                                   "flux_lm: expected a flux this beam can carry with a finite intensity (%g lm per "
                                   "cd), found %g lm",
                                   per_cd, sp->flux_lm);
                break;
            }
        } else {
            p.intensity = cdl_candelas(sp->intensity_cd);
        }
        p.intensity = cdl_luminous_intensity_scale(p.intensity, mf);
        st = cdl_emitter_create_spot(&p, &e, err);
        bounds_add(&proto, sp->position);
        break;
    }
    case CDL_LUMINAIRE_GONIOMETRIC: {
        cdl_photometry *ph = NULL;
        if (sp->copy > 0 && k > 0) {
            /* Copies of one entry ("array", "positions") share its file, read once. */
            ph = L->photometries[L->photometry_count - 1];
        } else {
            cdl_photometry_read_options opt = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
            st = cdl_photometry_read_file(sp->file, &opt, &ph, err);
            if (st != CDL_OK) {
                cdl_error_prefix(err, "%s.file: ", sp->json_path);
                cdl_error_prefix(err, "%s: ", scene->path);
                return st;
            }
            L->photometries[L->photometry_count++] = ph;
            const cdl_photometry_metadata *pm = cdl_photometry_get_metadata(ph);
            if (pm->radiometric)
                /* No light without a spectrum or an efficacy: refuse, never guess one. */
                return cdl_error_set(err, CDL_ERR_INPUT,
                                     "%s: %s.file: %s: expected photometric data (candela), found radiant "
                                     "intensity in %s ([%s]): Candela computes lux from luminous quantities, and "
                                     "watts of UV or infrared radiation are no light",
                                     scene->path, sp->json_path, sp->file,
                                     pm->radiometric_scale == 1.0 ? "W/sr" : pm->radiometric_scale == 1e-3 ? "mW/sr"
                                                                                                         : "uW/sr",
                                     pm->units_keyword);
        }
        L->luminaire_photometry[k] = ph;
        cdl_goniometric_params p;
        memset(&p, 0, sizeof p);
        p.position = sp->position;
        memcpy(p.rotation_deg, sp->rotation_deg, sizeof p.rotation_deg);
        p.photometry = ph;
        p.multiplier = sp->multiplier;
        p.maintenance_factor = mf;
        p.flux_lm = sp->has_flux ? sp->flux_lm : 0.0;
        p.apply_output_factor = 1;
        st = cdl_emitter_create_goniometric(&p, &e, err);
        bounds_add(&proto, sp->position);
        int spread = cdl_luminous_opening_is_spread(&cdl_photometry_get_metadata(ph)->opening);
        if (st == CDL_OK && sp->near_field != CDL_NEAR_FIELD_NEVER && spread)
            return add_near_field(scene, sp, &p, e, &proto, L, err);
        /* "always" asked of a file with nothing to spread over: the plan and a warning say so */
        proto.near_field_unspread = sp->near_field == CDL_NEAR_FIELD_ALWAYS;
        break;
    }
    case CDL_LUMINAIRE_AREA: {
        size_t piece = find_luminaire_piece(geometry, k);
        if (piece == SIZE_MAX)
            return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: %s: area luminaire has no geometry", scene->path,
                                 sp->json_path);
        const cdl_geometry_piece *gp = cdl_scene_geometry_piece(geometry, piece);
        cdl_area_params p;
        memset(&p, 0, sizeof p);
        p.shape = gp->shape;
        /* The piece carries the luminance: luminance_cd_m2, or flux_lm as
         * L = Phi / (pi A), times the maintenance factor (scene_geometry.c). */
        p.luminance = cdl_nits(gp->luminance_cd_m2);
        proto.owner = (uint32_t)piece;
        st = describe_area(&proto, &gp->shape, err);
        if (st == CDL_OK) st = cdl_emitter_create_area(&p, &e, err);
        break;
    }
    case CDL_LUMINAIRE_DIRECTIONAL: {
        cdl_directional_params p = {sp->direction, cdl_lux(sp->illuminance_lx * mf), sp->angular_diameter_deg};
        st = cdl_emitter_create_directional(&p, &e, err);
        if (st == CDL_OK) describe_sun_disk(&proto, e);
        break;
    }
    case CDL_LUMINAIRE_ENVIRONMENT: {
        if (sp->sky == CDL_SCENE_SKY_CIE || sp->sky == CDL_SCENE_SKY_PEREZ) return add_daylight(scene, sp, &proto, L, err);
        cdl_environment_params p;
        memset(&p, 0, sizeof p);
        p.up = sp->up;
        p.upper_hemisphere_only = sp->upper_hemisphere_only;
        p.scale = 1.0;
        float *image = NULL;
        if (sp->file) {
            st = read_environment_image(scene, sp, &image, &p.width, &p.height, err);
            if (st != CDL_OK) return st;
            for (size_t i = 0; i < (size_t)p.width * (size_t)p.height; ++i) image[i] = (float)(image[i] * mf);
            p.image = image;
            proto.is_image = 1;
        } else {
            p.luminance = cdl_nits(sp->luminance_cd_m2 * mf);
            p.sky = sp->sky_overcast ? CDL_SKY_CIE_OVERCAST : CDL_SKY_UNIFORM;
            proto.sky_varies = sp->sky_overcast;
        }
        proto.is_environment = 1;
        proto.upper_only = sp->upper_hemisphere_only;
        proto.up = cdl_vec3_normalize(sp->up);
        L->has_environment = 1;
        st = cdl_emitter_create_environment(&p, &e, err);
        /* Uniform and overcast skies and images alike (an image: the exact pixel sum). */
        if (st == CDL_OK) proto.has_closed_form = cdl_emitter_has_exact_illuminance(e);
        free(image);
        break;
    }
    }
    if (st != CDL_OK) {
        free(proto.outline);
        return fail_at(err, scene, sp->json_path, st);
    }
    return add_light(L, e, luminaire_kind_name(sp->kind), &proto, err);
}

static const char *box_face_name(int face)
{
    static const char *names[CDL_BOX_FACES] = {"-x", "+x", "-y", "+y", "-z", "+z"};
    return face >= 0 && face < CDL_BOX_FACES ? names[face] : "";
}

/* The far-field guess of every bounded extended light (scene_lights.h):
 * the intensity a luminaire spread over its opening has as a point (its
 * point model, from its photometric centre), else the emitter's own
 * intensity from the centre of its bounds (an area light's int L cos dA). */
static cdl_status build_guess_maps(const cdl_scene *scene, cdl_scene_lights *L, cdl_error *err)
{
    for (size_t i = 0; i < L->count; ++i) {
        cdl_scene_light *l = &L->lights[i];
        if (!l->bounded || cdl_emitter_is_delta(l->emitter)) continue;
        /* (an opening is always a luminaire's: its entry gives the centre) */
        const cdl_emitter *far = cdl_emitter_far_field(l->emitter);
        l->guess_origin = far ? scene->luminaires[l->luminaire].position : cdl_bounds3_centre(l->bounds);
        cdl_status st =
            cdl_intensity_map_build(far ? far : l->emitter, CDL_INTENSITY_MAP_RESOLUTION, &l->guess_map, err);
        if (st != CDL_OK) return st;
    }
    return CDL_OK;
}

cdl_status cdl_scene_lights_build(const cdl_scene *scene, const cdl_scene_geometry *geometry, cdl_scene_lights *out,
                                  cdl_error *err)
{
    memset(out, 0, sizeof *out);
    out->photometries = calloc(scene->luminaire_count + 1, sizeof *out->photometries);
    out->luminaire_photometry = calloc(scene->luminaire_count + 1, sizeof *out->luminaire_photometry);
    out->near_bounds = calloc(scene->luminaire_count + 1, sizeof *out->near_bounds);
    out->near_bound_known = calloc(scene->luminaire_count + 1, sizeof *out->near_bound_known);
    if (!out->photometries || !out->luminaire_photometry || !out->near_bounds || !out->near_bound_known) {
        cdl_scene_lights_release(out);
        return cdl_error_out_of_memory(err);
    }
    for (size_t k = 0; k < scene->luminaire_count; ++k) {
        cdl_status st = build_luminaire(scene, geometry, k, out, err);
        if (st != CDL_OK) {
            cdl_scene_lights_release(out);
            return st;
        }
    }
    /* Emitting surfaces: one area emitter per emitting piece. */
    size_t n = geometry ? cdl_scene_geometry_piece_count(geometry) : 0;
    for (size_t i = 0; i < n; ++i) {
        const cdl_geometry_piece *gp = cdl_scene_geometry_piece(geometry, i);
        if (gp->is_luminaire || !(gp->luminance_cd_m2 > 0.0)) continue;
        const cdl_surface_spec *ss = &scene->surfaces[gp->source_index];
        cdl_scene_light proto;
        memset(&proto, 0, sizeof proto);
        proto.luminaire = SIZE_MAX;
        if (gp->box_face >= 0 && ss->name)
            snprintf(proto.label, sizeof proto.label, "%s (%s, face %s)", ss->json_path, ss->name,
                     box_face_name(gp->box_face));
        else if (gp->box_face >= 0)
            snprintf(proto.label, sizeof proto.label, "%s (face %s)", ss->json_path, box_face_name(gp->box_face));
        else if (ss->name)
            snprintf(proto.label, sizeof proto.label, "%s (%s)", ss->json_path, ss->name);
        else
            snprintf(proto.label, sizeof proto.label, "%s", ss->json_path);
        proto.owner = (uint32_t)i;
        cdl_area_params p;
        memset(&p, 0, sizeof p);
        p.shape = gp->shape;
        p.luminance = cdl_nits(gp->luminance_cd_m2);
        cdl_emitter *e = NULL;
        cdl_status st = describe_area(&proto, &gp->shape, err);
        if (st == CDL_OK) st = cdl_emitter_create_area(&p, &e, err);
        if (st == CDL_OK)
            st = add_light(out, e, "emitting surface", &proto, err); /* owns the outline, also on failure */
        else
            free(proto.outline);
        if (st != CDL_OK) {
            fail_at(err, scene, ss->json_path, st);
            cdl_scene_lights_release(out);
            return st;
        }
    }
    cdl_status st = build_guess_maps(scene, out, err);
    if (st != CDL_OK) cdl_scene_lights_release(out);
    return st;
}

void cdl_scene_lights_release(cdl_scene_lights *L)
{
    if (!L) return;
    for (size_t i = 0; i < L->count; ++i) {
        cdl_emitter_release(L->emitters[i]);
        free(L->lights[i].outline);
        free(L->lights[i].model);
        cdl_intensity_map_release(L->lights[i].guess_map);
    }
    for (size_t i = 0; i < L->photometry_count; ++i) cdl_photometry_release(L->photometries[i]);
    free(L->lights);
    free(L->emitters);
    free(L->kinds);
    free(L->photometries);
    free(L->luminaire_photometry);
    free(L->near_bounds);
    free(L->near_bound_known);
    memset(L, 0, sizeof *L);
}
