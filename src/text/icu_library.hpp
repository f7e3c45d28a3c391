// Internal (text module): ICU's common library, opened when text first needs it.
//
// Line breaking (UAX #14) comes from ICU (libicuuc). Linked directly, its thousands of symbols
// (and its 30 MB data library) would be loaded and bound at every process's start-up, including
// those that draw one line without wrapping; so it is opened with dlopen by the soname of the ICU
// the build found (libicuuc.so.MAJOR) the first time a wrapped paragraph needs it, and its
// functions are called through this table (platform/runtime_library.hpp). Thread-safe: the
// library is opened once.
#pragma once

#include <unicode/ubrk.h>

namespace casteljau::icu_library {

// The ICU functions casteljau calls, with ICU's own signatures (ICU's headers rename them with
// its version suffix, e.g. ubrk_open_72, and so does the lookup).
struct Api {
    decltype(&::ubrk_open) break_open;
    decltype(&::ubrk_first) break_first;
    decltype(&::ubrk_next) break_next;
    decltype(&::ubrk_close) break_close;
};

// The loaded library, or null when it cannot be opened or lacks a function (callers then fall
// back to simpler rules).
const Api* api();

}  // namespace casteljau::icu_library
