// casteljau/projection.hpp: map projections, from longitude/latitude degrees to a projected plane.
//
// Pipeline position: map stage, between the readers (geojson.hpp) and the fit to pixels (map.hpp).
// Projected coordinates are y-up (north up), in the projection's own units: degrees for
// equirectangular (x = longitude, y = latitude, so --bbox maps exactly), metres for Web Mercator
// (EPSG:3857, sphere of radius 6378137 m, latitudes clamped to +/-85.0511287798) and for PROJ.
// Built in: "equirectangular" (aliases "plate-carree", "latlon", "EPSG:4326") and "mercator"
// (aliases "webmercator", "web-mercator", "EPSG:3857", "EPSG:900913"). Anything else goes to PROJ:
// a PROJ string ("+proj=robin"), a CRS ("EPSG:3035", "ESRI:54030") or WKT; a CRS is reached from
// EPSG:4326 with the axis order normalized for visualization (x east, y north).
//
// Antimeridian rule (applied by the map renderer before projecting, see map.hpp): a segment whose
// longitudes differ by more than 180 degrees is taken to cross the antimeridian the short way.
//
// Thread-safety: a MapProjection holds a PROJ context and object; use one per thread (clone()).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "casteljau/geometry.hpp"

namespace casteljau {

inline constexpr double kWebMercatorMaxLatitude = 85.0511287798;
inline constexpr double kWebMercatorRadius = 6378137.0;

class MapProjection {
public:
    enum class Kind { Equirectangular, WebMercator, Proj };

    MapProjection();  // equirectangular
    ~MapProjection();
    MapProjection(MapProjection&&) noexcept;
    MapProjection& operator=(MapProjection&&) noexcept;

    // Throws Error(InvalidArgument) naming the text when PROJ does not know it.
    static MapProjection parse(std::string_view spec);
    MapProjection clone() const;

    Kind kind() const { return kind_; }
    const std::string& spec() const { return spec_; }
    // True when straight lon/lat segments stay straight after projection (no densifying needed):
    // equirectangular; Web Mercator keeps meridians and parallels straight too.
    bool preserves_graticule_lines() const { return kind_ != Kind::Proj; }

    // Projects one position (degrees). Returns false when the projection cannot map it (PROJ
    // reports an error or a non-finite result).
    bool project(Point lonlat, Point& out) const {
        if (kind_ == Kind::Equirectangular) {
            out = lonlat;  // the identity, inline: a map projects every position more than once
            return true;
        }
        // By value, so that the caller's `out` need not live in memory (reading it back right
        // after a store of its halves stalls).
        const std::optional<Point> q = project_other(lonlat);
        if (q) out = *q;
        return q.has_value();
    }

private:
    std::optional<Point> project_other(Point lonlat) const;

    Kind kind_ = Kind::Equirectangular;
    std::string spec_ = "equirectangular";
    struct ProjState;
    std::unique_ptr<ProjState> proj_;
};

}  // namespace casteljau
