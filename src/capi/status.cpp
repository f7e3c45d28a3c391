// C API: version, status names, the thread-local last-error message and casteljau_free (casteljau.h).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "capi/handles.hpp"

namespace casteljau::capi {

namespace {
// The message of this thread's last failed call; thread-local, so no state is shared.
thread_local std::string t_last_error;
}  // namespace

casteljau_status fail(casteljau_status status, const char* message) noexcept {
    try {
        t_last_error = message ? message : "";
    } catch (...) {
        t_last_error.clear();  // keeps whatever fit; clear() never throws
    }
    return status;
}

casteljau_status status_of(ErrorKind kind) noexcept {
    switch (kind) {
        case ErrorKind::InvalidArgument: return CASTELJAU_ERROR_INVALID_ARGUMENT;
        case ErrorKind::Parse: return CASTELJAU_ERROR_PARSE;
        case ErrorKind::InvalidData: return CASTELJAU_ERROR_INVALID_DATA;
        case ErrorKind::Limit: return CASTELJAU_ERROR_LIMIT;
        case ErrorKind::Io: return CASTELJAU_ERROR_IO;
        case ErrorKind::Font: return CASTELJAU_ERROR_FONT;
    }
    return CASTELJAU_ERROR_INTERNAL;
}

void check_range(double v, double lo, double hi, const char* what) {
    if (!(v >= lo && v <= hi)) {
        char range[64];
        std::snprintf(range, sizeof range, "[%g, %g]", lo, hi);
        throw Error(ErrorKind::InvalidArgument, std::string(what) + " must be in " + range);
    }
}

}  // namespace casteljau::capi

extern "C" {

#define CASTELJAU_STR2(x) #x
#define CASTELJAU_STR(x) CASTELJAU_STR2(x)
const char* casteljau_version_string(void) {
    return CASTELJAU_STR(CASTELJAU_VERSION_MAJOR) "." CASTELJAU_STR(CASTELJAU_VERSION_MINOR) "." CASTELJAU_STR(
        CASTELJAU_VERSION_PATCH);
}

int casteljau_version(void) { return CASTELJAU_VERSION; }

const char* casteljau_last_error(void) { return casteljau::capi::t_last_error.c_str(); }

const char* casteljau_status_name(casteljau_status status) {
    switch (status) {
        case CASTELJAU_OK: return "ok";
        case CASTELJAU_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case CASTELJAU_ERROR_PARSE: return "parse error";
        case CASTELJAU_ERROR_INVALID_DATA: return "invalid data";
        case CASTELJAU_ERROR_LIMIT: return "limit exceeded";
        case CASTELJAU_ERROR_IO: return "i/o error";
        case CASTELJAU_ERROR_FONT: return "font error";
        case CASTELJAU_ERROR_OUT_OF_MEMORY: return "out of memory";
        case CASTELJAU_ERROR_INTERNAL: return "internal error";
        case CASTELJAU_ERROR_CANCELLED: return "cancelled";
    }
    return "unknown status";
}

void casteljau_free(void* memory) { std::free(memory); }

}  // extern "C"
