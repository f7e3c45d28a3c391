// Map stage: opening PROJ on first use (see proj_library.hpp).
#include "map/proj_library.hpp"

#include <dlfcn.h>

#include <mutex>
#include <string>

#include "casteljau/error.hpp"

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
    void* lib = dlopen(CASTELJAU_PROJ_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        const char* why = dlerror();
        l.error = std::string("cannot load PROJ (" CASTELJAU_PROJ_SONAME "): ") + (why ? why : "unknown error");
        return l;
    }
    // The library stays loaded for the life of the process (its contexts may outlive any scope).
    auto get = [&](auto& fn, const char* name) {
        fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(lib, name));
        if (!fn && l.error.empty()) l.error = std::string("PROJ (" CASTELJAU_PROJ_SONAME ") lacks ") + name;
    };
    get(l.api.context_create, "proj_context_create");
    get(l.api.context_destroy, "proj_context_destroy");
    get(l.api.log_level, "proj_log_level");
    get(l.api.create, "proj_create");
    get(l.api.is_crs, "proj_is_crs");
    get(l.api.create_crs_to_crs, "proj_create_crs_to_crs");
    get(l.api.normalize_for_visualization, "proj_normalize_for_visualization");
    get(l.api.angular_input, "proj_angular_input");
    get(l.api.destroy, "proj_destroy");
    get(l.api.errno_reset, "proj_errno_reset");
    get(l.api.errno_of, "proj_errno");
    get(l.api.trans, "proj_trans");
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
