/* exr_image.c - OpenEXR Core reading and writing of float images. */
#include "base/error_report.h"
#include "solver/scene/exr_image.h"

#include <errno.h>
#include <openexr.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The library must not print: errors are reported through return codes,
 * which we turn into messages naming the file. */
static void silent_error_handler(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    (void)code;
    (void)msg;
}

static exr_context_initializer_t quiet_initializer(void)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = silent_error_handler;
    return init;
}

static cdl_status exr_fail(cdl_error *err, cdl_status st, const char *path, const char *what, exr_result_t rv)
{
    return cdl_error_set(err, st, "%s: %s: %s (%s)", path, what, exr_get_default_error_message(rv),
                         exr_get_error_code_as_string(rv));
}

cdl_status cdl_exr_write(const char *path, int width, int height, const cdl_exr_channel *channels,
                         size_t channel_count, const cdl_exr_attribute *attributes, size_t attribute_count,
                         cdl_error *err)
{
    if (width <= 0 || height <= 0 || channel_count == 0)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: an EXR image needs a size and a channel", path);
    exr_context_initializer_t init = quiet_initializer();
    exr_context_t ctx = NULL;
    exr_result_t rv = exr_start_write(&ctx, path, EXR_INTERMEDIATE_TEMP_FILE, &init);
    if (rv != EXR_ERR_SUCCESS) return exr_fail(err, CDL_ERR_INTERNAL, path, "cannot create", rv);

    cdl_status st = CDL_OK;
    const char *stage = "header";
    int part = 0;
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int enc_ready = 0;

    rv = exr_add_part(ctx, "illuminance", EXR_STORAGE_SCANLINE, &part);
    if (rv == EXR_ERR_SUCCESS) rv = exr_initialize_required_attr_simple(ctx, part, width, height, EXR_COMPRESSION_ZIP);
    for (size_t c = 0; rv == EXR_ERR_SUCCESS && c < channel_count; ++c)
        rv = exr_add_channel(ctx, part, channels[c].name, EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR, 1, 1);
    for (size_t a = 0; rv == EXR_ERR_SUCCESS && a < attribute_count; ++a)
        rv = exr_attr_set_string(ctx, part, attributes[a].name, attributes[a].value);
    if (rv == EXR_ERR_SUCCESS) rv = exr_write_header(ctx);

    int32_t lines = 1;
    if (rv == EXR_ERR_SUCCESS) {
        stage = "pixels";
        rv = exr_get_scanlines_per_chunk(ctx, part, &lines);
    }
    for (int y = 0; rv == EXR_ERR_SUCCESS && y < height; y += lines) {
        exr_chunk_info_t cinfo;
        rv = exr_write_scanline_chunk_info(ctx, part, y, &cinfo);
        if (rv != EXR_ERR_SUCCESS) break;
        rv = enc_ready ? exr_encoding_update(ctx, part, &cinfo, &enc)
                       : exr_encoding_initialize(ctx, part, &cinfo, &enc);
        if (rv != EXR_ERR_SUCCESS) break;
        /* The pipeline lists channels sorted by name: match them to ours. */
        for (int16_t i = 0; i < enc.channel_count; ++i) {
            exr_coding_channel_info_t *ch = &enc.channels[i];
            const float *src = NULL;
            for (size_t c = 0; c < channel_count; ++c)
                if (strcmp(ch->channel_name, channels[c].name) == 0) src = channels[c].pixels;
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 4;
            ch->user_line_stride = 4 * width;
            ch->encode_from_ptr = (const uint8_t *)(src + (size_t)y * (size_t)width);
        }
        if (!enc_ready) {
            rv = exr_encoding_choose_default_routines(ctx, part, &enc);
            if (rv != EXR_ERR_SUCCESS) break;
            enc_ready = 1;
        }
        rv = exr_encoding_run(ctx, part, &enc);
    }
    if (enc_ready || enc.channels) exr_encoding_destroy(ctx, &enc);
    if (rv != EXR_ERR_SUCCESS) st = exr_fail(err, CDL_ERR_INTERNAL, path, stage, rv);
    exr_result_t frv = exr_finish(&ctx);
    if (st == CDL_OK && frv != EXR_ERR_SUCCESS) st = exr_fail(err, CDL_ERR_INTERNAL, path, "finish", frv);
    return st;
}

