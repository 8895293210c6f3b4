/* emitter_goniometric.c - a luminaire's measured distribution, placed and turned.
 *
 *   parameter            meaning                                       unit  default  range
 *   position             photometric centre                            m     -        finite
 *   rotation_deg         about world x, then y, then z (fixed axes)    deg   0,0,0    finite
 *   photometry           the table (borrowed, must outlive emitter)    -     -        non-NULL
 *   multiplier           scene multiplier                              -     1        > 0
 *   maintenance_factor   light loss over time                          -     1        > 0
 *   flux_lm              > 0: rescale the table to this flux           lm    0 (keep) finite
 *   apply_output_factor  1: the file's ballast/output factor applies   -     1        0 or 1
 *
 * Placement (DESIGN.md): the photometric frame (gamma = 0 along -z, C = 0
 * towards +x, C = 90 towards +y) is turned by world_from_luminaire =
 * Rz(rz) Ry(ry) Rx(rx): right-handed rotations about the fixed world axes,
 * x first. So [0, -30, 0] tilts the nadir from -z towards +x.
 *
 * Intensity towards world direction w:
 *     I(w) = I_table(luminaire_from_world w) x k,
 *     k = s x output factor x tilt factor x multiplier x maintenance factor,
 * with s = flux_lm / Phi_table when flux_lm > 0 (the table is first rescaled
 * to the given luminaire flux, then every application factor acts on it),
 * else 1; the output factor is 1 unless apply_output_factor; the tilt factor
 * is the file's TILT table at the installed tilt, the angle between the
 * turned nadir and world -z. Flux Phi = k Phi_table (the table's exact flux).
 */
#include <math.h>

#include "base/error_report.h"
#include "lights/emitters/emitter.h"
#include "lights/emitters/emitter_internal.h"
#include "radiometry/constants.h"

typedef struct goniometric_emitter {
    cdl_emitter base;
    cdl_vec3 position;
    const cdl_photometry *photometry;
    cdl_vec3 col[3];  /* columns of world_from_luminaire: the luminaire's x, y, z axes in world */
    double factor;    /* k above */
    double tilt_deg;
    int rotational;   /* type C table with one plane: I depends on gamma only */
    int has_cone;     /* light only where gamma < cone_gamma (see gonio_cone) */
    double cone_cos;  /* cos(cone_gamma) */
    double cone_cos2; /* its square */
} goniometric_emitter;

static const goniometric_emitter *as_gonio(const cdl_emitter *e)
{
    return (const goniometric_emitter *)e;
}

/* luminaire_from_world w = R^T w: the components of w along the luminaire's axes. */
static cdl_vec3 to_luminaire(const goniometric_emitter *g, cdl_vec3 w)
{
    return cdl_vec3_make(cdl_vec3_dot(g->col[0], w), cdl_vec3_dot(g->col[1], w), cdl_vec3_dot(g->col[2], w));
}

static cdl_luminous_intensity gonio_intensity(const cdl_emitter *e, cdl_vec3 unit_dir)
{
    const goniometric_emitter *g = as_gonio(e);
    cdl_vec3 local = to_luminaire(g, unit_dir);
    /* Beyond the table's cut-off the interpolated intensity is zero: skip the lookup. */
    if (g->has_cone && -local.z <= g->cone_cos) return cdl_candelas(0.0);
    /* A rotationally symmetric table does not depend on C: no azimuth needed. */
    cdl_luminous_intensity I = g->rotational
                                   ? cdl_photometry_intensity_c_gamma(g->photometry, 0.0, cdl_photometry_gamma_deg(local))
                                   : cdl_photometry_intensity(g->photometry, local);
    return cdl_candelas(I.cd * g->factor);
}

static cdl_luminous_flux gonio_flux(const cdl_emitter *e)
{
    const goniometric_emitter *g = as_gonio(e);
    /* Every factor is a constant multiplier of the whole distribution. */
    return cdl_lumens(cdl_photometry_flux(g->photometry).lm * g->factor);
}

/* The hot path of direct illuminance, for the common rotationally
 * symmetric table: the same E = I cos / d^2 as cdl_emitter_eval_positional
 * with gonio_intensity, computed in one pass: the emission cone first
 * (no square root), then one square root, one division, no azimuth. */
