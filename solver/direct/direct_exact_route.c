/* direct_exact_route.c - a partly hidden area emitter or uniform sky, exact
 * when few planar occluders are in the way.
 *
 * A Lambertian polygon of luminance L seen past occluders gives
 *     E = L Omega_p(visible part),
 * the visible part being the polygon minus the occluders' central
 * projections from the point onto its plane (geometry/visible_polygon.h).
 * A uniform sky is the same on the five faces of a unit cube over the
 * point's tangent plane (top and four half sides): every direction of the
 * hemisphere crosses exactly one face, so the visible sky is the union of
 * the faces' visible parts, each a polygon whose projected solid angle is
 * Lambert's closed form; an upper-hemisphere sky first loses the faces'
 * parts below the horizon of its `up`. (The configuration factor of the
 * visible polygon, as CIE 171:2006's daylight test cases compute it.)
 *
 * A flat goniometric opening (a luminaire spread over its luminous
 * opening, near field) is the same visible part of its plane, but its
 * luminance I(w) / (A |cos theta_o|) varies with the direction w from each
 * element: the part (the opening's bounding rectangle less the occluders'
 * projections) goes to the opening's own cubature (cdl_emitter_opening_
 * partial_illuminance), which clips it to the opening and integrates E to
 * 1e-5, as it does the unoccluded E.
 *
 * The occluders are the triangles of the occluder index that meet the
 * region between the point and the light (the pyramid to the emitter, or the
 * half-space above the tangent plane). The route is refused, and the light
 * sampled, when more than CDL_EXACT_ROUTE_MAX_OCCLUDERS are there, when a
 * sphere or a disk (curved: the index holds a disk as a circumscribed
 * polygon, not the disk) may be among them, when the emitter is not one
 * plane of polygons (disk, sphere, non-planar mesh), or when the visible
 * part falls into more pieces than geometry/visible_polygon.h holds.
 */
#include "solver/direct/direct_internal.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "radiometry/constants.h"
#include "radiometry/frame.h"
#include "solver/direct/sky_region.h"
#include "solver/geometry/visible_polygon.h"

/* Occluder parts closer to the point than this fraction of its ray epsilon
 * are ignored: they pass through the point (it lies on them). */
#define NEAR_FRACTION 1e-6

#define STRINGIFY_(x) #x
#define STRINGIFY(x) STRINGIFY_(x)

/* Subtract every occluder from a face; 0 if the face overflowed its
 * limits (then released). */
static int face_subtract(cdl_visible_face *face, const cdl_occluder_triangle *occ, size_t count)
{
    for (size_t i = 0; i < count && !face->overflow; ++i) cdl_visible_face_subtract_triangle(face, occ[i].v);
    if (face->overflow) cdl_visible_face_release(face);
    return !face->overflow;
}

/* Subtract every occluder from a face and add the visible part's Omega_p;
 * returns 0 if the face overflowed its limits. */
static int face_visible(cdl_visible_face *face, const cdl_occluder_triangle *occ, size_t count, cdl_vec3 n,
                        double *omega)
{
    if (!face_subtract(face, occ, count)) return 0;
    *omega += cdl_visible_face_projected_solid_angle(face, n);
    cdl_visible_face_release(face);
    return 1;
}

/* The sky visible past the occluders: the five faces of the unit cube over
 * p's tangent plane, each left with its visible pieces (the caller releases
 * them); 0 (all released) when a face overflowed. */