void cdl_exr_image_release(cdl_exr_image *image)
{
    if (!image) return;
    for (size_t c = 0; c < image->channel_count; ++c) {
        if (image->channel_names) free(image->channel_names[c]);
        if (image->channels) free(image->channels[c]);
    }
    free(image->channel_names);
    free(image->channels);
    memset(image, 0, sizeof *image);
}

const float *cdl_exr_image_channel(const cdl_exr_image *image, const char *name)
{
    for (size_t c = 0; c < image->channel_count; ++c)
        if (strcmp(image->channel_names[c], name) == 0) return image->channels[c];
    return NULL;
}

/* Decode one chunk into the output planes. */
static exr_result_t decode_chunk(exr_const_context_t ctx, const exr_chunk_info_t *cinfo, exr_decode_pipeline_t *dec,
                                 int *dec_ready, const cdl_exr_image *img, int min_x, int min_y)
{
    exr_result_t rv = *dec_ready ? exr_decoding_update(ctx, 0, cinfo, dec) : exr_decoding_initialize(ctx, 0, cinfo, dec);
    if (rv != EXR_ERR_SUCCESS) return rv;
    for (int16_t i = 0; i < dec->channel_count; ++i) {
        exr_coding_channel_info_t *ch = &dec->channels[i];
        float *plane = NULL;
        if (ch->data_type != EXR_PIXEL_UINT && ch->x_samples == 1 && ch->y_samples == 1)
            for (size_t c = 0; c < img->channel_count; ++c)
                if (strcmp(img->channel_names[c], ch->channel_name) == 0) plane = img->channels[c];
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
        ch->user_pixel_stride = 4;
        ch->user_line_stride = 4 * img->width;
        ch->decode_to_ptr =
            plane ? (uint8_t *)(plane + (size_t)(cinfo->start_y - min_y) * (size_t)img->width + (size_t)(cinfo->start_x - min_x))
                  : NULL;
    }
    if (!*dec_ready) {
        rv = exr_decoding_choose_default_routines(ctx, 0, dec);
        if (rv != EXR_ERR_SUCCESS) return rv;
        *dec_ready = 1;
    }
    return exr_decoding_run(ctx, 0, dec);
}

