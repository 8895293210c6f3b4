/* bench_report.h - the files of `candela bench`: bench.csv and bench.svg.
 *
 * bench.csv: a header line
 *   label,method,quality,target_error,seconds,rays,records,rms_rel_error,max_rel_error,within_2_sigma
 * then one row a measured rung (skipped rungs are left out: every field
 * past the third column parses as a number, but for rms_rel_error of a
 * rung below what the reference resolves, which is "<ref" in place of a
 * figure that would say little). Errors and within_2_sigma are fractions;
 * target_error, errors and shares with 6 significant digits, seconds with
 * 3 decimals.
 *
 * bench.svg (and bench.png): RMS relative error (%) against wall seconds, both axes
 * logarithmic with decade ticks, one polyline per method through its
 * rungs (each labelled, with a bar of +- the RMS's standard error when
 * the reference is a sample of the points), and the reference's own
 * stated RMS as a dashed horizontal floor. Both files are written atomically (atomic_file.h).
 */
#ifndef CANDELA_SOLVER_BENCH_REPORT_H
#define CANDELA_SOLVER_BENCH_REPORT_H

#include <stddef.h>

#include "base/error.h"
#include "solver/bench/bench_ladder.h"

cdl_status cdl_bench_report_write_csv(const char *path, const cdl_bench_row *rows, size_t count, cdl_error *err);

/* reference_rms: the reference's stated RMS (fraction), drawn as the floor. */
cdl_status cdl_bench_report_write_svg(const char *path, const cdl_bench_row *rows, size_t count,
                                      double reference_rms, cdl_error *err);

/* The same plot as bench.png (760 x 500; lines drawn pixel by pixel, text
 * by pango, graphics/raster_canvas.h; the y axis's title stands above the axis). */
cdl_status cdl_bench_report_write_png(const char *path, const cdl_bench_row *rows, size_t count,
                                      double reference_rms, cdl_error *err);

#endif