static int sky_faces(const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n, double near,
                     const cdl_occluder_triangle *occ, size_t count, cdl_visible_face faces[5])
{
    cdl_frame f = cdl_frame_from_normal(n);
    const cdl_vec3 sides[4] = {f.s, f.t, cdl_vec3_neg(f.s), cdl_vec3_neg(f.t)};
    for (int k = 0; k < 5; ++k) {
        cdl_visible_face *face = &faces[k];
        cdl_vec3 corner[4];
        if (k == 4) {
            /* the top: the square p + n + [-1, 1] s + [-1, 1] t */
            cdl_vec3 c = cdl_vec3_add(p, n);
            corner[0] = cdl_vec3_sub(cdl_vec3_sub(c, f.s), f.t);
            corner[1] = cdl_vec3_sub(cdl_vec3_add(c, f.s), f.t);
            corner[2] = cdl_vec3_add(cdl_vec3_add(c, f.s), f.t);
            corner[3] = cdl_vec3_add(cdl_vec3_sub(c, f.s), f.t);
            cdl_visible_face_init(face, p, cdl_vec3_neg(n), c, 0, near);
        } else {
            /* a half side: p + a + [-1, 1] b + [0, 1] n, b the next axis round */
            cdl_vec3 a = sides[k], b = sides[(k + 1) % 4];
            cdl_vec3 c = cdl_vec3_add(p, a);
            corner[0] = cdl_vec3_sub(c, b);
            corner[1] = cdl_vec3_add(c, b);
            corner[2] = cdl_vec3_add(corner[1], n);
            corner[3] = cdl_vec3_add(corner[0], n);
            cdl_visible_face_init(face, p, cdl_vec3_neg(a), c, 0, near);
        }
        cdl_visible_face_add_polygon(face, corner, 4);
        if (light->upper_only) {
            /* up . w >= 0 with w = -height toward + x e1 + y e2 */
            cdl_vec3 up = light->up;
            cdl_visible_face_clip(face, cdl_vec3_dot(up, face->e1), cdl_vec3_dot(up, face->e2),
                                  -face->height * cdl_vec3_dot(up, face->toward));
        }
        if (!face_subtract(face, occ, count)) {
            for (int j = 0; j < k; ++j) cdl_visible_face_release(&faces[j]);
            return 0;
        }
    }
    return 1;
}

static void faces_release(cdl_visible_face faces[5])
{
    for (int k = 0; k < 5; ++k) cdl_visible_face_release(&faces[k]);
}

/* A sky whose luminance over the visible part spans more than this many
 * times its typical value (the larger of L_ref and E_0 / pi, the mean over
 * the hemisphere) is sampled the other way, with shadow rays. Why: the
 * visible part is sampled uniformly in projected solid angle, and the
 * spread stands for what a missed feature could change a sample by
 * (direct_extended.c), so a small sun of 1e6 cd/m^2 in a 4000 cd/m^2 sky
 * holds every point to the cap of samples: on bench_environment's well
 * (a 2 x 2 pixel sun, 250 times the sky) stated sigma / target averaged
 * 3.9 that way, 1.45 with shadow rays and the sampler that draws pixels by
 * luminance. A smooth sky, or the cap sky's edge (spread 2 E_0 / pi),
 * stays well within 16. (An image's sun is now taken out first, below:
 * the spread is that of the rest, and that well's points meet 0.1 % at
 * 0.98 of the target on average, no rays.) */
#define SKY_SPREAD_MAX 16.0

/* An image sky's pixels brighter than SKY_PEAK_CUT times its typical
 * luminance (E_0 / pi, the mean over the receiver's hemisphere) are summed
 * exactly over the visible part (sky_region.h: a sun is exact, the rest
 * sampled as a sky without it), up to SKY_PEAK_PIXELS of them a point;
 * a sky brighter than that in more pixels (a wide bright aureole) keeps
 * the shadow-ray sampler. Why 8: the rest's spread, at most 8 E_0 / pi,
 * stays within SKY_SPREAD_MAX with room for a dark part; a lower cut puts
 * more of a smooth sky's bright horizon or aureole into the exact sum for
 * little gain. Each bright pixel costs two meridian clips and four
 * closed-form arcs per edge of the visible piece it lies in. */
#define SKY_PEAK_CUT 8.0
#define SKY_PEAK_PIXELS 1024

/* A sky past the occluders: a uniform one exact, E = L Omega_p of the
 * visible faces; an image or overcast sky as the region to integrate over
 * (sky_region.h), an image's sun (its pixels above the cut) summed exactly
 * over it, exact too where the bounds of the rest over the region meet
 * (one luminance there). *region is set where the rest is sampled. */
