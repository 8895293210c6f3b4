/* error.c - status codes and messages. */
#include "base/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void cdl_error_clear(cdl_error *err)
{
    if (!err) return;
    err->status = CDL_OK;
    err->message[0] = '\0';
}

cdl_status cdl_error_set(cdl_error *err, cdl_status status, const char *fmt, ...)
{
    if (!err) return status;
    err->status = status;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return status;
}

cdl_status cdl_error_prefix(cdl_error *err, const char *fmt, ...)
{
    if (!err) return CDL_ERR_INTERNAL;
    char prefix[CDL_ERROR_MESSAGE_SIZE];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(prefix, sizeof prefix, fmt, ap);
    va_end(ap);
    size_t plen = strlen(prefix), mlen = strlen(err->message), cap = sizeof err->message - 1;
    if (plen > cap) plen = cap;
    if (plen + mlen > cap) mlen = cap - plen;
    memmove(err->message + plen, err->message, mlen);
    memcpy(err->message, prefix, plen);
    err->message[plen + mlen] = '\0';
    return err->status;
}

cdl_status cdl_error_out_of_memory(cdl_error *err)
{
    return cdl_error_set(err, CDL_ERR_INTERNAL, "out of memory");
}

const char *cdl_status_name(cdl_status status)
{
    switch (status) {
    case CDL_OK: return "ok";
    case CDL_ERR_INPUT: return "bad input";
    case CDL_ERR_USAGE: return "usage error";
    case CDL_ERR_INTERNAL: return "internal or resource failure";
    case CDL_ERR_CANCELLED: return "cancelled";
    }
    return "unknown status";
}
