// Formats stage: opening SQLite on first use (see sqlite_library.hpp).
#include "formats/sqlite_library.hpp"

#include <mutex>
#include <string>

#include "casteljau/error.hpp"
#include "platform/runtime_library.hpp"

#ifndef CASTELJAU_SQLITE_SONAME
#define CASTELJAU_SQLITE_SONAME "libsqlite3.so.0"
#endif

namespace casteljau::sqlite_library {

namespace {

struct Loaded {
    Api api{};
    std::string error;  // empty when every function was found
};

Loaded load() {
    Loaded l;
    platform::RuntimeLibrary lib("SQLite", CASTELJAU_SQLITE_SONAME);
    lib.get(l.api.open_v2, "sqlite3_open_v2");
    lib.get(l.api.close, "sqlite3_close");
    lib.get(l.api.errmsg, "sqlite3_errmsg");
    lib.get(l.api.exec, "sqlite3_exec");
    lib.get(l.api.free, "sqlite3_free");
    lib.get(l.api.prepare_v2, "sqlite3_prepare_v2");
    lib.get(l.api.reset, "sqlite3_reset");
    lib.get(l.api.step, "sqlite3_step");
    lib.get(l.api.finalize, "sqlite3_finalize");
    lib.get(l.api.bind_int, "sqlite3_bind_int");
    lib.get(l.api.bind_int64, "sqlite3_bind_int64");
    lib.get(l.api.bind_text, "sqlite3_bind_text");
    lib.get(l.api.bind_blob, "sqlite3_bind_blob");
    lib.get(l.api.column_int, "sqlite3_column_int");
    lib.get(l.api.column_int64, "sqlite3_column_int64");
    lib.get(l.api.column_text, "sqlite3_column_text");
    lib.get(l.api.column_blob, "sqlite3_column_blob");
    lib.get(l.api.column_bytes, "sqlite3_column_bytes");
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

}  // namespace casteljau::sqlite_library
