/* version.c - the library's release and ABI version (candela/candela.h). */
#include "candela/candela.h"

const char *cdl_version(void)
{
    return CANDELA_VERSION;
}

int cdl_abi_version(void)
{
    return CANDELA_ABI_VERSION;
}
