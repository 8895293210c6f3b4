/* daylight_factor.c - the overcast sky a daylight factor is taken under (daylight_factor.h). */
#include "solver/daylight_factor.h"

#include <stdio.h>

#include "base/error_report.h"

cdl_status cdl_daylight_factor_reference(const cdl_scene *scene, const cdl_scene_lights *lights,
                                         const cdl_grid_spec *spec, double *E_h, char *words, size_t size,
                                         cdl_error *err)
{
    const cdl_luminaire_spec *sky = scene->luminaire_count == 1 ? &scene->luminaires[0] : NULL;
    int overcast = sky && sky->kind == CDL_LUMINAIRE_ENVIRONMENT &&
                   (sky->sky == CDL_SCENE_SKY_CIE_OVERCAST ||
                    (sky->sky == CDL_SCENE_SKY_CIE && sky->daylight.cie_type == 1));
    if (!overcast || lights->count != 1) {
        const char *found = "no light";
        char what[200];
        if (lights->count > 1) {
            /* the first light that is not the overcast sky */
            size_t l = overcast ? 1 : 0;
            snprintf(what, sizeof what, "%s (%s) besides", lights->lights[l].label, lights->kinds[l]);
            found = what;
        } else if (lights->count == 1) {
            snprintf(what, sizeof what, "%s (%s)", lights->lights[0].label, lights->kinds[0]);
            found = what;
        }
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: %s.outputs: expected a scene lit by one CIE overcast sky alone for "
                             "\"daylight_factor\" (\"sky\": \"cie_overcast\", or \"cie\" with \"cie_type\": 1, and "
                             "no other light: the factor is that sky's light over its horizontal illuminance), found "
                             "%s",
                             scene->path, spec->json_path, found);
    }
    /* its illuminance on an unobstructed horizontal plane: the sky's flux
     * through a 1 m^2 disk facing up (emitter.h), 7 pi L_z / 9 for Moon
     * and Spencer's sky */
    *E_h = cdl_emitter_flux(lights->lights[0].emitter).lm;
    if (!(*E_h > 0.0))
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s: %s.outputs: expected a sky brighter than 0 for \"daylight_factor\", found %s giving "
                             "%g lx on a horizontal plane",
                             scene->path, spec->json_path, lights->lights[0].label, *E_h);
    snprintf(words, size,
             "100 E / E_h under %s, %s: E_h = %.10g lx on an unobstructed horizontal plane; interreflected light "
             "included where modelled",
             lights->lights[0].label,
             sky->sky == CDL_SCENE_SKY_CIE_OVERCAST ? "the CIE standard overcast sky (Moon and Spencer 1942), E_h = 7 "
                                                      "pi L_z / 9"
                                                    : "the CIE standard general sky of type 1 (ISO 15469:2004)",
             *E_h);
    return CDL_OK;
}
