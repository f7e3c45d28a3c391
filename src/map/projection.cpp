// Map stage: projections (see include/casteljau/projection.hpp). The two built-in ones are plain
// formulas; everything else is delegated to PROJ (opened on first use: map/proj_library.hpp).
#include "casteljau/projection.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "casteljau/error.hpp"
#include "map/proj_library.hpp"

namespace casteljau {

struct MapProjection::ProjState {
    PJ_CONTEXT* ctx = nullptr;
    PJ* pj = nullptr;
    bool radians_in = false;  // a bare operation ("+proj=robin") takes radians
    ~ProjState() {
        // A state exists only once PROJ was loaded.
        const proj_library::Api& api = proj_library::api();
        if (pj) api.destroy(pj);
        if (ctx) api.context_destroy(ctx);
    }
};

MapProjection::MapProjection() = default;
MapProjection::~MapProjection() = default;
MapProjection::MapProjection(MapProjection&&) noexcept = default;
MapProjection& MapProjection::operator=(MapProjection&&) noexcept = default;

namespace {

std::string lower(std::string_view s) {
    std::string o(s);
    for (char& c : o) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return o;
}

}  // namespace

MapProjection MapProjection::parse(std::string_view spec) {
    MapProjection p;
    const std::string l = lower(spec);
    p.spec_ = std::string(spec);
    if (l == "equirectangular" || l == "plate-carree" || l == "latlon" || l == "epsg:4326") {
        p.kind_ = Kind::Equirectangular;
        return p;
    }
    if (l == "mercator" || l == "webmercator" || l == "web-mercator" || l == "epsg:3857" || l == "epsg:900913") {
        p.kind_ = Kind::WebMercator;
        return p;
    }
    if (spec.empty()) throw Error(ErrorKind::InvalidArgument, "empty projection");
    const proj_library::Api& api = proj_library::api();
    auto st = std::make_unique<ProjState>();
    st->ctx = api.context_create();
    if (!st->ctx) throw Error(ErrorKind::Io, "PROJ: cannot create a context");
    api.log_level(st->ctx, PJ_LOG_NONE);
    const std::string text(spec);
    PJ* obj = api.create(st->ctx, text.c_str());
    if (!obj)
        throw Error(ErrorKind::InvalidArgument, "unknown projection '" + text +
                                                    "' (expected equirectangular, mercator, a PROJ string such as "
                                                    "'+proj=robin' or a CRS such as 'EPSG:3035')");
    if (api.is_crs(obj)) {
        PJ* op = api.create_crs_to_crs(st->ctx, "EPSG:4326", text.c_str(), nullptr);
        api.destroy(obj);
        if (!op) throw Error(ErrorKind::InvalidArgument, "PROJ: no transformation from EPSG:4326 to '" + text + "'");
        PJ* norm = api.normalize_for_visualization(st->ctx, op);
        api.destroy(op);
        if (!norm) throw Error(ErrorKind::InvalidArgument, "PROJ: cannot normalize the axes of '" + text + "'");
        st->pj = norm;
        st->radians_in = false;
    } else {
        st->pj = obj;
        st->radians_in = api.angular_input(obj, PJ_FWD) != 0;
    }
    p.kind_ = Kind::Proj;
    p.proj_ = std::move(st);
    return p;
}

MapProjection MapProjection::clone() const { return parse(spec_); }

std::optional<Point> MapProjection::project_other(Point ll) const {
    switch (kind_) {
        case Kind::Equirectangular: return ll;
        case Kind::WebMercator: {
            constexpr double d2r = kPi / 180.0;
            const double lat = std::clamp(ll.y, -kWebMercatorMaxLatitude, kWebMercatorMaxLatitude);
            return Point{kWebMercatorRadius * ll.x * d2r,
                         kWebMercatorRadius * std::log(std::tan(kPi / 4 + lat * d2r / 2))};
        }
        case Kind::Proj: {
            const proj_library::Api& api = proj_library::api();
            const double to_input = proj_->radians_in ? kPi / 180.0 : 1.0;
            PJ_COORD c;
            c.v[0] = ll.x * to_input;
            c.v[1] = ll.y * to_input;
            c.v[2] = 0;
            c.v[3] = 0;
            api.errno_reset(proj_->pj);
            const PJ_COORD r = api.trans(proj_->pj, PJ_FWD, c);
            if (api.errno_of(proj_->pj) != 0 || !std::isfinite(r.xy.x) || !std::isfinite(r.xy.y) ||
                std::fabs(r.xy.x) > 1e30 || std::fabs(r.xy.y) > 1e30)
                return std::nullopt;
            return Point{r.xy.x, r.xy.y};
        }
    }
    return std::nullopt;
}

}  // namespace casteljau
