/* `candela info --json`: one valid JSON object with the documented keys,
 * finite numbers, null where a value is unknown, UTF-8 text, and nothing on
 * stdout for a file that is rejected. Runs the real executable ($CANDELA). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "check.h"
#include "radiometry/constants.h"

#define FIXTURES CANDELA_SOURCE_DIR "/tests/data/photometric/"

/* Runs `$CANDELA info --json FILE`; returns stdout (malloc'd) and the exit status. */
static char *run_info(const char *file, int *status)
{
    const char *exe = getenv("CANDELA");
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s' info --json '%s%s' 2>/dev/null", exe ? exe : "candela", FIXTURES, file);
    FILE *f = popen(cmd, "r");
    if (!f) return NULL;
    size_t cap = 1 << 16, n = 0;
    char *out = malloc(cap);
    size_t got;
    while (out && (got = fread(out + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (n + 1 == cap) {
            char *grown = realloc(out, cap *= 2);
            if (!grown) break;
            out = grown;
        }
    }
    int rc = pclose(f);
    *status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    if (out) out[n] = '\0';
    return out;
}

static cJSON *info(const char *file)
{
    int status;
    char *text = run_info(file, &status);
    CHECK_MSG(status == 0, "%s: exit status %d", file, status);
    cJSON *j = text ? cJSON_Parse(text) : NULL;
    CHECK_MSG(j && cJSON_IsObject(j), "%s: not one JSON object: %.200s", file, text ? text : "(no output)");
    free(text);
    return j;
}

static double number(const cJSON *j, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, key);
    CHECK_MSG(cJSON_IsNumber(v), "%s is not a number", key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

static int is_null(const cJSON *j, const char *key) { return cJSON_IsNull(cJSON_GetObjectItemCaseSensitive(j, key)); }

static const char *string(const cJSON *j, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, key);
    CHECK_MSG(cJSON_IsString(v), "%s is not a string", key);
    return cJSON_IsString(v) ? v->valuestring : "";
}

/* Every number anywhere in the document is finite (cJSON writes null for NaN). */
static int all_finite(const cJSON *j)
{
    for (const cJSON *c = j->child; c; c = c->next) {
        if (cJSON_IsNumber(c) && !isfinite(c->valuedouble)) return 0;
        if ((cJSON_IsObject(c) || cJSON_IsArray(c)) && !all_finite(c)) return 0;
    }
    return 1;
}

static void test_required_keys(void)
{
    static const char *const keys[] = {"format",       "version",         "photometric_type", "symmetry",
                                       "c_planes",     "gamma_angles",    "lamp_flux_lm",     "flux_lm",
                                       "lor",          "max_intensity_cd", "beam_angle_deg",  "field_angle_deg",
                                       "downward_fraction", "warnings"};
    const char *files[] = {"iso_1000cd.ies", "ies_1986_one_per_line.ies", "ldt_comma_blank_crlf.ldt", "warn_seam.ies"};
    for (size_t f = 0; f < sizeof files / sizeof *files; ++f) {
        cJSON *j = info(files[f]);
        if (!j) continue;
        for (size_t k = 0; k < sizeof keys / sizeof *keys; ++k)
            CHECK_MSG(cJSON_HasObjectItem(j, keys[k]), "%s: no key %s", files[f], keys[k]);
        CHECK(all_finite(j));
        CHECK(cJSON_IsArray(cJSON_GetObjectItemCaseSensitive(j, "warnings")));
        cJSON_Delete(j);
    }
}

static void test_values(void)
{
    /* isotropic 1000 cd, absolute photometry */
    cJSON *j = info("iso_1000cd.ies");
    if (j) {
        CHECK(strcmp(string(j, "format"), "IES") == 0);
        CHECK(strcmp(string(j, "version"), "LM-63-2002") == 0);
        CHECK(strcmp(string(j, "photometric_type"), "C") == 0);
        CHECK(strcmp(string(j, "symmetry"), "rotational") == 0);
        CHECK(number(j, "c_planes") == 1.0 && number(j, "gamma_angles") == 19.0);
        CHECK(is_null(j, "lamp_flux_lm") && is_null(j, "lor"));
        /* the JSON keeps enough digits for a closed form: 4000 pi */
        CHECK_REL(number(j, "flux_lm"), 4000.0 * CDL_PI, 1e-12);
        CHECK_REL(number(j, "max_intensity_cd"), 1000.0, 0.0);
        CHECK_REL(number(j, "downward_fraction"), 0.5, 1e-12);
        /* a constant never falls to half its maximum: no beam angle */
        const cJSON *beam = cJSON_GetObjectItemCaseSensitive(j, "beam_angle_deg");
        CHECK(cJSON_IsNull(cJSON_GetObjectItemCaseSensitive(beam, "c0_c180")));
        CHECK(cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(j, "warnings")) == 0);
        cJSON_Delete(j);
    }
    /* relative photometry: lamp flux and LOR known */
    j = info("ies_1986_one_per_line.ies");
    if (j) {
        CHECK(strcmp(string(j, "version"), "LM-63-1986") == 0);
        CHECK_REL(number(j, "lamp_flux_lm"), 1000.0, 0.0);
        CHECK_REL(number(j, "lor"), number(j, "flux_lm") / 1000.0, 1e-12);
        cJSON_Delete(j);
    }
    /* EULUMDAT: Mc and Ng as written */
    j = info("ldt_comma_blank_crlf.ldt");
    if (j) {
        CHECK(strcmp(string(j, "format"), "EULUMDAT") == 0);
        CHECK(strcmp(string(j, "symmetry"), "quadrant") == 0);
        CHECK(number(j, "c_planes") == 4.0 && number(j, "gamma_angles") == 4.0);
        cJSON_Delete(j);
    }
    /* a warning is listed */
    j = info("warn_seam.ies");
    if (j) {
        const cJSON *w = cJSON_GetObjectItemCaseSensitive(j, "warnings");
        /* {"code", "line", "message"}: the seam row's code and the line of its first value */
        const cJSON *w0 = cJSON_GetArrayItem(w, 0);
        const cJSON *code = cJSON_GetObjectItemCaseSensitive(w0, "code");
        const cJSON *line = cJSON_GetObjectItemCaseSensitive(w0, "line");
        const cJSON *message = cJSON_GetObjectItemCaseSensitive(w0, "message");
        CHECK(cJSON_GetArraySize(w) == 1 && cJSON_IsString(code) && strcmp(code->valuestring, "seam-differs") == 0);
        CHECK(cJSON_IsNumber(line) && line->valuedouble >= 1.0);
        CHECK(cJSON_IsString(message) && strstr(message->valuestring, "H = 360"));
        char at[32];
        snprintf(at, sizeof at, ":%d:", cJSON_IsNumber(line) ? (int)line->valuedouble : -1);
        CHECK(cJSON_IsString(message) && strstr(message->valuestring, at));
        cJSON_Delete(j);
    }
    /* the asymmetric fixture's maximum: IES H = 90 is frame C = 270 */
    j = info("asym_h90_peak.ies");
    if (j) {
        const cJSON *d = cJSON_GetObjectItemCaseSensitive(j, "max_intensity_direction");
        CHECK_REL(cJSON_GetObjectItemCaseSensitive(d, "c_deg")->valuedouble, 270.0, 0.0);
        CHECK_REL(cJSON_GetObjectItemCaseSensitive(d, "gamma_deg")->valuedouble, 45.0, 0.0);
        cJSON_Delete(j);
    }
}

/* Latin-1 text in the file becomes valid UTF-8 in the JSON. */
static void test_latin1(void)
{
    cJSON *j = info("ies_crlf_latin1_ctrlz.ies");
    if (!j) return;
    const cJSON *kw = cJSON_GetObjectItemCaseSensitive(j, "keywords");
    int found = 0;
    for (const cJSON *k = kw ? kw->child : NULL; k; k = k->next) {
        const cJSON *v = cJSON_GetObjectItemCaseSensitive(k, "value");
        if (cJSON_IsString(v) && strcmp(v->valuestring, "Lumi\xc3\xa8re & Fils") == 0) found = 1;
    }
    CHECK(found);
    cJSON_Delete(j);
}

static void test_rejected(void)
{
    int status;
    char *out = run_info("bad_negative_candela.ies", &status);
    CHECK(status == 1);
    CHECK(out && out[0] == '\0');
    free(out);
}

int main(void)
{
    if (!getenv("CANDELA")) {
        fprintf(stderr, "CANDELA (the path of the candela executable) is not set: run this test through ctest\n");
        return 1;
    }
    test_required_keys();
    test_values();
    test_latin1();
    test_rejected();
    return check_finish();
}
