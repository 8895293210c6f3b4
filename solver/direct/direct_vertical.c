/* direct_vertical.c - cylindrical and semicylindrical illuminance from the same per-light data as E.
 *
 * Cylindrical illuminance E_z at a point (EN 12464-1:2021, 3.2.6; CIE S
 * 017:2020, 17-21-075) is the mean illuminance over the curved surface of
 * a very small vertical cylinder there; semicylindrical illuminance E_sz
 * (CIE 136:2000, 3.2; EN 13201-2 "E_SC") the mean over the curved half of
 * it that faces a horizontal direction f. A delta light reaching the point
 * from the unit direction w with illuminance E_n = I / d^2 on the plane
 * facing it lights a facet of the cylinder whose horizontal outward normal
 * m lies at azimuth phi from w's azimuth with E_n sin(theta) max(0, cos
 * phi), theta the angle between w and the vertical. The means:
 *   E_z  = (1 / 2pi) int_0^2pi E_n sin(theta) max(0, cos phi) dphi
 *        = E_n sin(theta) / pi
 *   E_sz = (1 / pi) int_{-pi/2}^{pi/2} E_n sin(theta) max(0, cos(psi - alpha)) dpsi
 *        = E_n sin(theta) (1 + cos alpha) / pi
 * with alpha the horizontal angle between w and f (for |alpha| <= pi the
 * integrand is positive for psi - alpha in [-pi/2, pi/2 - |alpha|], whose
 * integral of cos is 1 + cos alpha). A light straight above or below
 * (sin theta = 0) adds nothing to either.
 *
 * Delta lights only (point, spot, goniometric, directional), each with the
 * shadow ray E uses when its strategy has one; extended emitters, skies and
 * interreflected light are sampled over directions (transport/
 * vertical_sampled.c). A point lying on a surface (a floor grid) sees
 * nothing behind it: that surface hides the lights below its plane, which
 * the plan's strategy, made for E's hemisphere, does not shadow-test.
 */
#include "solver/direct/direct.h"
#include "solver/direct/direct_internal.h"

#include <math.h>

#include "radiometry/constants.h"

void cdl_vertical_illuminance_from_light(double E_normal, cdl_vec3 to_light, cdl_vec3 facing, double *Ez,
                                         double *Esz)
{
    /* sin(theta) times the unit horizontal direction: the horizontal part of w. */
    double hx = to_light.x, hy = to_light.y;
    double sin_theta = sqrt(hx * hx + hy * hy);
    *Ez = E_normal * sin_theta / CDL_PI;
    /* cos(alpha) sin(theta) = the horizontal part of w along f (f horizontal, unit). */
    *Esz = E_normal * (sin_theta + hx * facing.x + hy * facing.y) / CDL_PI;
}

int cdl_direct_facing_direction(cdl_vec3 n, cdl_vec3 *facing)
{
    double h = sqrt(n.x * n.x + n.y * n.y);
    if (!(h > CDL_DIRECT_FACING_MIN)) return 0;
    *facing = cdl_vec3_make(n.x / h, n.y / h, 0.0);
    return 1;
}

void cdl_direct_vertical_point(const cdl_direct_context *ctx, const cdl_light_strategy *strategies,
                               const uint32_t *active, size_t active_count, cdl_vec3 p, cdl_vec3 n, cdl_vec3 facing,
                               int on_surface, double *Ez_out, double *Esz_out, cdl_direct_sample_stats *stats)
{
    size_t count = active ? active_count : ctx->light_count;
    double Ez = 0.0, Esz = 0.0;
    for (size_t a = 0; a < count; ++a) {
        size_t l = active ? active[a] : a;
        cdl_light_strategy st = strategies[l];
        if (st != CDL_STRATEGY_DELTA_EXACT && st != CDL_STRATEGY_DELTA_SHADOWED) continue;
        if (!cdl_scene_light_applies(&ctx->lights[l], p)) continue;
        const cdl_emitter *e = ctx->lights[l].emitter;
        /* First the direction to the light (given whatever the plane),
         * then the illuminance on the plane facing it: E_n = I / d^2. */
        cdl_delta_light d;
        cdl_emitter_eval_delta(e, p, cdl_vec3_make(0, 0, 1), &d);
        if (!(cdl_vec3_dot(d.to_light, d.to_light) > 0.5)) continue;
        if (on_surface && !(cdl_vec3_dot(d.to_light, n) > 0.0)) continue;
        if (!cdl_emitter_eval_delta(e, p, d.to_light, &d) || !(d.E.lx > 0.0)) continue;
        double T = st == CDL_STRATEGY_DELTA_SHADOWED
                       ? cdl_direct_transmission(ctx, p, n, d.to_light, d.distance,
                                                 cdl_scene_light_own_piece(&ctx->lights[l]), stats)
                       : 1.0;
        if (!(T > 0.0)) continue;
        double ez, esz;
        cdl_vertical_illuminance_from_light(d.E.lx * T, d.to_light, facing, &ez, &esz);
        Ez += ez;
        Esz += esz;
    }
    if (Ez_out) *Ez_out = Ez;
    if (Esz_out) *Esz_out = Esz;
}