static inline int gonio_rotational_eval(const goniometric_emitter *g, cdl_vec3 n, double d2, cdl_vec3 w,
                                        cdl_delta_light *out)
{
    out->E = cdl_lux(0.0);
    /* cos(gamma) |w| of the direction light -> p, -w, in the luminaire's
     * frame: -(-w . z_luminaire) = w . z_luminaire */
    double along = cdl_vec3_dot(g->col[2], w);
    if (g->has_cone && g->cone_cos >= 0.0 && (along <= 0.0 || along * along <= g->cone_cos2 * d2)) {
        out->to_light = cdl_vec3_make(0.0, 0.0, 0.0);
        out->distance = 0.0;
        return 0;
    }
    double d = sqrt(d2), k = 1.0 / d;
    out->to_light = cdl_vec3_scale(w, k);
    out->distance = d;
    double cos_theta = cdl_vec3_dot(n, out->to_light);
    if (!(cos_theta > 0.0)) return 0;
    double c = along * k;
    if (g->has_cone && c <= g->cone_cos) return 0;
    double gamma_deg;
    if (fabs(c) < 0.7) {
        gamma_deg = acos(c) * CDL_RAD_TO_DEG;
    } else {
        /* near the poles from sin(gamma), which acos would lose */
        double x = cdl_vec3_dot(g->col[0], out->to_light), y = cdl_vec3_dot(g->col[1], out->to_light);
        double r = sqrt(x * x + y * y); /* a plain comparison: fmin is a library call here */
        double s = asin(r < 1.0 ? r : 1.0) * CDL_RAD_TO_DEG;
        gamma_deg = c > 0.0 ? s : 180.0 - s;
    }
    double I = cdl_photometry_intensity_one_plane(g->photometry, gamma_deg) * g->factor;
    /* Inverse-square and cosine law E = I cos(theta) / d^2 (Lambert, Photometria 1760). */
    out->E = cdl_lux(I * cos_theta * k * k);
    return out->E.lx > 0.0;
}

static int gonio_eval_delta(const cdl_emitter *e, cdl_vec3 p, cdl_vec3 n, cdl_delta_light *out)
{
    const goniometric_emitter *g = as_gonio(e);
    cdl_vec3 w = cdl_vec3_sub(g->position, p);
    double d2 = cdl_vec3_dot(w, w);
    if (!g->rotational || !(d2 > 1e-290 && d2 < 1e290))
        return cdl_emitter_eval_positional(e, g->position, gonio_intensity, p, n, out);
    return gonio_rotational_eval(g, n, d2, w, out);
}

static void gonio_eval_delta_many(const cdl_emitter *e, const cdl_vec3 *p, const cdl_vec3 *n, size_t count,
                                  cdl_delta_light *out)
{
    const goniometric_emitter *g = as_gonio(e);
    for (size_t i = 0; i < count; ++i) {
        cdl_vec3 w = cdl_vec3_sub(g->position, p[i]);
        double d2 = cdl_vec3_dot(w, w);
        if (g->rotational && d2 > 1e-290 && d2 < 1e290)
            gonio_rotational_eval(g, n[i], d2, w, &out[i]);
        else if (!cdl_emitter_eval_positional(e, g->position, gonio_intensity, p[i], n[i], &out[i]))
            out[i].E = cdl_lux(0.0);
    }
}

static int gonio_cone(const cdl_emitter *e, cdl_vec3 *position, cdl_vec3 *axis, double *cos_min)
{
    const goniometric_emitter *g = as_gonio(e);
    if (!g->has_cone) return 0;
    *position = g->position;
    *axis = cdl_vec3_neg(g->col[2]); /* the rotated nadir */
    *cos_min = g->cone_cos;
    return 1;
}

/* The gamma beyond which a type C table gives no light in any plane. The
 * interpolated intensity is zero past the last non-zero sample of a plane
 * once the next sample is zero (and beyond the table's last gamma), and
 * interpolation between planes mixes only those planes, so the cut-off is
 * the largest such gamma over the planes. Returns 0 (no cone) when light
 * reaches gamma = 180 or the table is not type C. */
static int gamma_cutoff(const cdl_photometry *ph, double *cutoff_deg)
{
    cdl_photometry_table t;
    cdl_photometry_get_table(ph, &t);
    if (t.type != CDL_PHOTOMETRIC_TYPE_C || t.vertical_count == 0) return 0;
    double cut = 0.0;
    for (size_t i = 0; i < t.horizontal_count; ++i) {
        const double *row = &t.candela[i * t.vertical_count];
        size_t last = t.vertical_count;
        for (size_t j = t.vertical_count; j-- > 0;)
            if (row[j] > 0.0) {
                last = j;
                break;
            }
        if (last == t.vertical_count) continue; /* a dark plane */
        double g = last + 1 < t.vertical_count ? t.vertical_deg[last + 1] : t.vertical_deg[last];
        if (g > cut) cut = g;
    }
    if (!(cut < 180.0)) return 0;
    *cutoff_deg = cut;
    return 1;
}

static const cdl_emitter_ops gonio_ops = {gonio_flux, gonio_intensity, gonio_eval_delta, NULL, NULL, NULL, NULL,
                                          gonio_cone, gonio_eval_delta_many};

/* Columns of Rz(c) Ry(b) Rx(a) (a, b, c the angles about x, y, z), each
 * rotation right-handed about a fixed world axis: R e_k for k = x, y, z. */
