// Map stage: opening SQLite on first use (see sqlite_library.hpp).
#include "map/sqlite_library.hpp"

#include "core/runtime_library.hpp"

#ifndef CASTELJAU_SQLITE_SONAME
#define CASTELJAU_SQLITE_SONAME "libsqlite3.so.0"
#endif

namespace casteljau::sqlite_library {

const Api& api() {
    return platform::open_once<Api>("SQLite", CASTELJAU_SQLITE_SONAME, [](platform::RuntimeLibrary& lib, Api& a) {
        lib.get(a.open_v2, "sqlite3_open_v2");
        lib.get(a.close, "sqlite3_close");
        lib.get(a.errmsg, "sqlite3_errmsg");
        lib.get(a.exec, "sqlite3_exec");
        lib.get(a.free, "sqlite3_free");
        lib.get(a.prepare_v2, "sqlite3_prepare_v2");
        lib.get(a.reset, "sqlite3_reset");
        lib.get(a.step, "sqlite3_step");
        lib.get(a.finalize, "sqlite3_finalize");
        lib.get(a.bind_int, "sqlite3_bind_int");
        lib.get(a.bind_int64, "sqlite3_bind_int64");
        lib.get(a.bind_text, "sqlite3_bind_text");
        lib.get(a.bind_blob, "sqlite3_bind_blob");
        lib.get(a.column_int, "sqlite3_column_int");
        lib.get(a.column_int64, "sqlite3_column_int64");
        lib.get(a.column_text, "sqlite3_column_text");
        lib.get(a.column_blob, "sqlite3_column_blob");
        lib.get(a.column_bytes, "sqlite3_column_bytes");
    });
}

}  // namespace casteljau::sqlite_library
