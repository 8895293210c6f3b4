/* report_html.c - the document as HTML (report_html.h). */
#include "report/report_html.h"

#include <stdlib.h>
#include <string.h>

static void put_escaped(FILE *fp, const char *s)
{
    for (; s && *s; ++s) {
        if (*s == '&') fputs("&amp;", fp);
        else if (*s == '<') fputs("&lt;", fp);
        else if (*s == '>') fputs("&gt;", fp);
        else if (*s == '"') fputs("&quot;", fp);
        else if ((unsigned char)*s >= 0x20 || *s == '\n' || *s == '\t') fputc(*s, fp);
    }
}

/* RFC 4648 base64 of n bytes. */
static void put_base64(FILE *fp, const unsigned char *data, size_t n)
{
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < n; i += 3) {
        unsigned v = (unsigned)data[i] << 16 | (i + 1 < n ? (unsigned)data[i + 1] << 8 : 0u) |
                     (i + 2 < n ? (unsigned)data[i + 2] : 0u);
        fputc(alphabet[v >> 18 & 63], fp);
        fputc(alphabet[v >> 12 & 63], fp);
        fputc(i + 1 < n ? alphabet[v >> 6 & 63] : '=', fp);
        fputc(i + 2 < n ? alphabet[v & 63] : '=', fp);
    }
}

static const char style[] =
    "body{font-family:'DejaVu Sans',sans-serif;font-size:10pt;color:#111;max-width:190mm;margin:12mm auto;}\n"
    "h1{font-size:20pt;margin:40mm 0 10mm 0;}h2{font-size:14pt;margin-top:8mm;}h3{font-size:11pt;}\n"
    "table{border-collapse:collapse;margin:3mm 0;}td,th{border:1px solid #bbb;padding:2px 5px;vertical-align:top;}\n"
    "th{background:#eee;text-align:left;}td.num{text-align:right;}\n"
    "td.pass{color:#063;font-weight:bold;}td.fail{color:#b00;font-weight:bold;}\n"
    "img{display:block;max-width:100%;height:auto;margin:3mm 0;}\n"
    ".break{break-before:page;}\n"
    "@page{size:A4;margin:14mm;}\n"
    "@media print{body{margin:0;max-width:none;}}\n";

/* A cell is a number (right-aligned) when it starts with a digit, or a sign
 * and a digit, and is short with at most a unit after it ("2118 lm", "0.36 %"). */
static int numeric(const char *s)
{
    if (!s || strlen(s) > 16 || strchr(s, ' ') != strrchr(s, ' ')) return 0;
    if (*s == '-' || *s == '+') ++s;
    return *s >= '0' && *s <= '9';
}

static void put_table(FILE *fp, const cdl_report_block *b)
{
    fputs("<table>\n", fp);
    for (size_t r = 0; r < b->rows; ++r) {
        fputs("<tr>", fp);
        for (size_t c = 0; c < b->columns; ++c) {
            const char *text = b->cells[r * b->columns + c];
            int head = b->header && r == 0;
            int verdict = cdl_report_cell_verdict(text);
            if (head) fputs("<th>", fp);
            else if (!b->header && c == 0) fputs("<th>", fp);
            else if (verdict) fputs(verdict > 0 ? "<td class=\"pass\">" : "<td class=\"fail\">", fp);
            else fputs(b->header && numeric(text) ? "<td class=\"num\">" : "<td>", fp);
            put_escaped(fp, text);
            fputs(head || (!b->header && c == 0) ? "</th>" : "</td>", fp);
        }
        fputs("</tr>\n", fp);
    }
    fputs("</table>\n", fp);
}

static cdl_status put_figure(FILE *fp, const cdl_report_block *b, cdl_error *err)
{
    char *svg = NULL;
    size_t size = 0;
    cdl_status st = cdl_figure_svg(&b->figure, &svg, &size, err);
    if (st != CDL_OK) return st;
    /* CSS pixels are 3/4 of a point */
    fprintf(fp, "<img width=\"%.0f\" height=\"%.0f\" alt=\"", b->figure.width * b->figure_scale * 4.0 / 3.0,
            b->figure.height * b->figure_scale * 4.0 / 3.0);
    put_escaped(fp, b->figure.title);
    fputs("\" src=\"data:image/svg+xml;base64,", fp);
    put_base64(fp, (const unsigned char *)svg, size);
    fputs("\">\n", fp);
    free(svg);
    return CDL_OK;
}

cdl_status cdl_report_html_write(const cdl_report_document *d, cdl_atomic_file *file, cdl_error *err)
{
    FILE *fp = file->fp;
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>", fp);
    put_escaped(fp, d->title);
    fprintf(fp, "</title>\n<meta name=\"generator\" content=\"Candela %s\">\n<style>\n%s</style>\n</head>\n<body>\n",
            CANDELA_VERSION, style);
    int page_break = 0;
    for (size_t k = 0; k < d->count; ++k) {
        const cdl_report_block *b = &d->blocks[k];
        const char *cls = page_break ? " class=\"break\"" : "";
        switch (b->kind) {
        case CDL_BLOCK_PAGE_BREAK:
            page_break = 1;
            continue;
        case CDL_BLOCK_HEADING:
            fprintf(fp, "<h%d%s>", b->level, cls);
            put_escaped(fp, b->text);
            fprintf(fp, "</h%d>\n", b->level);
            break;
        case CDL_BLOCK_PARAGRAPH:
            fprintf(fp, "<p%s>", cls);
            put_escaped(fp, b->text);
            fputs("</p>\n", fp);
            break;
        case CDL_BLOCK_TABLE:
            if (page_break) fputs("<div class=\"break\"></div>\n", fp);
            put_table(fp, b);
            break;
        case CDL_BLOCK_FIGURE: {
            if (page_break) fputs("<div class=\"break\"></div>\n", fp);
            cdl_status st = put_figure(fp, b, err);
            if (st != CDL_OK) return st;
            break;
        }
        }
        page_break = 0;
    }
    fputs("</body>\n</html>\n", fp);
    return CDL_OK;
}
