/* cmd_sun.c - `candela sun`: the sun's position for a place and a time (the SPA). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli_args.h"
#include "command.h"
#include "lights/environment/solar_position.h"

static void print_help(FILE *out)
{
    fputs("usage: candela sun --lat DEG --lon DEG --time ISO8601 [options]\n"
          "\n"
          "Prints where the sun is seen from a place at a time, by the NREL Solar\n"
          "Position Algorithm (Reda and Andreas 2004, +-0.0003 degrees for the years\n"
          "-2000 to 6000): the topocentric zenith angle (refraction included), the\n"
          "azimuth eastward from north (90 east, 180 south), the sun's geocentric\n"
          "declination and the equation of time (apparent minus mean solar time).\n"
          "\n"
          "  --lat DEG            latitude, north positive, -90..90\n"
          "  --lon DEG            longitude, east positive, -180..180\n"
          "  --time ISO8601       date and time with its UTC offset, e.g.\n"
          "                       2003-10-17T12:30:30-07:00 or 2003-10-17T19:30:30Z\n"
          "  --elevation M        height above sea level (default 0)\n"
          "  --pressure MBAR      mean air pressure for refraction (default 1013.25;\n"
          "                       0: no refraction)\n"
          "  --temperature C      mean air temperature for refraction (default 12)\n"
          "  --delta-t S          Delta T = TT - UT1 in seconds (default: estimated for\n"
          "                       the year, Espenak and Meeus 2006)\n"
          "  --json               one JSON object instead of text\n"
          "\n"
          "Exit status: 0 success, 1 bad input (a time without a UTC offset, a value\n"
          "out of range), 2 usage error, 3 internal failure.\n",
          out);
}

/* A number option into *out (kept when absent); 2 after saying what was found. */
static int read_number(cdl_cli_option *opt, double *out)
{
    if (!opt->present) return 0;
    char *end = NULL;
    double v = strtod(opt->value, &end);
    if (!end || end == opt->value || *end || !isfinite(v)) {
        fprintf(stderr, "candela sun: --%s: expected a number, found '%s'\n(see 'candela sun --help')\n",
                opt->long_name, opt->value);
        return CDL_EXIT_USAGE;
    }
    *out = v;
    return 0;
}