static cdl_direct_route sky_route(const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n, double near,
                                  const cdl_occluder_triangle *occ, size_t count, double unoccluded, double *E,
                                  cdl_sky_region **region)
{
    cdl_visible_face faces[5];
    if (!sky_faces(light, p, n, near, occ, count, faces)) return CDL_ROUTE_TOO_COMPLEX;
    if (!light->is_image && !light->sky_varies) {
        double omega = 0.0;
        for (int k = 0; k < 5; ++k) omega += cdl_visible_face_projected_solid_angle(&faces[k], n);
        faces_release(faces);
        /* uniform: the luminance of any direction above the horizon */
        double L = cdl_emitter_radiance(light->emitter, p, n, light->upper_only ? light->up : n, NULL).cd_m2;
        /* E = L Omega_p of the visible part (Lambert); never below 0 by rounding */
        *E = omega > 0.0 ? L * omega : 0.0;
        return CDL_ROUTE_VISIBLE_POLYGON;
    }
    cdl_sky_region *r = NULL;
    double cut = light->is_image ? SKY_PEAK_CUT * unoccluded / CDL_PI : INFINITY;
    cdl_status st = cdl_sky_region_create(faces, 5, p, n, light->emitter, cut, SKY_PEAK_PIXELS, &r, NULL);
    faces_release(faces);
    if (st != CDL_OK) return CDL_ROUTE_TOO_COMPLEX;
    if (cdl_sky_region_too_bright(r)) {
        cdl_sky_region_release(r);
        return CDL_ROUTE_SKY_PEAK;
    }
    double lo, hi, omega = cdl_sky_region_projected_solid_angle(r);
    int sun = cdl_sky_region_bright_solid_angle(r) > 0.0;
    cdl_sky_region_luminance_bounds(r, &lo, &hi);
    if (!(omega > 0.0) || lo == hi) {
        /* one luminance over R but for the bright pixels, summed exactly */
        *E = omega > 0.0 ? fmax(0.0, cdl_sky_region_exact_part(r)) : 0.0;
        cdl_sky_region_release(r);
        return sun ? CDL_ROUTE_SKY_SUN : CDL_ROUTE_VISIBLE_POLYGON;
    }
    if (hi - lo > SKY_SPREAD_MAX * fmax(cdl_sky_region_reference_luminance(r), unoccluded / CDL_PI)) {
        cdl_sky_region_release(r);
        return CDL_ROUTE_SKY_PEAK;
    }
    *region = r;
    return sun ? CDL_ROUTE_SKY_SUN : CDL_ROUTE_SKY_REGION;
}

/* The sun's disk as SUN_SECTORS convex sectors of SUN_SECTOR_EDGES edges
 * along its rim each (the centre and 21 rim points: 22 vertices, leaving
 * room under CDL_VISIBLE_MAX_VERTICES for the corners occluders' edges
 * cut into a piece), a 240-gon of the disk's area. The visible fraction of the polygon stands
 * for the disk's: an occluder's edge across the disk moves by at most the
 * polygon's distance from the circle, r (1 - cos(pi / 240)) / 2 = 4.3e-5 r
 * (the equal-area polygon lies within that of its circle), so the
 * fraction, and E in the penumbra, is within about 1e-4 of the round
 * disk's. */
#define SUN_SECTORS 12
#define SUN_SECTOR_EDGES 20

/* The sun past the occluders: E_0 times the visible fraction of its disk's
 * projected solid angle. The disk lies on the plane at unit distance
 * towards the sun, radius tan(alpha); nothing between p and infinity may
 * hide it (an unbounded face, as the sky's). */
static cdl_direct_route sun_route(const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n, double near,
                                  const cdl_occluder_triangle *occ, size_t count, double unoccluded, double *E)
{
    cdl_frame f = cdl_frame_from_normal(light->sun_dir);
    cdl_vec3 c = cdl_vec3_add(p, light->sun_dir);
    const int edges = SUN_SECTORS * SUN_SECTOR_EDGES;
    /* the equal-area polygon: (N / 2) R^2 sin(2 pi / N) = pi r^2 */
    double r = tan(light->sun_half_angle);
    double R = r * sqrt(CDL_TWO_PI / (edges * sin(CDL_TWO_PI / edges)));
    cdl_visible_face face;
    cdl_visible_face_init(&face, p, cdl_vec3_neg(light->sun_dir), c, 0, near);
    for (int k = 0; k < SUN_SECTORS; ++k) {
        cdl_vec3 pts[SUN_SECTOR_EDGES + 2];
        pts[0] = c;
        for (int j = 0; j <= SUN_SECTOR_EDGES; ++j) {
            double a = CDL_TWO_PI * (k * SUN_SECTOR_EDGES + j) / edges;
            pts[j + 1] = cdl_vec3_add(c, cdl_vec3_add(cdl_vec3_scale(f.s, R * cos(a)), cdl_vec3_scale(f.t, R * sin(a))));
        }
        cdl_visible_face_add_polygon(&face, pts, SUN_SECTOR_EDGES + 2);
    }
    double whole = cdl_visible_face_projected_solid_angle(&face, n);
    double visible = 0.0;
    if (!face_visible(&face, occ, count, n, &visible)) return CDL_ROUTE_TOO_COMPLEX;
    *E = whole > 0.0 && visible > 0.0 ? unoccluded * fmin(1.0, visible / whole) : 0.0;
    return CDL_ROUTE_VISIBLE_POLYGON;
}

