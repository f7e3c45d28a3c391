// Map stage: where tiles go: a folder tree DIR/z/x/y.png or an MBTiles 1.3 SQLite file
// (see include/casteljau/tiles.hpp).
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/projection.hpp"
#include "casteljau/tiles.hpp"
#include "map/sqlite_library.hpp"

namespace casteljau {

namespace {
// SQLite, opened on first use.
const sqlite_library::Api& sq() { return sqlite_library::api(); }

// The Web Mercator world in degrees: the bounds of a pyramid's MBTiles metadata.
constexpr Rect kWorldBounds{-180, -kWebMercatorMaxLatitude, 180, kWebMercatorMaxLatitude};
}  // namespace

TileFolderWriter::TileFolderWriter(std::string dir) : dir_(std::move(dir)) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec || !std::filesystem::is_directory(dir_))
        throw Error(ErrorKind::Io,
                    "cannot create the tile folder '" + dir_ + "': " + (ec ? ec.message() : "not a folder"));
}

std::string TileFolderWriter::tile_path(int z, int x, int y) const {
    return dir_ + "/" + std::to_string(z) + "/" + std::to_string(x) + "/" + std::to_string(y) + ".png";
}

bool TileFolderWriter::exists(int z, int x, int y) const {
    struct stat st;
    return ::stat(tile_path(z, x, y).c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0;
}

std::size_t TileFolderWriter::remove_interrupted_writes() const {
    std::size_t removed = 0;
    std::error_code ec;
    std::filesystem::recursive_directory_iterator it(dir_, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) && is_atomic_write_temporary(it->path().filename().string()) &&
            std::filesystem::remove(it->path(), ec))
            ++removed;
    }
    return removed;
}

void TileFolderWriter::write(int z, int x, int y, const std::vector<std::uint8_t>& png) {
    const std::string folder = dir_ + "/" + std::to_string(z) + "/" + std::to_string(x);
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error(ErrorKind::Io, "cannot create '" + folder + "': " + ec.message());
    write_file_atomic(tile_path(z, x, y), png);
}

struct MbtilesWriter::Impl {
    std::string path, tmp;
    sqlite3* db = nullptr;
    sqlite3_stmt* insert = nullptr;
    bool finished = false;

    [[noreturn]] void fail(const std::string& what) {
        const std::string msg = "MBTiles '" + path + "': " + what + (db ? std::string(": ") + sq().errmsg(db) : "");
        throw Error(ErrorKind::Io, msg);
    }
    void exec(const char* sql) {
        char* err = nullptr;
        if (sq().exec(db, sql, nullptr, nullptr, &err) != SQLITE_OK) {
            const std::string m = err ? err : "error";
            sq().free(err);
            throw Error(ErrorKind::Io, "MBTiles '" + path + "': " + m);
        }
    }
    void close_and_remove() {
        if (insert) sq().finalize(insert);
        insert = nullptr;
        if (db) sq().close(db);
        db = nullptr;
        if (!tmp.empty()) {
            std::remove(tmp.c_str());
            std::remove((tmp + "-journal").c_str());
        }
    }
};