cdl_status cdl_exr_read(const char *path, cdl_exr_image *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    /* Say what is wrong with the path itself in words, not as OpenEXR's
     * stream errors ("Error reading from stream" for a folder). */
    struct stat info;
    if (stat(path, &info) != 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: cannot open the OpenEXR image: %s", path, strerror(errno));
    if (!S_ISREG(info.st_mode))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected an OpenEXR image, found a directory or device", path);
    FILE *probe = fopen(path, "rb");
    if (!probe) return cdl_error_set(err, CDL_ERR_INPUT, "%s: cannot open the OpenEXR image: %s", path, strerror(errno));
    fclose(probe);
    exr_context_initializer_t init = quiet_initializer();
    exr_context_t ctx = NULL;
    exr_result_t rv = exr_start_read(&ctx, path, &init);
    if (rv != EXR_ERR_SUCCESS) {
        exr_finish(&ctx);
        return exr_fail(err, CDL_ERR_INPUT, path, "cannot read as OpenEXR", rv);
    }
    cdl_status st = CDL_OK;
    exr_attr_box2i_t dw;
    exr_storage_t storage;
    const exr_attr_chlist_t *chlist = NULL;
    rv = exr_get_data_window(ctx, 0, &dw);
    if (rv == EXR_ERR_SUCCESS) rv = exr_get_storage(ctx, 0, &storage);
    if (rv == EXR_ERR_SUCCESS) rv = exr_get_channels(ctx, 0, &chlist);
    if (rv != EXR_ERR_SUCCESS) {
        st = exr_fail(err, CDL_ERR_INPUT, path, "header", rv);
        goto done;
    }
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s: deep OpenEXR images are not supported", path);
        goto done;
    }
    long long w = (long long)dw.max.x - dw.min.x + 1, h = (long long)dw.max.y - dw.min.y + 1;
    if (w <= 0 || h <= 0 || w * h > (1ll << 30)) {
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s: unsupported data window %lldx%lld", path, w, h);
        goto done;
    }
    out->width = (int)w;
    out->height = (int)h;
    out->channel_names = calloc((size_t)chlist->num_channels, sizeof(char *));
    out->channels = calloc((size_t)chlist->num_channels, sizeof(float *));
    if (!out->channel_names || !out->channels) {
        st = cdl_error_out_of_memory(err);
        goto done;
    }
    for (int c = 0; c < chlist->num_channels; ++c) {
        const exr_attr_chlist_entry_t *e = &chlist->entries[c];
        out->channel_names[c] = malloc((size_t)e->name.length + 1);
        out->channels[c] = calloc((size_t)(w * h), sizeof(float));
        out->channel_count = (size_t)c + 1;
        if (!out->channel_names[c] || !out->channels[c]) {
            st = cdl_error_out_of_memory(err);
            goto done;
        }
        memcpy(out->channel_names[c], e->name.str, (size_t)e->name.length);
        out->channel_names[c][e->name.length] = '\0';
    }

    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int dec_ready = 0;
    if (storage == EXR_STORAGE_SCANLINE) {
        int32_t lines = 1;
        rv = exr_get_scanlines_per_chunk(ctx, 0, &lines);
        for (int y = dw.min.y; rv == EXR_ERR_SUCCESS && y <= dw.max.y; y += lines) {
            exr_chunk_info_t cinfo;
            rv = exr_read_scanline_chunk_info(ctx, 0, y, &cinfo);
            if (rv == EXR_ERR_SUCCESS) rv = decode_chunk(ctx, &cinfo, &dec, &dec_ready, out, dw.min.x, dw.min.y);
        }
    } else {
        int32_t tw = 0, th = 0;
        rv = exr_get_tile_sizes(ctx, 0, 0, 0, &tw, &th);
        if (rv == EXR_ERR_SUCCESS && (tw <= 0 || th <= 0)) rv = EXR_ERR_INVALID_ATTR;
        int tiles_x = rv == EXR_ERR_SUCCESS ? (int)((w + tw - 1) / tw) : 0;
        int tiles_y = rv == EXR_ERR_SUCCESS ? (int)((h + th - 1) / th) : 0;
        for (int ty = 0; rv == EXR_ERR_SUCCESS && ty < tiles_y; ++ty)
            for (int tx = 0; rv == EXR_ERR_SUCCESS && tx < tiles_x; ++tx) {
                exr_chunk_info_t cinfo;
                rv = exr_read_tile_chunk_info(ctx, 0, tx, ty, 0, 0, &cinfo);
                if (rv == EXR_ERR_SUCCESS) rv = decode_chunk(ctx, &cinfo, &dec, &dec_ready, out, dw.min.x, dw.min.y);
            }
    }
    if (dec_ready || dec.channels) exr_decoding_destroy(ctx, &dec);
    if (rv != EXR_ERR_SUCCESS) st = exr_fail(err, CDL_ERR_INPUT, path, "pixel data", rv);

done:
    exr_finish(&ctx);
    if (st != CDL_OK) cdl_exr_image_release(out);
    return st;
}

cdl_status cdl_exr_read_string_attribute(const char *path, const char *name, char *buf, size_t size,
                                         cdl_error *err)
{
    exr_context_initializer_t init = quiet_initializer();
    exr_context_t ctx = NULL;
    exr_result_t rv = exr_start_read(&ctx, path, &init);
    if (rv != EXR_ERR_SUCCESS) {
        exr_finish(&ctx);
        return exr_fail(err, CDL_ERR_INPUT, path, "cannot read as OpenEXR", rv);
    }
    int32_t len = 0;
    const char *value = NULL;
    rv = exr_attr_get_string(ctx, 0, name, &len, &value);
    cdl_status st = CDL_OK;
    if (rv != EXR_ERR_SUCCESS || !value)
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s: no string attribute '%s'", path, name);
    else
        snprintf(buf, size, "%.*s", (int)len, value);
    exr_finish(&ctx);
    return st;
}
