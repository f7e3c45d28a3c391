// Text stage: opening ICU on first use (see icu_library.hpp).
#include "text/icu_library.hpp"

#include <unicode/uvernum.h>

#include "casteljau/error.hpp"
#include "core/runtime_library.hpp"

// The name a macro expands to, as a string: ICU's headers define ubrk_open as ubrk_open_72.
#define CASTELJAU_ICU_NAME_OF(x) CASTELJAU_ICU_STRING(x)
#define CASTELJAU_ICU_STRING(x) #x

namespace casteljau::icu_library {

const Api* api() {
    try {
        return &platform::open_once<Api>("ICU", "libicuuc.so." CASTELJAU_ICU_NAME_OF(U_ICU_VERSION_MAJOR_NUM),
                                         [](platform::RuntimeLibrary& lib, Api& a) {
                                             lib.get(a.break_open, CASTELJAU_ICU_NAME_OF(ubrk_open));
                                             lib.get(a.break_first, CASTELJAU_ICU_NAME_OF(ubrk_first));
                                             lib.get(a.break_next, CASTELJAU_ICU_NAME_OF(ubrk_next));
                                             lib.get(a.break_close, CASTELJAU_ICU_NAME_OF(ubrk_close));
                                         });
    } catch (const Error&) { return nullptr; }
}

}  // namespace casteljau::icu_library
