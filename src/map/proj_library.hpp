// Map stage: PROJ, loaded when a projection first needs it.
//
// libproj brings about 35 more shared libraries with it (curl, TLS, Kerberos, LDAP, TIFF, ...);
// linked directly, every casteljau process would pay for loading and relocating them at start-up
// (about 5 ms, most of a `casteljau text` run) although only a PROJ projection uses them. So
// PROJ is opened with dlopen by its soname (CASTELJAU_PROJ_SONAME, from the PROJ found at build
// time) the first time a projection that is not built in is parsed, and its functions are called
// through this table. Thread-safe: the library is opened once (std::call_once).
#pragma once

#include <proj.h>

namespace casteljau::proj_library {

// The PROJ functions casteljau calls, with PROJ's own signatures.
struct Api {
    decltype(&::proj_context_create) context_create;
    decltype(&::proj_context_destroy) context_destroy;
    decltype(&::proj_log_level) log_level;
    decltype(&::proj_create) create;
    decltype(&::proj_is_crs) is_crs;
    decltype(&::proj_create_crs_to_crs) create_crs_to_crs;
    decltype(&::proj_normalize_for_visualization) normalize_for_visualization;
    decltype(&::proj_angular_input) angular_input;
    decltype(&::proj_destroy) destroy;
    decltype(&::proj_errno_reset) errno_reset;
    decltype(&::proj_errno) errno_of;
    decltype(&::proj_trans) trans;
};

// The loaded library. Throws Error(ErrorKind::Io) naming the library when it cannot be opened
// or lacks a function (every later call throws the same).
const Api& api();

}  // namespace casteljau::proj_library
