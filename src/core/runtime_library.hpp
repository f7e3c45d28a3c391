// Core stage (below every other): a shared library opened at run time.
//
// Libraries that only some commands need (PROJ for projections that are not built in, SQLite for
// MBTiles) are not linked: every casteljau process would pay for loading and relocating them at
// start-up. They are opened with dlopen by soname on first use instead, and their functions are
// called through a table of pointers (map/proj_library.hpp, map/sqlite_library.hpp).
// RuntimeLibrary fills such a table; open_once() opens a library once per process. RuntimeLibrary
// is not thread-safe by itself; open_once() is.
#pragma once

#include <mutex>
#include <string>
#include <type_traits>

#include "casteljau/error.hpp"

namespace casteljau::platform {

class RuntimeLibrary {
public:
    // Opens `soname` (RTLD_NOW | RTLD_LOCAL); `name` is what error messages call it ("PROJ").
    // The library stays loaded for the life of the process (objects it made may outlive any scope).
    RuntimeLibrary(const char* name, const char* soname);

    // Sets fn to the library's function `symbol` (nullptr, and error() says so, when missing).
    template <class Fn>
    void get(Fn& fn, const char* symbol) {
        static_assert(std::is_pointer_v<Fn>, "a function pointer");
        fn = reinterpret_cast<Fn>(find(symbol));
    }

    // Empty when the library opened and every symbol asked for was found; otherwise the first
    // failure, naming the library and its soname.
    const std::string& error() const { return error_; }

private:
    void* find(const char* symbol);
    void* handle_ = nullptr;
    std::string label_;  // "PROJ (libproj.so.25)"
    std::string error_;
};

// The table of a library opened on the first call: `fill(lib, api)` looks up its functions
// (lib.get). Every call returns the same table, or throws Error(ErrorKind::Io) with the first
// failure (the library or a function missing). Each call site (each `fill` lambda) has its own
// table. Thread-safe.
template <class Api, class Fill>
const Api& open_once(const char* name, const char* soname, Fill fill) {
    static std::once_flag once;
    static Api api{};
    static std::string error;
    std::call_once(once, [&] {
        RuntimeLibrary lib(name, soname);
        fill(lib, api);
        error = lib.error();
    });
    if (!error.empty()) throw Error(ErrorKind::Io, error);
    return api;
}

}  // namespace casteljau::platform