/* The corners of triangle t of a triangle-set shape. */
static void shape_triangle(const cdl_shape *s, size_t t, cdl_vec3 *c)
{
    for (int k = 0; k < 3; ++k) {
        const double *v = &s->vertices[3 * (size_t)s->triangles[3 * t + (size_t)k]];
        c[k] = cdl_vec3_make(v[0], v[1], v[2]);
    }
}

/* Omega_p of the emitter's polygons visible past the occluders; 0 with
 * *route set when the emitter is not planar polygons. */
static int emitter_visible(const cdl_geometry_piece *piece, const cdl_scene_light *light, cdl_vec3 p, cdl_vec3 n,
                           double near, const cdl_occluder_triangle *occ, size_t count, double *omega,
                           cdl_direct_route *route)
{
    const cdl_shape *s = &piece->shape;
    *omega = 0.0;
    cdl_visible_face face;
    if (s->kind == CDL_SHAPE_RECT) {
        cdl_vec3 m = cdl_vec3_normalize(cdl_vec3_cross(s->u, s->v));
        if (!(cdl_vec3_dot(m, cdl_vec3_sub(p, s->origin)) > 0.0)) return 1; /* behind: dark */
        cdl_vec3 c[4] = {s->origin, cdl_vec3_add(s->origin, s->u), cdl_vec3_add(cdl_vec3_add(s->origin, s->u), s->v),
                         cdl_vec3_add(s->origin, s->v)};
        cdl_visible_face_init(&face, p, m, s->origin, 1, near);
        cdl_visible_face_add_polygon(&face, c, 4);
    } else if (s->kind == CDL_SHAPE_TRIANGLES && light->outline_count > 0) {
        /* One plane (the light's outline exists only for planar meshes):
         * its normal from Newell's sum, each triangle facing p a piece. */
        cdl_vec3 m = cdl_vec3_make(0, 0, 0), o = light->outline[0];
        for (size_t t = 0; t < s->triangle_count; ++t) {
            cdl_vec3 c[3];
            shape_triangle(s, t, c);
            m = cdl_vec3_add(m, cdl_vec3_cross(cdl_vec3_sub(c[1], c[0]), cdl_vec3_sub(c[2], c[0])));
        }
        m = cdl_vec3_normalize(m);
        double h = cdl_vec3_dot(m, cdl_vec3_sub(p, o));
        if (h == 0.0) return 1; /* in the plane: sees nothing of it */
        if (h < 0.0) m = cdl_vec3_neg(m);
        cdl_visible_face_init(&face, p, m, o, 1, near);
        for (size_t t = 0; t < s->triangle_count; ++t) {
            cdl_vec3 c[3];
            shape_triangle(s, t, c);
            cdl_vec3 front = cdl_vec3_cross(cdl_vec3_sub(c[1], c[0]), cdl_vec3_sub(c[2], c[0]));
            if (cdl_vec3_dot(front, cdl_vec3_sub(p, c[0])) > 0.0) cdl_visible_face_add_polygon(&face, c, 3);
        }
    } else {
        *route = CDL_ROUTE_CURVED_EMITTER;
        return 0;
    }
    if (!face_visible(&face, occ, count, n, omega)) {
        *route = CDL_ROUTE_TOO_COMPLEX;
        return 0;
    }
    return 1;
}

/* A flat goniometric opening past the occluders: the visible part of its
 * bounding rectangle in its plane, handed to the opening's cubature
 * (cdl_emitter_opening_partial_illuminance: clipped to the opening there,
 * its luminance varying over it with the direction of each element). */