MbtilesWriter::MbtilesWriter(std::string path, const std::string& name, int min_zoom, int max_zoom, const Rect& b)
    : impl_(new Impl) {
    impl_->path = std::move(path);
    impl_->tmp = impl_->path + ".tmp-" + std::to_string(::getpid());
    try {
        std::remove(impl_->tmp.c_str());
        if (sq().open_v2(impl_->tmp.c_str(), &impl_->db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
            SQLITE_OK)
            impl_->fail("cannot create the database");
        impl_->exec(
            "PRAGMA journal_mode=OFF; PRAGMA synchronous=OFF;"
            "CREATE TABLE metadata (name text, value text);"
            "CREATE TABLE tiles (zoom_level integer, tile_column integer, tile_row integer, tile_data blob);"
            "CREATE UNIQUE INDEX tile_index on tiles (zoom_level, tile_column, tile_row);"
            "BEGIN;");
        sqlite3_stmt* st = nullptr;
        if (sq().prepare_v2(impl_->db, "INSERT INTO metadata VALUES (?, ?)", -1, &st, nullptr) != SQLITE_OK)
            impl_->fail("cannot prepare");
        std::ostringstream bounds, center;
        bounds.precision(10);
        center.precision(10);
        bounds << b.x0 << "," << b.y0 << "," << b.x1 << "," << b.y1;
        center << (b.x0 + b.x1) / 2 << "," << (b.y0 + b.y1) / 2 << "," << min_zoom;
        const std::pair<std::string, std::string> meta[] = {{"name", name},
                                                            {"format", "png"},
                                                            {"type", "overlay"},
                                                            {"version", "1.3"},
                                                            {"description", "rendered by casteljau"},
                                                            {"bounds", bounds.str()},
                                                            {"center", center.str()},
                                                            {"minzoom", std::to_string(min_zoom)},
                                                            {"maxzoom", std::to_string(max_zoom)}};
        for (const auto& [k, v] : meta) {
            sq().reset(st);
            sq().bind_text(st, 1, k.c_str(), -1, SQLITE_TRANSIENT);
            sq().bind_text(st, 2, v.c_str(), -1, SQLITE_TRANSIENT);
            if (sq().step(st) != SQLITE_DONE) {
                sq().finalize(st);
                impl_->fail("cannot write metadata");
            }
        }
        sq().finalize(st);
        if (sq().prepare_v2(impl_->db, "INSERT OR REPLACE INTO tiles VALUES (?, ?, ?, ?)", -1, &impl_->insert,
                            nullptr) != SQLITE_OK)
            impl_->fail("cannot prepare");
    } catch (...) {
        impl_->close_and_remove();
        delete impl_;
        throw;
    }
}

MbtilesWriter::~MbtilesWriter() {
    if (!impl_->finished) impl_->close_and_remove();
    delete impl_;
}

void MbtilesWriter::write(int z, int x, int y, const std::vector<std::uint8_t>& png) {
    sqlite3_stmt* st = impl_->insert;
    sq().reset(st);
    sq().bind_int(st, 1, z);
    sq().bind_int64(st, 2, x);
    sq().bind_int64(st, 3, (std::int64_t{1} << z) - 1 - y);  // TMS row
    sq().bind_blob(st, 4, png.data(), static_cast<int>(png.size()), SQLITE_TRANSIENT);
    if (sq().step(st) != SQLITE_DONE) impl_->fail("cannot write tile");
}

void MbtilesWriter::finish() {
    impl_->exec("COMMIT;");
    sq().finalize(impl_->insert);
    impl_->insert = nullptr;
    if (sq().close(impl_->db) != SQLITE_OK) impl_->fail("cannot close");
    impl_->db = nullptr;
    if (std::rename(impl_->tmp.c_str(), impl_->path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        impl_->close_and_remove();
        throw Error(ErrorKind::Io, "cannot rename the MBTiles file into '" + impl_->path + "': " + reason);
    }
    impl_->finished = true;
}

namespace {

struct ReadDb {
    sqlite3* db = nullptr;
    explicit ReadDb(const std::string& path) {
        if (sq().open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
            const std::string m = db ? sq().errmsg(db) : "cannot open";
            if (db) sq().close(db);
            throw Error(ErrorKind::Io, "cannot open MBTiles '" + path + "': " + m);
        }
    }
    ~ReadDb() {
        if (db) sq().close(db);
    }
};

}  // namespace

void merge_mbtiles(const std::vector<std::string>& inputs, const std::string& output) {
    if (inputs.empty()) throw Error(ErrorKind::InvalidArgument, "tiles-merge needs at least one input");
    int minz = limits::kMaxTileZoom, maxz = 0;
    Rect b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    std::string name = "casteljau";
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        ReadDb in(inputs[i]);
        sqlite3_stmt* st = nullptr;
        if (sq().prepare_v2(in.db, "SELECT name, value FROM metadata", -1, &st, nullptr) != SQLITE_OK)
            throw Error(ErrorKind::InvalidData, "'" + inputs[i] + "' is not an MBTiles file (no metadata table)");
        while (sq().step(st) == SQLITE_ROW) {
            const std::string k = reinterpret_cast<const char*>(sq().column_text(st, 0));
            const char* vt = reinterpret_cast<const char*>(sq().column_text(st, 1));
            const std::string v = vt ? vt : "";
            if (k == "minzoom") minz = std::min(minz, std::atoi(v.c_str()));
            if (k == "maxzoom") maxz = std::max(maxz, std::atoi(v.c_str()));
            if (k == "name" && i == 0) name = v;
            if (k == "bounds") {
                double w, s, e, n;
                if (std::sscanf(v.c_str(), "%lf,%lf,%lf,%lf", &w, &s, &e, &n) == 4) {
                    b.x0 = std::min(b.x0, w);
                    b.y0 = std::min(b.y0, s);
                    b.x1 = std::max(b.x1, e);
                    b.y1 = std::max(b.y1, n);
                }
            }
        }
        sq().finalize(st);
    }
    if (minz > maxz) minz = maxz = 0;
    if (!(b.x0 <= b.x1)) b = kWorldBounds;
    MbtilesWriter out(output, name, minz, maxz, b);
    for (const std::string& path : inputs) {
        ReadDb in(path);
        sqlite3_stmt* st = nullptr;
        if (sq().prepare_v2(in.db, "SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles", -1, &st,
                            nullptr) != SQLITE_OK)
            throw Error(ErrorKind::InvalidData, "'" + path + "' is not an MBTiles file (no tiles table)");
        while (sq().step(st) == SQLITE_ROW) {
            const int z = sq().column_int(st, 0);
            const std::int64_t x = sq().column_int64(st, 1), row = sq().column_int64(st, 2);
            const auto* blob = static_cast<const std::uint8_t*>(sq().column_blob(st, 3));
            const int n = sq().column_bytes(st, 3);
            if (z < 0 || z > limits::kMaxTileZoom) continue;
            std::vector<std::uint8_t> png(blob, blob + n);
            out.write(z, static_cast<int>(x), static_cast<int>((std::int64_t{1} << z) - 1 - row), png);
        }
        sq().finalize(st);
    }
    out.finish();
}

TileStats write_tiles(const MapData& data, const MapStyle& style, const TileOptions& opts, const std::string& output,
                      const std::string& name, const std::function<void(std::uint64_t, std::uint64_t)>& progress) {
    if (output.ends_with(".mbtiles")) {
        if (opts.resume)
            throw Error(ErrorKind::InvalidArgument,
                        "resume works with a folder output (an .mbtiles file is written whole)");
        MbtilesWriter w(output, name, opts.min_zoom, opts.max_zoom, kWorldBounds);
        const TileStats st = render_tiles(
            data, style, opts,
            [&](int z, int x, int y, const std::vector<std::uint8_t>& png) { w.write(z, x, y, png); }, {}, progress);
        w.finish();
        return st;
    }
    TileFolderWriter w(output);
    if (opts.resume) w.remove_interrupted_writes();
    return render_tiles(
        data, style, opts, [&](int z, int x, int y, const std::vector<std::uint8_t>& png) { w.write(z, x, y, png); },
        [&](int z, int x, int y) { return w.exists(z, x, y); }, progress);
}

}  // namespace casteljau