/* The option a library message names ("latitude_deg: ...") as typed. */
static const char *option_for(const char *message)
{
    static const struct {
        const char *field, *option;
    } names[] = {{"latitude_deg", "--lat"},       {"longitude_deg", "--lon"},         {"elevation_m", "--elevation"},
                 {"pressure_mbar", "--pressure"}, {"temperature_c", "--temperature"}, {"delta_t_s", "--delta-t"},
                 {"time", "--time"}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
        if (strncmp(message, names[i].field, strlen(names[i].field)) == 0) return names[i].option;
    return NULL;
}

static void print_text(const cdl_solar_site *site, const char *when, const cdl_solar_position *s)
{
    printf("sun at latitude %.10g, longitude %.10g, %.10g m above sea level, %s\n", site->latitude_deg,
           site->longitude_deg, site->elevation_m, when);
    printf("  zenith            %10.5f deg  (elevation %.5f deg, refraction %.5f deg)\n", s->zenith_deg,
           s->elevation_deg, s->refraction_deg);
    printf("  azimuth           %10.5f deg  (eastward from north)\n", s->azimuth_deg);
    printf("  declination       %10.5f deg\n", s->declination_deg);
    printf("  equation of time  %10.5f min\n", s->equation_of_time_min);
    printf("  Julian day (UT)   %.6f, Delta T %.3g s\n", s->julian_day, s->delta_t_s);
}

static void print_json(const cdl_solar_site *site, const char *when, const cdl_solar_position *s)
{
    printf("{\"time\": \"%s\", \"latitude_deg\": %.17g, \"longitude_deg\": %.17g, \"elevation_m\": %.17g, "
           "\"pressure_mbar\": %.17g, \"temperature_c\": %.17g, \"delta_t_s\": %.17g, \"julian_day\": %.17g, "
           "\"zenith_deg\": %.17g, \"azimuth_deg\": %.17g, \"elevation_deg\": %.17g, \"refraction_deg\": %.17g, "
           "\"declination_deg\": %.17g, \"right_ascension_deg\": %.17g, \"equation_of_time_min\": %.17g}\n",
           when, site->latitude_deg, site->longitude_deg, site->elevation_m, site->pressure_mbar, site->temperature_c,
           s->delta_t_s, s->julian_day, s->zenith_deg, s->azimuth_deg, s->elevation_deg, s->refraction_deg,
           s->declination_deg, s->right_ascension_deg, s->equation_of_time_min);
}

static int run(int argc, char **argv)
{
    cdl_cli_option options[] = {{"lat", 0, 1, 0, NULL},       {"lon", 0, 1, 0, NULL},
                                {"time", 0, 1, 0, NULL},      {"elevation", 0, 1, 0, NULL},
                                {"pressure", 0, 1, 0, NULL},  {"temperature", 0, 1, 0, NULL},
                                {"delta-t", 0, 1, 0, NULL},   {"json", 0, 0, 0, NULL}};
    const size_t count = sizeof options / sizeof options[0];
    cdl_cli_result r;
    if (cdl_cli_scan(argc, argv, options, count, &r) != 0) {
        fprintf(stderr, "candela sun: %s\n(see 'candela sun --help')\n", r.message);
        return CDL_EXIT_USAGE;
    }
    if (r.help) {
        print_help(stdout);
        return CDL_EXIT_OK;
    }
    if (r.positional_count) {
        fprintf(stderr, "candela sun: expected options only, found '%s'\n(see 'candela sun --help')\n",
                r.positional[0]);
        return CDL_EXIT_USAGE;
    }
    const char *required[] = {"lat", "lon", "time"};
    for (size_t i = 0; i < 3; ++i)
        if (!cdl_cli_find(options, count, required[i])->present) {
            fprintf(stderr, "candela sun: --%s is required\n(see 'candela sun --help')\n", required[i]);
            return CDL_EXIT_USAGE;
        }
    cdl_solar_site site = CDL_SOLAR_SITE_DEFAULT;
    int st = read_number(cdl_cli_find(options, count, "lat"), &site.latitude_deg);
    if (!st) st = read_number(cdl_cli_find(options, count, "lon"), &site.longitude_deg);
    if (!st) st = read_number(cdl_cli_find(options, count, "elevation"), &site.elevation_m);
    if (!st) st = read_number(cdl_cli_find(options, count, "pressure"), &site.pressure_mbar);
    if (!st) st = read_number(cdl_cli_find(options, count, "temperature"), &site.temperature_c);
    if (!st) st = read_number(cdl_cli_find(options, count, "delta-t"), &site.delta_t_s);
    if (st) return st;
    const char *when = cdl_cli_find(options, count, "time")->value;
    cdl_civil_time t;
    cdl_error err;
    cdl_error_clear(&err);
    if (cdl_civil_time_parse(when, &t, &err) != CDL_OK) {
        fprintf(stderr, "candela sun: --time: %s\n", err.message);
        return CDL_EXIT_INPUT;
    }
    cdl_solar_position s;
    cdl_status status = cdl_solar_position_compute(&site, &t, &s, &err);
    if (status != CDL_OK) {
        const char *option = option_for(err.message);
        fprintf(stderr, "candela sun: %s%s%s\n", option ? option : "", option ? ": " : "", err.message);
        return (int)status;
    }
    if (cdl_cli_find(options, count, "json")->present)
        print_json(&site, when, &s);
    else
        print_text(&site, when, &s);
    return CDL_EXIT_OK;
}

const cdl_command cdl_command_sun = {"sun", "the sun's position for a place and time (NREL SPA)", run, print_help};