static cdl_direct_route opening_visible(const cdl_scene_light *light, const cdl_vec3 corner[4], cdl_vec3 p,
                                        cdl_vec3 n, double near, const cdl_occluder_triangle *occ, size_t count,
                                        double *E)
{
    cdl_vec3 m = cdl_vec3_normalize(cdl_vec3_cross(cdl_vec3_sub(corner[1], corner[0]), cdl_vec3_sub(corner[3], corner[0])));
    double h = cdl_vec3_dot(m, cdl_vec3_sub(p, corner[0]));
    if (!(h != 0.0)) return CDL_ROUTE_VISIBLE_POLYGON; /* in its plane: sees no area of it */
    cdl_visible_face face;
    cdl_visible_face_init(&face, p, h > 0.0 ? m : cdl_vec3_neg(m), corner[0], 1, near);
    cdl_visible_face_add_polygon(&face, corner, 4);
    if (!face_subtract(&face, occ, count)) return CDL_ROUTE_TOO_COMPLEX;
    size_t total = 0;
    for (size_t k = 0; k < face.count; ++k) total += (size_t)face.pieces[k].count;
    cdl_vec3 *points = malloc((total ? total : 1) * sizeof *points);
    int *counts = malloc((face.count ? face.count : 1) * sizeof *counts);
    if (!points || !counts) {
        free(points);
        free(counts);
        cdl_visible_face_release(&face);
        return CDL_ROUTE_TOO_COMPLEX;
    }
    /* the plane's 2-D coordinates stand for foot + x e1 + y e2 */
    cdl_vec3 foot = cdl_vec3_madd(face.apex, -face.height, face.toward);
    size_t at = 0;
    for (size_t k = 0; k < face.count; ++k) {
        const cdl_visible_piece *piece = &face.pieces[k];
        counts[k] = piece->count;
        for (int i = 0; i < piece->count; ++i)
            points[at++] = cdl_vec3_add(foot, cdl_vec3_add(cdl_vec3_scale(face.e1, piece->v[i][0]),
                                                           cdl_vec3_scale(face.e2, piece->v[i][1])));
    }
    cdl_illuminance visible;
    cdl_status st = cdl_emitter_opening_partial_illuminance(light->emitter, p, n, points, counts, face.count, &visible,
                                                            NULL);
    free(points);
    free(counts);
    cdl_visible_face_release(&face);
    if (st != CDL_OK) return CDL_ROUTE_TOO_COMPLEX;
    *E = visible.lx > 0.0 ? visible.lx : 0.0;
    return CDL_ROUTE_VISIBLE_POLYGON;
}

/* The exact route for one light at p, or why not. */
static cdl_direct_route exact_route(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_vec3 p,
                                    cdl_vec3 n, double unoccluded, double *E, uint32_t *occluders,
                                    cdl_sky_region **sky)
{
    *E = 0.0;
    *occluders = 0;
    if (ctx->no_exact_route || !ctx->geometry || !ctx->occluders) return CDL_ROUTE_DISABLED;
    const cdl_geometry_piece *piece = NULL;
    cdl_vec3 opening[4];
    int is_opening = !light->is_environment && light->owner == UINT32_MAX &&
                     cdl_emitter_opening_bounding_rectangle(light->emitter, opening);
    if (!light->is_environment && !is_opening && !light->is_sun_disk) {
        if (light->owner == UINT32_MAX || light->outline_is_sphere) return CDL_ROUTE_CURVED_EMITTER;
        piece = cdl_scene_geometry_piece(ctx->geometry, light->owner);
        if (piece->shape.kind != CDL_SHAPE_RECT &&
            !(piece->shape.kind == CDL_SHAPE_TRIANGLES && light->outline_count > 0))
            return CDL_ROUTE_CURVED_EMITTER;
    }
    cdl_convex_region region;
    double tol;
    if (!cdl_direct_light_region(ctx, light, p, n, &region, &tol)) return CDL_ROUTE_CURVED_EMITTER;
    cdl_occluder_triangle occ[CDL_EXACT_ROUTE_MAX_OCCLUDERS];
    size_t count = 0;
    cdl_occluder_list_status ls =
        cdl_occluder_index_list(ctx->occluders, &region, tol, cdl_scene_light_own_piece(light), occ,
                                CDL_EXACT_ROUTE_MAX_OCCLUDERS, &count);
    if (ls == CDL_OCCLUDERS_SPHERE) return CDL_ROUTE_CURVED_OCCLUDER;
    if (ls == CDL_OCCLUDERS_TOO_MANY) return CDL_ROUTE_TOO_MANY;
    for (size_t i = 0; i < count; ++i)
        if (cdl_geometry_piece_is_curved(cdl_scene_geometry_piece(ctx->geometry, occ[i].owner)))
            return CDL_ROUTE_CURVED_OCCLUDER;
    /* a pane passes part of the light, by angle: no polygon is exact */
    for (size_t i = 0; i < count; ++i)
        if (cdl_scene_geometry_piece(ctx->geometry, occ[i].owner)->transmittance > 0.0) return CDL_ROUTE_GLASS;
    *occluders = (uint32_t)count;
    double near = NEAR_FRACTION * cdl_ray_offsets_epsilon(&ctx->offsets, p);
    if (light->is_environment) return sky_route(light, p, n, near, occ, count, unoccluded, E, sky);
    if (light->is_sun_disk) return sun_route(light, p, n, near, occ, count, unoccluded, E);
    if (is_opening) return opening_visible(light, opening, p, n, near, occ, count, E);
    double omega = 0.0;
    cdl_direct_route route = CDL_ROUTE_VISIBLE_POLYGON;
    if (!emitter_visible(piece, light, p, n, near, occ, count, &omega, &route)) return route;
    /* E = L Omega_p of the visible part (Lambert); never below 0 by rounding */
    *E = omega > 0.0 ? piece->luminance_cd_m2 * omega : 0.0;
    return CDL_ROUTE_VISIBLE_POLYGON;
}

