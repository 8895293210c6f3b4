/* environment_sampler.h - sampling an image environment for one receiver normal.
 *
 * For a receiver with unit normal n, pixel (i, j) is chosen with probability
 *     P_ij = L_ij Q_ij(n) / E(n),  E(n) = sum L Q,
 * Q_ij(n) the pixel's exact projected solid angle on n's hemisphere
 * (environment_pixels.h), then a direction uniform in the pixel's solid
 * angle Omega_j: pdf = P_ij / Omega_j in solid angle. With nothing in the
 * way the estimator L cos / pdf = E(n) cos Omega_j / Q_ij is nearly constant
 * (it varies only with cos across a pixel), against the emitter's own
 * sampler (by L Omega, cdl_emitter_sample), whose estimator varies with cos
 * over the whole hemisphere and wastes samples below the horizon of n.
 * Samples in a pixel the horizon crosses may fall below it: they return 0
 * (counted as zeros, the estimator stays unbiased).
 *
 *   parameter   meaning                                      unit   range
 *   emitter     an image environment (cdl_emitter_create_environment with
 *               an image); borrowed, must outlive the sampler
 *   n           receiver normal, world frame                 -      non-zero
 *
 * Creation costs one pass over the pixels and keeps one double per pixel of
 * the rows that carry light; it depends on n only, so a caller meeting many
 * receivers with one normal can create it once. A created sampler is
 * immutable: sampling is thread-safe.
 */
#ifndef CANDELA_LIGHTS_ENVIRONMENT_ENVIRONMENT_SAMPLER_H
#define CANDELA_LIGHTS_ENVIRONMENT_ENVIRONMENT_SAMPLER_H

#include "lights/emitters/emitter.h"

typedef struct cdl_environment_sampler cdl_environment_sampler;

/* 1 if `emitter` is an image environment (the sampler applies). */
int cdl_environment_sampler_applies(const cdl_emitter *emitter);

/* CDL_ERR_USAGE if the emitter is not an image environment, CDL_ERR_INPUT
 * for a zero or non-finite n, CDL_ERR_OUT_OF_MEMORY. */
cdl_status cdl_environment_sampler_create(const cdl_emitter *emitter, cdl_vec3 n, cdl_environment_sampler **out,
                                          cdl_error *err);
void cdl_environment_sampler_release(cdl_environment_sampler *sampler);

/* E(n) with nothing in the way: the exact pixel sum (equal to
 * cdl_emitter_exact_illuminance for this normal). */
cdl_illuminance cdl_environment_sampler_illuminance(const cdl_environment_sampler *sampler);

/* A direction from u1, u2 in [0, 1) (u1 picks the pixel, stratified u1
 * gives stratified pixels). Returns 0 (out->L = 0) when the direction is
 * below the horizon of n, or when E(n) = 0. out->distance = INFINITY. */
int cdl_environment_sampler_sample(const cdl_environment_sampler *sampler, double u1, double u2,
                                   cdl_light_sample *out);

/* The solid-angle density with which sample() draws world direction w
 * (any length > 0): P_ij / Omega_j in pixel (i, j), also below the horizon
 * of n (such draws are returned as 0), so that it integrates to 1 over the
 * sphere; 0 in pixels it never draws. */
double cdl_environment_sampler_pdf(const cdl_environment_sampler *sampler, cdl_vec3 w);

#endif
