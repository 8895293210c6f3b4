/* JSON numbers that read back as the doubles written (solver/output/
 * json_numbers.h): a tree of doubles spread over every magnitude, printed
 * after cdl_json_numbers_exact and parsed again, gives back every double
 * bit for bit, as the CSVs' digits do; small integers stay integers in the
 * text, non-finite numbers stay null, strings and nesting are untouched. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "base/rng.h"
#include "solver/output/grid_result.h"
#include "solver/output/json_numbers.h"

int main(void)
{
    enum { N = 20000 };
    double *v = malloc(N * sizeof *v);
    cJSON *root = cJSON_CreateObject(), *list = cJSON_AddArrayToObject(root, "values");
    cdl_rng_key key = {11, 5};
    for (int k = 0; k < N; ++k) {
        double u[2];
        cdl_rng_uniform2(key, (uint64_t)k, u);
        /* mantissas of every bit pattern, exponents from 1e-300 to 1e300 */
        v[k] = (u[0] - 0.5) * pow(10.0, 600.0 * u[1] - 300.0);
        cJSON_AddItemToArray(list, cJSON_CreateNumber(v[k]));
    }
    /* the case that showed it: a UGR cJSON alone wrote with 15 digits, one
     * bit off */
    v[0] = 25.378118616655602;
    cJSON_SetNumberValue(cJSON_GetArrayItem(list, 0), v[0]);
    cJSON *nested = cJSON_AddObjectToObject(root, "nested");
    cJSON_AddNumberToObject(nested, "third", 1.0 / 3.0);
    cJSON_AddNumberToObject(nested, "count", 657);
    cJSON_AddNumberToObject(nested, "nan", NAN);
    cJSON_AddStringToObject(nested, "name", "0.1");
    cdl_json_numbers_exact(root);
    char *text = cJSON_PrintUnformatted(root);
    CHECK(text != NULL);
    cJSON_Delete(root);
    cJSON *back = text ? cJSON_Parse(text) : NULL;
    CHECK(back != NULL);
    if (back) {
        cJSON *bl = cJSON_GetObjectItem(back, "values");
        int differ = 0;
        for (int k = 0; k < N; ++k) differ += cJSON_GetArrayItem(bl, k)->valuedouble != v[k];
        CHECK_MSG(differ == 0, "%d of %d doubles read back otherwise", differ, N);
        cJSON *bn = cJSON_GetObjectItem(back, "nested");
        CHECK(cJSON_GetObjectItem(bn, "third")->valuedouble == 1.0 / 3.0);
        CHECK(cJSON_IsNull(cJSON_GetObjectItem(bn, "nan")));
        CHECK(strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(bn, "name")), "0.1") == 0);
        /* the text: the integer as an integer, the UGR with the CSV's digits */
        char csv[CDL_CSV_NUMBER_SIZE];
        cdl_csv_format_number(v[0], csv);
        CHECK(strstr(text, "\"count\":657,") != NULL);
        CHECK(strstr(text, csv) != NULL && strcmp(csv, "25.378118616655602") == 0);
        cJSON_Delete(back);
    }
    free(text);
    free(v);
    return check_finish();
}