/* The visible sky's pieces; glass_clear: panes are left out of the
 * occluders (*glass_seen says whether there were any). */
static cdl_direct_route visible_sky(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_sky_piece_fn piece,
                                    void *user, int glass_clear, int *glass_seen)
{
    *glass_seen = 0;
    if (!ctx->geometry || !ctx->occluders) return CDL_ROUTE_FULL_VIEW;
    /* a sky of every direction: its region is the half-space above p's plane */
    cdl_scene_light sky;
    memset(&sky, 0, sizeof sky);
    sky.is_environment = 1;
    sky.owner = UINT32_MAX;
    cdl_convex_region region;
    double tol;
    cdl_direct_light_region(ctx, &sky, p, n, &region, &tol);
    cdl_occluder_triangle occ[CDL_EXACT_ROUTE_MAX_OCCLUDERS];
    size_t count = 0;
    cdl_occluder_list_status ls =
        cdl_occluder_index_list(ctx->occluders, &region, tol, UINT32_MAX, occ, CDL_EXACT_ROUTE_MAX_OCCLUDERS, &count);
    if (ls == CDL_OCCLUDERS_SPHERE) return CDL_ROUTE_CURVED_OCCLUDER;
    if (ls == CDL_OCCLUDERS_TOO_MANY) return CDL_ROUTE_TOO_MANY;
    size_t kept = 0;
    for (size_t i = 0; i < count; ++i) {
        const cdl_geometry_piece *g = cdl_scene_geometry_piece(ctx->geometry, occ[i].owner);
        if (cdl_geometry_piece_is_curved(g)) return CDL_ROUTE_CURVED_OCCLUDER;
        if (g->transmittance > 0.0) {
            if (!glass_clear) return CDL_ROUTE_GLASS;
            *glass_seen = 1;
            continue;
        }
        occ[kept++] = occ[i];
    }
    count = kept;
    /* nothing in the way (but panes, whose pieces the caller weighs: handed over) */
    if (count == 0 && !*glass_seen) return CDL_ROUTE_FULL_VIEW;
    double near = NEAR_FRACTION * cdl_ray_offsets_epsilon(&ctx->offsets, p);
    cdl_visible_face faces[5];
    if (!sky_faces(&sky, p, n, near, occ, count, faces)) return CDL_ROUTE_TOO_COMPLEX;
    for (int k = 0; k < 5; ++k) {
        const cdl_visible_face *f = &faces[k];
        /* a piece's point (x, y) is foot + x e1 + y e2, seen from the apex
         * along -height toward + x e1 + y e2 */
        for (size_t i = 0; i < f->count; ++i) {
            const cdl_visible_piece *pc = &f->pieces[i];
            cdl_vec3 dirs[CDL_VISIBLE_MAX_VERTICES];
            for (int v = 0; v < pc->count; ++v) {
                cdl_vec3 d = cdl_vec3_scale(f->toward, -f->height);
                d = cdl_vec3_madd(d, pc->v[v][0], f->e1);
                dirs[v] = cdl_vec3_normalize(cdl_vec3_madd(d, pc->v[v][1], f->e2));
            }
            if (pc->count >= 3) piece(user, dirs, pc->count);
        }
    }
    faces_release(faces);
    return CDL_ROUTE_VISIBLE_POLYGON;
}

cdl_direct_route cdl_direct_visible_sky(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n, cdl_sky_piece_fn piece,
                                        void *user)
{
    int glass = 0;
    return visible_sky(ctx, p, n, piece, user, 0, &glass);
}

