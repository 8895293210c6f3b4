/* report_builder.c - adding blocks to the report's document (report_builder.h). */
#include "report/report_builder.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

cdl_report_block *cdl_report_add_block(cdl_report_builder *b, cdl_report_block_kind kind)
{
    cdl_report_document *d = b->doc;
    if (d->count == d->capacity) {
        size_t cap = d->capacity ? 2 * d->capacity : 32;
        cdl_report_block *grown = realloc(d->blocks, cap * sizeof *grown);
        if (!grown) {
            b->failed = 1;
            return NULL;
        }
        d->blocks = grown;
        d->capacity = cap;
    }
    cdl_report_block *block = &d->blocks[d->count++];
    memset(block, 0, sizeof *block);
    block->kind = kind;
    return block;
}

static char *vformat(cdl_report_builder *b, const char *fmt, va_list ap)
{
    va_list copy;
    va_copy(copy, ap);
    int n = vsnprintf(NULL, 0, fmt, copy);
    va_end(copy);
    char *text = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (!text) {
        b->failed = 1;
        return NULL;
    }
    vsnprintf(text, (size_t)n + 1, fmt, ap);
    return text;
}

void cdl_report_text(cdl_report_builder *b, cdl_report_block_kind kind, int level, const char *fmt, ...)
{
    cdl_report_block *block = cdl_report_add_block(b, kind);
    if (!block) return;
    block->level = level;
    va_list ap;
    va_start(ap, fmt);
    block->text = vformat(b, fmt, ap);
    va_end(ap);
}

cdl_report_block *cdl_report_table(cdl_report_builder *b, size_t columns, size_t rows, int header)
{
    cdl_report_block *block = cdl_report_add_block(b, CDL_BLOCK_TABLE);
    if (!block) return NULL;
    block->columns = columns;
    block->rows = rows;
    block->header = header;
    block->cells = calloc(columns * rows, sizeof *block->cells);
    if (!block->cells) b->failed = 1;
    return block;
}

void cdl_report_cell(cdl_report_builder *b, cdl_report_block *t, size_t row, size_t column, const char *fmt, ...)
{
    if (!t || !t->cells) return;
    va_list ap;
    va_start(ap, fmt);
    free(t->cells[row * t->columns + column]); /* a cell may be written again */
    t->cells[row * t->columns + column] = vformat(b, fmt, ap);
    va_end(ap);
}

void cdl_report_figure(cdl_report_builder *b, cdl_figure f, double scale)
{
    cdl_report_block *block = cdl_report_add_block(b, CDL_BLOCK_FIGURE);
    if (!block) return;
    block->figure = f;
    block->figure_scale = scale;
}

