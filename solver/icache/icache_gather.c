/* icache_gather.c - a record's stratified gather, its variance and its gradients. */
#include "solver/icache/icache_record.h"

#include <math.h>
#include <stdlib.h>

#include "radiometry/constants.h"
#include "radiometry/estimate.h"
#include "radiometry/frame.h"

/* theta of the boundary at j / M of the cosine-weighted strata: cos^2 theta
 * = 1 - j / M (equal projected solid angle per ring). */
static double ring_theta(int j, int M)
{
    return acos(sqrt(fmax(0.0, 1.0 - (double)j / M)));
}

int cdl_icache_gather(const cdl_path_context *ctx, cdl_rng_key key, cdl_vec3 p, cdl_vec3 n, int M, int N,
                      cdl_icache_record *rec, cdl_path_stats *stats, cdl_path_tally *tally)
{
    size_t cells = (size_t)M * (size_t)N;
    double *v = malloc(2 * cells * sizeof *v);
    if (!v) return 0;
    double *r = v + cells;
    cdl_frame f = cdl_frame_from_normal(n);
    double inv_distance = 0.0, open = 0.0;
    cdl_round round = {0.0, 0.0, 0.0, 0};
    for (int j = 0; j < M; ++j)
        for (int k = 0; k < N; ++k) {
            size_t c = (size_t)j * N + k;
            cdl_rng_key pk = {key.seed, cdl_rng_stream_id(key.stream, c, 0x676174686572 /* "gather" */)};
            double u[2];
            cdl_rng_uniform2(pk, 0, u);
            double ct = sqrt(fmax(0.0, 1.0 - (j + u[0]) / M)), st = sqrt(fmax(0.0, 1.0 - ct * ct));
            double phi = 2.0 * CDL_PI * (k + u[1]) / N;
            cdl_vec3 local = cdl_vec3_make(st * cos(phi), st * sin(phi), ct);
            cdl_path_result res;
            cdl_transport_path(ctx, pk, p, n, cdl_frame_to_world(&f, local), &res, stats);
            if (tally) cdl_path_tally_add(tally, &res);
            v[c] = res.value;
            r[c] = res.distance;
            if (isfinite(res.distance) && res.distance > 0.0)
                inv_distance += 1.0 / res.distance;
            else
                open += 1.0;
            /* Neighbouring strata k, k + 1 (k even) form one stratum of two
             * samples for the variance (estimate.h): an upper bound on the
             * variance of the M x N stratified mean. */
            if (k & 1) cdl_round_add_pair(&round, v[c - 1], v[c]);
        }
    cdl_estimate est = {0.0, 0.0, 0.0, 0};
    cdl_estimate_add_round(&est, &round);
    rec->p = p;
    rec->n = n;
    rec->E = cdl_estimate_mean(&est);
    rec->var = cdl_estimate_variance(&est);
    rec->open = open / cells;
    rec->harmonic = inv_distance > 0.0 ? cells / inv_distance : INFINITY;

    /* Gradients (Ward and Heckbert 1992), with L_jk = v_jk / pi the radiance
     * seen through stratum (j, k), u_k the tangent direction at phi_k and
     * v_k = n x u_k (the direction of increasing phi).
     *  - Rotation: turning n by a small angle a about a tangent axis changes
     *    cos theta by a sin theta (axis-dependent), so dE/da is the integral
     *    of L tan theta over the cosine-weighted samples:
     *        g_r = (1 / MN) sum_jk v_jk tan theta_j v_k,
     *    theta_j at the stratum's centre (a jittered theta near the horizon
     *    would make tan unbounded).
     *  - Translation: moving p by dx shifts the boundaries between strata
     *    over the surfaces they see at distance r: the ring boundary theta_j-
     *    by dx cos theta / r along u_k, the meridian phi_k- by dx / (r sin
     *    theta) along v_k-, each exchanging the radiance of the two strata
     *    over the projected solid angle swept:
     *        g_t = sum_k [ u_k (2 pi / N) sum_{j>=1} sin theta_j- cos^2 theta_j-
     *                        (L_jk - L_{j-1,k}) / min(r_jk, r_{j-1,k})
     *                    + v_k- sum_j (sin theta_j+ - sin theta_j-)
     *                        (L_jk - L_{j,k-1}) / min(r_jk, r_{j,k-1}) ]. */
    cdl_vec3 gr = cdl_vec3_make(0, 0, 0), gt = cdl_vec3_make(0, 0, 0);
    for (int k = 0; k < N; ++k) {
        double phic = 2.0 * CDL_PI * (k + 0.5) / N, phib = 2.0 * CDL_PI * k / N;
        cdl_vec3 uk = cdl_frame_to_world(&f, cdl_vec3_make(cos(phic), sin(phic), 0.0));
        cdl_vec3 vk = cdl_frame_to_world(&f, cdl_vec3_make(-sin(phic), cos(phic), 0.0));
        cdl_vec3 vb = cdl_frame_to_world(&f, cdl_vec3_make(-sin(phib), cos(phib), 0.0));
        double rot = 0.0, radial = 0.0, azimuthal = 0.0;
        int km = (k + N - 1) % N;
        for (int j = 0; j < M; ++j) {
            size_t c = (size_t)j * N + k;
            double tlo = ring_theta(j, M), thi = ring_theta(j + 1, M);
            double tc = acos(sqrt(fmax(0.0, 1.0 - (j + 0.5) / M)));
            rot += v[c] * tan(tc);
            if (j > 0) {
                double rm = fmin(r[c], r[c - N]);
                if (isfinite(rm) && rm > 0.0)
                    radial += sin(tlo) * cos(tlo) * cos(tlo) * (v[c] - v[c - N]) / (CDL_PI * rm);
            }
            double rm = fmin(r[c], r[(size_t)j * N + km]);
            if (isfinite(rm) && rm > 0.0)
                azimuthal += (sin(thi) - sin(tlo)) * (v[c] - v[(size_t)j * N + km]) / (CDL_PI * rm);
        }
        gr = cdl_vec3_add(gr, cdl_vec3_scale(vk, rot / cells));
        gt = cdl_vec3_add(gt, cdl_vec3_add(cdl_vec3_scale(uk, 2.0 * CDL_PI / N * radial), cdl_vec3_scale(vb, azimuthal)));
    }
    rec->grad_r = gr;
    rec->grad_t = gt;
    free(v);
    return 1;
}