cdl_direct_route cdl_direct_visible_sky_through_glass(const cdl_direct_context *ctx, cdl_vec3 p, cdl_vec3 n,
                                                      cdl_sky_piece_fn piece, void *user, int *through_glass)
{
    return visible_sky(ctx, p, n, piece, user, 1, through_glass);
}

int cdl_direct_exact_term(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_light_strategy st,
                          cdl_vec3 p, cdl_vec3 n, double unoccluded, double *E, cdl_sky_region **region,
                          cdl_direct_sample_stats *stats)
{
    *region = NULL;
    cdl_direct_route_tally *tally = stats->routes ? &stats->routes[light - ctx->lights] : NULL;
    if (st == CDL_STRATEGY_EXTENDED_TESTED && cdl_direct_light_fully_visible(ctx, light, p, n)) {
        if (tally) tally->points[CDL_ROUTE_FULL_VIEW]++;
        return 0; /* the caller's closed form stands */
    }
    uint32_t occluders = 0;
    cdl_direct_route route = exact_route(ctx, light, p, n, unoccluded, E, &occluders, region);
    if (tally) {
        tally->points[route]++;
        if ((route == CDL_ROUTE_VISIBLE_POLYGON || route == CDL_ROUTE_SKY_REGION || route == CDL_ROUTE_SKY_SUN) &&
            occluders > tally->most_occluders)
            tally->most_occluders = occluders;
    }
    if (route == CDL_ROUTE_VISIBLE_POLYGON) return 1;
    if (route == CDL_ROUTE_SKY_REGION || route == CDL_ROUTE_SKY_SUN) return *region ? 2 : 1;
    return -1;
}

int cdl_direct_light_seen(const cdl_direct_context *ctx, const cdl_scene_light *light, cdl_light_strategy strategy,
                          cdl_vec3 p, cdl_vec3 n)
{
    cdl_illuminance E0;
    if (cdl_emitter_exact_illuminance(light->emitter, p, n, &E0, NULL) != CDL_OK || !(E0.lx > 0.0)) return 0;
    if (strategy == CDL_STRATEGY_EXTENDED_EXACT) return 1;
    if (strategy != CDL_STRATEGY_EXTENDED_TESTED) return -1;
    cdl_direct_sample_stats stats = {0};
    double E = 0.0;
    cdl_sky_region *region = NULL;
    int route = cdl_direct_exact_term(ctx, light, strategy, p, n, E0.lx, &E, &region, &stats);
    if (route == 2) {
        int seen = cdl_sky_region_projected_solid_angle(region) > 0.0;
        cdl_sky_region_release(region);
        return seen;
    }
    if (route == 0) return 1;
    if (route == 1) return E > 0.0;
    return -1;
}

void cdl_direct_stats_add(cdl_direct_sample_stats *a, const cdl_direct_sample_stats *b, size_t light_count)
{
    a->rays += b->rays;
    a->exact_evaluations += b->exact_evaluations;
    a->sampled_evaluations += b->sampled_evaluations;
    if (!a->routes || !b->routes) return;
    for (size_t l = 0; l < light_count; ++l) {
        for (int r = 0; r < CDL_ROUTE_COUNT; ++r) a->routes[l].points[r] += b->routes[l].points[r];
        a->routes[l].capped += b->routes[l].capped;
        if (b->routes[l].most_occluders > a->routes[l].most_occluders)
            a->routes[l].most_occluders = b->routes[l].most_occluders;
    }
}

