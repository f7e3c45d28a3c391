// Map stage: SQLite, loaded when an MBTiles file is first written or read.
//
// Only `tiles -o FILE.mbtiles` and `tiles-merge` use SQLite, but linked directly it was bound at
// every process's start-up: Debian's libsqlite3 is linked with BIND_NOW, so the dynamic loader
// resolved its 1,600 symbol references before `casteljau text` could draw one letter (a third
// of all the loader's lookups). So SQLite is opened with dlopen by its soname
// (CASTELJAU_SQLITE_SONAME, read from the SQLite found at build time) on first use, and its
// functions are called through this table (core/runtime_library.hpp). Thread-safe: the
// library is opened once (std::call_once).
#pragma once

#include <sqlite3.h>

namespace casteljau::sqlite_library {

// The SQLite functions casteljau calls, with SQLite's own signatures.
struct Api {
    decltype(&::sqlite3_open_v2) open_v2;
    decltype(&::sqlite3_close) close;
    decltype(&::sqlite3_errmsg) errmsg;
    decltype(&::sqlite3_exec) exec;
    decltype(&::sqlite3_free) free;
    decltype(&::sqlite3_prepare_v2) prepare_v2;
    decltype(&::sqlite3_reset) reset;
    decltype(&::sqlite3_step) step;
    decltype(&::sqlite3_finalize) finalize;
    decltype(&::sqlite3_bind_int) bind_int;
    decltype(&::sqlite3_bind_int64) bind_int64;
    decltype(&::sqlite3_bind_text) bind_text;
    decltype(&::sqlite3_bind_blob) bind_blob;
    decltype(&::sqlite3_column_int) column_int;
    decltype(&::sqlite3_column_int64) column_int64;
    decltype(&::sqlite3_column_text) column_text;
    decltype(&::sqlite3_column_blob) column_blob;
    decltype(&::sqlite3_column_bytes) column_bytes;
};

// The loaded library. Throws Error(ErrorKind::Io) naming the library when it cannot be opened
// or lacks a function (every later call throws the same).
const Api& api();

}  // namespace casteljau::sqlite_library
