/* environment_sampler.c - image environments sampled by luminance times each
 * pixel's projected solid angle on one receiver's hemisphere.
 *
 * The pixel is drawn by inverting the cumulative sum of L Q over the pixels
 * (a 1-D piecewise-constant distribution, pbrt-v4's PiecewiseConstant1D:
 * Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., 2023,
 * A.4.1); where u1 fell within the pixel's share and u2 then place the
 * direction uniformly in the pixel's solid angle (cos theta uniform between
 * the row's bounds, phi uniform across the column; Archimedes' hat-box
 * theorem). The probability of a pixel is read back from the same
 * cumulative sum, so the pdf is the one the sampler has.
 */
#include "lights/environment/environment_sampler.h"

#include <math.h>
#include <stdlib.h>

#include "base/error_report.h"
#include "lights/emitters/distribution2d.h"
#include "lights/environment/environment_pixels.h"

struct cdl_environment_sampler {
    const cdl_env_pixels *px;
    cdl_vec3 n;
    double E;           /* exact unoccluded illuminance, lux */
    size_t count;       /* pixels in the rows that carry light */
    double *cdf;        /* normalised cumulative sum of L Q; NULL when E = 0 */
};

int cdl_environment_sampler_applies(const cdl_emitter *emitter)
{
    return cdl_emitter_environment_pixels(emitter) != NULL;
}

cdl_status cdl_environment_sampler_create(const cdl_emitter *emitter, cdl_vec3 n, cdl_environment_sampler **out,
                                          cdl_error *err)
{
    *out = NULL;
    const cdl_env_pixels *px = cdl_emitter_environment_pixels(emitter);
    if (!px) return cdl_error_set(err, CDL_ERR_USAGE, "environment sampler: expected an image environment emitter");
    double len = cdl_vec3_length(n);
    if (!(len > 0.0) || !isfinite(len))
        return cdl_error_set(err, CDL_ERR_INPUT, "environment sampler: normal: expected a finite non-zero vector, "
                                                 "found [%g, %g, %g]", n.x, n.y, n.z);
    cdl_environment_sampler *s = calloc(1, sizeof *s);
    size_t count = (size_t)px->rows * (size_t)px->width;
    double *cdf = malloc((count ? count : 1) * sizeof *cdf);
    if (!s || !cdf) {
        free(s);
        free(cdf);
        return cdl_error_out_of_memory(err);
    }
    s->px = px;
    s->n = cdl_vec3_scale(n, 1.0 / len);
    s->count = count;
    s->E = cdl_env_pixels_illuminance(px, s->n, cdf);
    double total = 0.0;
    for (size_t k = 0; k < count; ++k) {
        total += cdf[k];
        cdf[k] = total;
    }
    if (total > 0.0 && count > 0) {
        for (size_t k = 0; k < count; ++k) cdf[k] /= total;
        cdf[count - 1] = 1.0;
        s->cdf = cdf;
    } else {
        free(cdf);
        s->E = 0.0;
    }
    *out = s;
    return CDL_OK;
}

void cdl_environment_sampler_release(cdl_environment_sampler *sampler)
{
    if (!sampler) return;
    free(sampler->cdf);
    free(sampler);
}

cdl_illuminance cdl_environment_sampler_illuminance(const cdl_environment_sampler *sampler)
{
    return cdl_lux(sampler->E);
}

/* Probability of pixel k, and pdf in solid angle of a direction within it. */
static double pixel_pdf(const cdl_environment_sampler *s, size_t k)
{
    double P = s->cdf[k] - (k > 0 ? s->cdf[k - 1] : 0.0);
    int j = (int)(k / (size_t)s->px->width);
    double omega = cdl_env_pixels_solid_angle(s->px, j);
    return omega > 0.0 ? P / omega : 0.0;
}

int cdl_environment_sampler_sample(const cdl_environment_sampler *s, double u1, double u2, cdl_light_sample *out)
{
    out->L = cdl_nits(0.0);
    out->pdf = 0.0;
    out->distance = INFINITY;
    if (!s->cdf) return 0;
    double frac;
    size_t k = cdl_distribution_invert_cdf(s->cdf, s->count, u1, &frac);
    const cdl_env_pixels *px = s->px;
    int j = (int)(k / (size_t)px->width), i = (int)(k % (size_t)px->width);
    /* Uniform in solid angle within the pixel. */
    double cos_t = px->cos_a[j] - frac * (px->cos_a[j] - px->cos_b[j]);
    double sin_t = sqrt(fmax(0.0, (1.0 - cos_t) * (1.0 + cos_t)));
    double phi = px->phi_a[i] + u2 * px->dphi;
    cdl_vec3 w = cdl_frame_to_world(&px->frame, cdl_vec3_make(sin_t * cos(phi), sin_t * sin(phi), cos_t));
    out->to_light = w;
    double pdf = pixel_pdf(s, k);
    double L = px->scale * px->image[k];
    if (!(cdl_vec3_dot(s->n, w) > 0.0) || !(pdf > 0.0) || !(L > 0.0)) return 0;
    out->L = cdl_nits(L);
    out->pdf = pdf;
    return 1;
}

double cdl_environment_sampler_pdf(const cdl_environment_sampler *s, cdl_vec3 w)
{
    double len = cdl_vec3_length(w);
    if (!s->cdf || !(len > 0.0) || !isfinite(len)) return 0.0;
    w = cdl_vec3_scale(w, 1.0 / len);
    int i, j;
    if (!cdl_env_pixels_locate(s->px, w, &i, &j)) return 0.0;
    return pixel_pdf(s, (size_t)j * (size_t)s->px->width + (size_t)i);
}