void cdl_emitter_rotation_columns(const double rotation_deg[3], cdl_vec3 col[3])
{
    double a = rotation_deg[0] * CDL_DEG_TO_RAD, b = rotation_deg[1] * CDL_DEG_TO_RAD,
           c = rotation_deg[2] * CDL_DEG_TO_RAD;
    double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b), cc = cos(c), sc = sin(c);
    /* Rz Ry Rx =
     *   [cc cb   cc sb sa - sc ca   cc sb ca + sc sa]
     *   [sc cb   sc sb sa + cc ca   sc sb ca - cc sa]
     *   [-sb     cb sa              cb ca           ] */
    col[0] = cdl_vec3_make(cc * cb, sc * cb, -sb);
    col[1] = cdl_vec3_make(cc * sb * sa - sc * ca, sc * sb * sa + cc * ca, cb * sa);
    col[2] = cdl_vec3_make(cc * sb * ca + sc * sa, sc * sb * ca - cc * sa, cb * ca);
}

double cdl_emitter_goniometric_tilt_deg(const cdl_emitter *emitter)
{
    return emitter->kind == CDL_EMITTER_GONIOMETRIC ? as_gonio(emitter)->tilt_deg : 0.0;
}

cdl_status cdl_emitter_create_goniometric(const cdl_goniometric_params *p, cdl_emitter **out, cdl_error *err)
{
    *out = NULL;
    cdl_status st;
    if (!p->photometry)
        return cdl_error_set(err, CDL_ERR_USAGE, "goniometric emitter: photometry: expected a table, found NULL");
    if ((st = cdl_emitter_check_position(p->position, "goniometric emitter: position", err)) != CDL_OK) return st;
    for (int k = 0; k < 3; ++k)
        if (!isfinite(p->rotation_deg[k]))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "goniometric emitter: rotation[%d]: expected a finite angle in degrees, found %g", k,
                                 p->rotation_deg[k]);
    if (!(isfinite(p->multiplier) && p->multiplier > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT, "goniometric emitter: multiplier: expected a finite number > 0, found %g",
                             p->multiplier);
    if (!(isfinite(p->maintenance_factor) && p->maintenance_factor > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "goniometric emitter: maintenance_factor: expected a finite number > 0, found %g",
                             p->maintenance_factor);
    if (!isfinite(p->flux_lm))
        return cdl_error_set(err, CDL_ERR_INPUT, "goniometric emitter: flux_lm: expected a finite number, found %g",
                             p->flux_lm);
    /* A radiant intensity table (W/sr) emits no light the solver could count. */
    cdl_luminous_flux luminous;
    if ((st = cdl_photometry_luminous_flux(p->photometry, &luminous, err)) != CDL_OK) {
        cdl_error_prefix(err, "goniometric emitter: photometry: ");
        return st;
    }
    double table_flux = luminous.lm;
    if (p->flux_lm > 0.0 && !(table_flux > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "goniometric emitter: flux_lm: cannot rescale a distribution whose flux is %g lm to %g lm",
                             table_flux, p->flux_lm);

    goniometric_emitter *g = cdl_emitter_alloc(sizeof *g, CDL_EMITTER_GONIOMETRIC, &gonio_ops, err);
    if (!g) return CDL_ERR_INTERNAL;
    g->position = p->position;
    g->photometry = p->photometry;
    cdl_emitter_rotation_columns(p->rotation_deg, g->col);
    /* Installed tilt: angle between the turned nadir R(-e_z) = -col[2] and
     * world -z, from atan2(|a x b|, a.b), exact at every angle. */
    cdl_vec3 nadir = cdl_vec3_neg(g->col[2]), down = cdl_vec3_make(0.0, 0.0, -1.0);
    g->tilt_deg = atan2(cdl_vec3_length(cdl_vec3_cross(nadir, down)), cdl_vec3_dot(nadir, down)) * CDL_RAD_TO_DEG;
    double k = p->flux_lm > 0.0 ? p->flux_lm / table_flux : 1.0;
    if (p->apply_output_factor) k *= cdl_photometry_output_factor(p->photometry);
    k *= cdl_photometry_tilt_factor(p->photometry, g->tilt_deg);
    k *= p->multiplier * p->maintenance_factor;
    if (!(isfinite(k) && k >= 0.0)) {
        cdl_emitter_release(&g->base);
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "goniometric emitter: expected a finite non-negative total factor, found %g (check the "
                             "file's ballast and tilt factors)",
                             k);
    }
    g->factor = k;
    cdl_photometry_table table;
    cdl_photometry_get_table(p->photometry, &table);
    g->rotational = table.type == CDL_PHOTOMETRIC_TYPE_C && table.symmetry == CDL_PHOTOMETRY_SYMMETRY_ROTATIONAL;
    double cut;
    if (gamma_cutoff(p->photometry, &cut)) {
        g->has_cone = 1;
        g->cone_cos = cos(cut * CDL_DEG_TO_RAD);
        g->cone_cos2 = g->cone_cos * g->cone_cos;
    }
    *out = &g->base;
    return CDL_OK;
}
