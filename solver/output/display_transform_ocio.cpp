// display_transform_ocio.cpp - the only file that includes OpenColorIO. It
// exposes the C API of display_transform.h; no exception crosses it.
#include "base/error_report.h"
#include "solver/output/display_transform.h"

#include <OpenColorIO/OpenColorIO.h>

#include <exception>
#include <new>

namespace OCIO = OCIO_NAMESPACE;

struct cdl_display_transform {
    OCIO::ConstCPUProcessorRcPtr cpu;
};

extern "C" cdl_status cdl_display_transform_open(const char *config_path, const char *source, const char *display,
                                                 const char *view, cdl_display_transform **out, cdl_error *err)
{
    *out = nullptr;
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(config_path);
        OCIO::ConstProcessorRcPtr proc =
            config->getProcessor(source, display, view, OCIO::TRANSFORM_DIR_FORWARD);
        cdl_display_transform *t = new (std::nothrow) cdl_display_transform;
        if (!t) return cdl_error_out_of_memory(err);
        t->cpu = proc->getDefaultCPUProcessor();
        *out = t;
        return CDL_OK;
    } catch (const std::exception &e) {
        return cdl_error_set(err, CDL_ERR_INPUT, "OpenColorIO config %s (%s -> %s/%s): %s", config_path, source,
                             display, view, e.what());
    } catch (...) {
        return cdl_error_set(err, CDL_ERR_INTERNAL, "OpenColorIO: unknown exception");
    }
}

extern "C" cdl_status cdl_display_transform_apply(const cdl_display_transform *t, float *rgb, size_t pixel_count,
                                                  cdl_error *err)
{
    try {
        OCIO::PackedImageDesc desc(rgb, (long)pixel_count, 1, 3);
        t->cpu->apply(desc);
        return CDL_OK;
    } catch (const std::exception &e) {
        return cdl_error_set(err, CDL_ERR_INTERNAL, "OpenColorIO: %s", e.what());
    } catch (...) {
        return cdl_error_set(err, CDL_ERR_INTERNAL, "OpenColorIO: unknown exception");
    }
}

extern "C" void cdl_display_transform_release(cdl_display_transform *t)
{
    delete t;
}
