// Map stage: opening PROJ on first use (see proj_library.hpp).
#include "map/proj_library.hpp"

#include <mutex>
#include <string>

#include "casteljau/error.hpp"
#include "platform/runtime_library.hpp"

#ifndef CASTELJAU_PROJ_SONAME
#define CASTELJAU_PROJ_SONAME "libproj.so"
#endif

namespace casteljau::proj_library {

namespace {

struct Loaded {
    Api api{};
    std::string error;  // empty when every function was found
};

Loaded load() {
    Loaded l;
    platform::RuntimeLibrary lib("PROJ", CASTELJAU_PROJ_SONAME);
    lib.get(l.api.context_create, "proj_context_create");
    lib.get(l.api.context_destroy, "proj_context_destroy");
    lib.get(l.api.log_level, "proj_log_level");
    lib.get(l.api.create, "proj_create");
    lib.get(l.api.is_crs, "proj_is_crs");
    lib.get(l.api.create_crs_to_crs, "proj_create_crs_to_crs");
    lib.get(l.api.normalize_for_visualization, "proj_normalize_for_visualization");
    lib.get(l.api.angular_input, "proj_angular_input");
    lib.get(l.api.destroy, "proj_destroy");
    lib.get(l.api.errno_reset, "proj_errno_reset");
    lib.get(l.api.errno_of, "proj_errno");
    lib.get(l.api.trans, "proj_trans");
    l.error = lib.error();
    return l;
}

}  // namespace

const Api& api() {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = load(); });
    if (!loaded.error.empty()) throw Error(ErrorKind::Io, loaded.error);
    return loaded.api;
}

}  // namespace casteljau::proj_library
