/* cmd_convert.c - `candela convert`: IES <-> EULUMDAT by file extension. */
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli_args.h"
#include "command.h"
#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"

static void print_help(FILE *out)
{
    fputs("usage: candela convert IN OUT [options]\n"
          "\n"
          "Converts between IES LM-63 (.ies) and EULUMDAT (.ldt), formats chosen by\n"
          "file extension. Any LM-63 version is read; LM-63-2019 is written by default.\n"
          "The output holds the most compact symmetry that represents the data\n"
          "exactly; what the target format cannot hold is reported on stderr.\n"
          "\n"
          "  --ies-version 2019|2002   LM-63 version written (default 2019)\n"
          "  --c-mapping MAP           how an EULUMDAT C-plane and an IES horizontal\n"
          "                            angle H correspond (used only between formats):\n"
          "       mirror    H = (360 - C) mod 360   (default)\n"
          "       identity  H = C\n"
          "       plus90    H = (C + 90) mod 360\n"
          "       minus90   H = (C + 270) mod 360\n"
          "  --strict                  refuse an input that has warnings\n"
          "  --quiet                   do not list what the target cannot hold\n"
          "\n"
          "Conventions. EULUMDAT C-planes are measured counter-clockwise seen from\n"
          "above the luminaire (C0 along +x, C90 along +y, gamma 0 at nadir). IES\n"
          "type C horizontal angles are read as counter-clockwise seen from below,\n"
          "so by default an IES H is the EULUMDAT plane C = 360 - H: H0 = C0,\n"
          "H90 = C270, H180 = C180. Real converters write the same (the IES H90\n"
          "plane holds the EULUMDAT C270 data). Radiance's ies2rad agrees for 90-270\n"
          "tables but turns a full 0-360 table the other way (H90 towards +y). For\n"
          "symmetric data (one plane, 0-90, 0-180) the choice changes nothing; for\n"
          "0-360 and 90-270 tables it decides which side is which. If the other\n"
          "program in your chain numbers H like C, use --c-mapping identity.\n"
          "\n"
          "Units. EULUMDAT intensities are cd/klm of lamp set 1; IES relative data\n"
          "becomes lamps x lumens per lamp, IES absolute photometry (lumens = -1)\n"
          "becomes a negative lamp count with the integrated flux, LORL 100 %. The\n"
          "IES multiplier is applied (written as 1). A gamma range EULUMDAT allows\n"
          "but LM-63 does not (e.g. 0-140) is padded with zero intensity. IES type\n"
          "A/B data is resampled onto C-planes for EULUMDAT (the flux change is\n"
          "reported). EULUMDAT has no ballast factor: an IES one is folded into the\n"
          "lamp flux (line 29), so the luminaire gives the same light (said on\n"
          "stderr), and `candela info` reads the same flux from both. Test-lab fields\n"
          "both ways: [TEST] is the report number (line 8), [ISSUEDATE] the date\n"
          "(line 12), and [TESTLAB], which EULUMDAT lacks, follows the date as\n"
          "\", test lab: NAME\" and comes back as [TESTLAB].\n"
          "\n"
          "Round trips. EULUMDAT -> IES -> EULUMDAT gives back the file: the fields\n"
          "LM-63 has no place for (Ityp, Isym and Mc, the luminaire's size, the\n"
          "luminous heights per side, the stated DFF and LORL, the measurement tilt,\n"
          "CCT and colour rendering, further lamp sets, the direct ratios, a gamma\n"
          "range LM-63 cannot end at) travel as IES keywords [_EULUMDAT_...] that\n"
          "the EULUMDAT writer reads back. IES -> EULUMDAT keeps [TEST], [TESTLAB],\n"
          "[ISSUEDATE], [MANUFAC], [LUMCAT], [LUMINAIRE] and [LAMP] and names every\n"
          "other keyword it cannot hold; it computes the direct ratios (lines 27-36,\n"
          "see `candela info --help`), DFF and LORL from the table.\n"
          "\n"
          "Radiometric files (a table in W/sr, e.g. [_INTENSITYUNITS] mW/sr) are\n"
          "refused as EULUMDAT, which holds cd/klm only (every program would read\n"
          "them as light); IES to IES keeps their units.\n"
          "\n"
          "Exit status: 0 success, 1 bad input (an unreadable or invalid IN, an\n"
          "unwritable OUT), 2 usage error, 3 internal or resource failure.\n", out);
}

/* Format by extension, case-insensitive; 0 when unknown. */
static cdl_photometry_format format_of(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash)) return CDL_PHOTOMETRY_FORMAT_TABLE;
    if (strcasecmp(dot, ".ies") == 0) return CDL_PHOTOMETRY_FORMAT_IES;
    if (strcasecmp(dot, ".ldt") == 0) return CDL_PHOTOMETRY_FORMAT_EULUMDAT;
    return CDL_PHOTOMETRY_FORMAT_TABLE;
}

typedef struct mapping {
    const char *name;
    int sign;       /* the model transform C' = sign x C + offset that realises H = map(C) */
    double offset;
} mapping;

/* Frame planes are EULUMDAT planes and the IES writer/reader use
 * H = -C; to make H = m(C) the table moves by C' = -m(C). */
