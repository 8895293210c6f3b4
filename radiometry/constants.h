/* constants.h - physical and photometric constants, each with its source.
 *
 * Every constant that turns one kind of quantity into another lives here,
 * named; no other file writes 683, 179 or 4*pi-with-a-meaning inline.
 *
 * Macros only, each with its unit beside it: nothing to own, no state
 * (thread-safe), no errors.
 */
#ifndef CANDELA_RADIOMETRY_CONSTANTS_H
#define CANDELA_RADIOMETRY_CONSTANTS_H

#define CDL_PI 3.14159265358979323846
#define CDL_TWO_PI 6.28318530717958647692
#define CDL_FOUR_PI 12.56637061435917295384
#define CDL_INV_PI 0.31830988618379067154
#define CDL_DEG_TO_RAD (CDL_PI / 180.0)
#define CDL_RAD_TO_DEG (180.0 / CDL_PI)

/* Maximum photopic luminous efficacy Km: the SI definition of the candela
 * fixes K_cd = 683 lm/W for monochromatic radiation of 540e12 Hz (BIPM, SI
 * Brochure 9th ed. 2019, 2.3.1). 540 THz is 555.016 nm in standard air, so
 * strictly Km = 683.002 lm/W at the V(lambda) peak (CIE 018:2019 / ISO 23539);
 * Candela uses 683, as most lighting programs do. */
#define CDL_KM_PHOTOPIC_LM_PER_W 683.0
/* Maximum scotopic luminous efficacy K'm = 1700 lm/W at 507 nm
 * (CIE 1951; 1700.06 lm/W by the 1979 redefinition, ISO 23539:2005). */
#define CDL_KM_SCOTOPIC_LM_PER_W 1700.0

/* CODATA 2018 exact SI values (BIPM SI Brochure 2019). */
#define CDL_PLANCK_H 6.62607015e-34        /* J s */
#define CDL_SPEED_OF_LIGHT 299792458.0     /* m/s */
#define CDL_BOLTZMANN_K 1.380649e-23       /* J/K */
/* Stefan-Boltzmann constant sigma = 2 pi^5 k^4 / (15 h^3 c^2) (CODATA 2018). */
#define CDL_STEFAN_BOLTZMANN 5.670374419e-8 /* W m^-2 K^-4 */
/* Wien displacement constant b (CODATA 2018). */
#define CDL_WIEN_B 2.897771955e-3          /* m K */

/* International foot, exactly 0.3048 m (1959 international yard and pound agreement). */
#define CDL_METRES_PER_FOOT 0.3048
/* International inch, exactly 0.0254 m. */
#define CDL_METRES_PER_INCH 0.0254

#endif
