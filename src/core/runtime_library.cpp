// Core stage: a shared library opened at run time (see runtime_library.hpp).
#include "core/runtime_library.hpp"

#include <dlfcn.h>

namespace casteljau::platform {

RuntimeLibrary::RuntimeLibrary(const char* name, const char* soname) : label_(std::string(name) + " (" + soname + ")") {
    handle_ = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
        const char* why = dlerror();
        error_ = "cannot load " + label_ + ": " + (why ? why : "unknown error");
    }
}

void* RuntimeLibrary::find(const char* symbol) {
    if (!handle_) return nullptr;
    void* p = dlsym(handle_, symbol);
    if (!p && error_.empty()) error_ = label_ + " lacks " + symbol;
    return p;
}

}  // namespace casteljau::platform
