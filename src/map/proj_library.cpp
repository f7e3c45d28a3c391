// Map stage: opening PROJ on first use (see proj_library.hpp).
#include "map/proj_library.hpp"

#include "core/runtime_library.hpp"

#ifndef CASTELJAU_PROJ_SONAME
#define CASTELJAU_PROJ_SONAME "libproj.so"
#endif

namespace casteljau::proj_library {

const Api& api() {
    return platform::open_once<Api>("PROJ", CASTELJAU_PROJ_SONAME, [](platform::RuntimeLibrary& lib, Api& a) {
        lib.get(a.context_create, "proj_context_create");
        lib.get(a.context_destroy, "proj_context_destroy");
        lib.get(a.log_level, "proj_log_level");
        lib.get(a.create, "proj_create");
        lib.get(a.is_crs, "proj_is_crs");
        lib.get(a.create_crs_to_crs, "proj_create_crs_to_crs");
        lib.get(a.normalize_for_visualization, "proj_normalize_for_visualization");
        lib.get(a.angular_input, "proj_angular_input");
        lib.get(a.destroy, "proj_destroy");
        lib.get(a.errno_reset, "proj_errno_reset");
        lib.get(a.errno_of, "proj_errno");
        lib.get(a.trans, "proj_trans");
    });
}

}  // namespace casteljau::proj_library