cdl_status cdl_direct_stats_share(cdl_rank_group *group, cdl_direct_sample_stats *s, size_t light_count,
                                  cdl_error *err)
{
    if (cdl_rank_group_count(group) == 1) return CDL_OK;
    /* Counts add up; the most occluders of any point is a maximum. */
    size_t per = CDL_ROUTE_COUNT + 1, n = 3 + (s->routes ? light_count * per : 0);
    uint64_t *sum = malloc(n * sizeof *sum), *most = malloc((light_count + 1) * sizeof *most);
    cdl_status st = sum && most ? CDL_OK : cdl_error_out_of_memory(err);
    if (st == CDL_OK) {
        sum[0] = s->rays;
        sum[1] = s->exact_evaluations;
        sum[2] = s->sampled_evaluations;
        for (size_t l = 0; s->routes && l < light_count; ++l) {
            for (int r = 0; r < CDL_ROUTE_COUNT; ++r) sum[3 + l * per + (size_t)r] = s->routes[l].points[r];
            sum[3 + l * per + CDL_ROUTE_COUNT] = s->routes[l].capped;
            most[l] = s->routes[l].most_occluders;
        }
        st = cdl_rank_sum_u64(group, sum, n, err);
    }
    if (st == CDL_OK && s->routes) st = cdl_rank_max_u64(group, most, light_count, err);
    if (st == CDL_OK) {
        s->rays = sum[0];
        s->exact_evaluations = sum[1];
        s->sampled_evaluations = sum[2];
        for (size_t l = 0; s->routes && l < light_count; ++l) {
            for (int r = 0; r < CDL_ROUTE_COUNT; ++r) s->routes[l].points[r] = sum[3 + l * per + (size_t)r];
            s->routes[l].capped = sum[3 + l * per + CDL_ROUTE_COUNT];
            s->routes[l].most_occluders = (uint32_t)most[l];
        }
    }
    free(sum);
    free(most);
    return st;
}

void cdl_direct_route_describe(const cdl_direct_route_tally *t, char *out, size_t size)
{
    static const char *why[CDL_ROUTE_COUNT] = {
        [CDL_ROUTE_TOO_MANY] = "more than " STRINGIFY(CDL_EXACT_ROUTE_MAX_OCCLUDERS) " occluders",
        [CDL_ROUTE_CURVED_OCCLUDER] = "curved occluder (sphere or disk)",
        [CDL_ROUTE_CURVED_EMITTER] = "curved or non-planar emitter",
        [CDL_ROUTE_TOO_COMPLEX] = "visible part in too many pieces",
        [CDL_ROUTE_SKY_PEAK] = "the sky over the visible part far brighter in more than " STRINGIFY(
            SKY_PEAK_PIXELS) " pixels (a sun's wide aureole)",
        [CDL_ROUTE_DISABLED] = "exact route turned off",
        [CDL_ROUTE_GLASS] = "seen through glass (its transmittance varies with the angle of incidence: shadow rays "
                            "carry it)",
    };
    size_t used = 0;
    out[0] = '\0';
#define APPEND(...)                                                                   \
    do {                                                                              \
        if (used < size) {                                                            \
            int w = snprintf(out + used, size - used, __VA_ARGS__);                   \
            if (w > 0) used += (size_t)w;                                             \
        }                                                                             \
    } while (0)
    const char *sep = "";
    if (t->points[CDL_ROUTE_FULL_VIEW]) {
        APPEND("closed form in full view at %" PRIu64 " points", t->points[CDL_ROUTE_FULL_VIEW]);
        sep = "; ";
    }
    if (t->points[CDL_ROUTE_VISIBLE_POLYGON]) {
        APPEND("%sexact: visible polygon past up to %" PRIu32 " occluders at %" PRIu64 " points", sep,
               t->most_occluders, t->points[CDL_ROUTE_VISIBLE_POLYGON]);
        sep = "; ";
    }
    if (t->points[CDL_ROUTE_SKY_REGION]) {
        APPEND("%ssampled within the visible sky (no shadow rays: the sky's luminance varies over it) past up to "
               "%" PRIu32 " occluders at %" PRIu64 " points",
               sep, t->most_occluders, t->points[CDL_ROUTE_SKY_REGION]);
        sep = "; ";
    }
    if (t->points[CDL_ROUTE_SKY_SUN]) {
        APPEND("%sa sun within the visible sky: the sky's pixels above " STRINGIFY(SKY_PEAK_CUT) " times its mean "
               "luminance exact over their visible part, the rest exact where it is one luminance, else sampled "
               "within the visible sky (no shadow rays), past up to %" PRIu32 " occluders at %" PRIu64 " points",
               sep, t->most_occluders, t->points[CDL_ROUTE_SKY_SUN]);
        sep = "; ";
    }
    for (int r = CDL_ROUTE_TOO_MANY; r < CDL_ROUTE_COUNT; ++r)
        if (t->points[r]) {
            APPEND("%ssampled: %s at %" PRIu64 " points", sep, why[r], t->points[r]);
            sep = "; ";
        }
    if (t->capped)
        APPEND("%sthe cap of %.0f samples a light held %" PRIu64 " points short of the target (their stated error "
               "is larger)", sep, CDL_DIRECT_MAX_SAMPLES, t->capped);
#undef APPEND
}