static const mapping mappings[] = {
    {"mirror", 1, 0.0}, {"identity", -1, 0.0}, {"plus90", -1, -90.0}, {"minus90", -1, 90.0}};

static int run(int argc, char **argv)
{
    cdl_cli_option options[] = {{"ies-version", 0, 1, 0, NULL},
                                {"c-mapping", 0, 1, 0, NULL},
                                {"strict", 0, 0, 0, NULL},
                                {"quiet", 'q', 0, 0, NULL}};
    const size_t count = sizeof options / sizeof options[0];
    cdl_cli_result r;
    if (cdl_cli_scan(argc, argv, options, count, &r) != 0) {
        fprintf(stderr, "candela convert: %s\n(see 'candela convert --help')\n", r.message);
        return CDL_EXIT_USAGE;
    }
    if (r.help) {
        print_help(stdout);
        return CDL_EXIT_OK;
    }
    if (r.positional_count != 2) {
        fprintf(stderr,
                "candela convert: expected an input and an output file, found %zu arguments\n"
                "(see 'candela convert --help')\n",
                r.positional_count);
        return CDL_EXIT_USAGE;
    }
    const char *in = r.positional[0], *out = r.positional[1];
    cdl_photometry_format out_format = format_of(out);
    if (out_format == CDL_PHOTOMETRY_FORMAT_TABLE) {
        fprintf(stderr, "candela convert: %s: expected an output name ending in .ies or .ldt\n", out);
        return CDL_EXIT_USAGE;
    }
    cdl_photometry_write_options wo = CDL_PHOTOMETRY_WRITE_OPTIONS_INIT;
    const cdl_cli_option *ver = cdl_cli_find(options, count, "ies-version");
    if (ver->present) {
        if (strcmp(ver->value, "2019") == 0) wo.ies_version = 2019;
        else if (strcmp(ver->value, "2002") == 0) wo.ies_version = 2002;
        else {
            fprintf(stderr, "candela convert: --ies-version: expected 2019 or 2002, found '%s'\n", ver->value);
            return CDL_EXIT_USAGE;
        }
    }
    const mapping *map = &mappings[0];
    const cdl_cli_option *mo = cdl_cli_find(options, count, "c-mapping");
    if (mo->present) {
        map = NULL;
        for (size_t k = 0; k < sizeof mappings / sizeof *mappings; ++k)
            if (strcmp(mo->value, mappings[k].name) == 0) map = &mappings[k];
        if (!map) {
            fprintf(stderr,
                    "candela convert: --c-mapping: expected mirror, identity, plus90 or minus90, found '%s'\n",
                    mo->value);
            return CDL_EXIT_USAGE;
        }
    }
    int quiet = cdl_cli_find(options, count, "quiet")->present;

    cdl_photometry_read_options ro = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    ro.strict = cdl_cli_find(options, count, "strict")->present;
    cdl_photometry *p = NULL;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = cdl_photometry_read_file(in, &ro, &p, &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela convert: %s\n", err.message);
        return (int)st;
    }
    if (!quiet)
        for (size_t i = 0; i < cdl_photometry_warning_count(p); ++i)
            fprintf(stderr, "candela convert: warning: [%s] %s\n", cdl_photometry_warning_code(p, i),
                    cdl_photometry_warning(p, i));

    const cdl_photometry_metadata *m = cdl_photometry_get_metadata(p);
    cdl_photometry_table t;
    cdl_photometry_get_table(p, &t);
    cdl_photometry *moved = NULL;
    const cdl_photometry *source = p;
    int crosses = m->format != out_format;
    if (!crosses && mo->present && !quiet)
        fprintf(stderr, "candela convert: --c-mapping applies only between IES and EULUMDAT; ignored\n");
    if (crosses && t.type != CDL_PHOTOMETRIC_TYPE_C && mo->present && !quiet)
        fprintf(stderr, "candela convert: --c-mapping applies to type C data only; ignored\n");
    if (crosses && t.type == CDL_PHOTOMETRIC_TYPE_C && (map->sign != 1 || map->offset != 0.0)) {
        st = cdl_photometry_remap_c(p, map->sign, map->offset, &moved, &err);
        if (st != CDL_OK) {
            fprintf(stderr, "candela convert: %s\n", err.message);
            cdl_photometry_release(p);
            return (int)st;
        }
        source = moved;
    }
    cdl_photometry_notes lost = CDL_PHOTOMETRY_NOTES_INIT;
    st = cdl_photometry_write_file(source, out, out_format, &wo, &lost, &err);
    if (st == CDL_OK && !quiet)
        for (size_t i = 0; i < lost.count; ++i)
            fprintf(stderr, "candela convert: %s cannot hold: %s\n",
                    out_format == CDL_PHOTOMETRY_FORMAT_IES ? "IES" : "EULUMDAT", lost.items[i]);
    cdl_photometry_notes_free(&lost);
    cdl_photometry_release(moved);
    cdl_photometry_release(p);
    if (st != CDL_OK) {
        fprintf(stderr, "candela convert: %s\n", err.message);
        return (int)st;
    }
    return CDL_EXIT_OK;
}

const cdl_command cdl_command_convert = {"convert", "convert IES <-> EULUMDAT (by extension); LM-63-2019 or -2002 out", run, print_help};
