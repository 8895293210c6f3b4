/* ugr_table_conditions.h - the standard rooms and reflectances of CIE
 * 190:2010's UGR table (not public: a table carries its own, ugr_table.h).
 * Constant data; thread-safe. */
#ifndef CANDELA_GLARE_UGR_TABLE_CONDITIONS_H
#define CANDELA_GLARE_UGR_TABLE_CONDITIONS_H

#include "glare/ugr_table.h"

/* The rooms, X and Y in multiples of H, in the catalogue's order. */
extern const double cdl_ugr_table_rooms[CDL_UGR_TABLE_ROOMS][2];
/* The reflectance sets: ceiling, walls, floor. */
extern const double cdl_ugr_table_reflectances[CDL_UGR_TABLE_REFLECTANCE_SETS][3];

#endif
