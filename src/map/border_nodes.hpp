// Map stage (internal): the positions where the borders that rings and lines share begin and end,
// so that a shared border can be simplified identically in every ring that holds it.
//
// A position is a node when
//   - it occurs with two different pairs of neighbours (unordered) anywhere in the data: where a
//     border shared by two rings begins or ends, where three or more borders meet, where a ring
//     touches another at a vertex;
//   - it is an end of a line;
//   - it is an end of a step that crosses the antimeridian (the renderer cuts such steps in
//     longitude/latitude, so no simplified segment may stand in for them);
//   - its ring or line has fewer than three distinct positions (nothing to simplify).
// Between two consecutive nodes of a ring every position has the same two neighbours wherever it
// occurs, so such a run is either held whole by every ring that holds one of its inner positions,
// in one direction or the other, or by none: the runs between nodes are the arcs of the data's
// topology. TopoJSON data (MapData::arc_ends not empty, every geometry with its
// Geometry::arc_starts) has them already: a border two rings share is one arc, so the positions
// where a ring or line passes from one arc to the next are its nodes, with no search. Any other
// data (a GeoJSON file whose neighbours repeat their common positions) gets them from its
// positions alone, through a table of every position and the neighbours it was first seen with.
// Positions compare bit for bit (-0.0 equals +0.0).
//
// Consecutive repeats of a position (and a ring's closing repeat of its first) are skipped: they
// carry no step. distinct_positions() is the one place that decides which positions count.
//
// Memory while finding: 4 bytes per position and about 43 bytes per distinct position (the table
// grows with them; TopoJSON: none); the result keeps one byte per position.
// Thread-safety: free functions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "casteljau/geojson.hpp"

namespace casteljau::map_detail {

struct BorderNodes {
    // The index of each feature's first position in `node` (features, their geometries and their
    // positions in order); one more entry holds the total.
    std::vector<std::size_t> feature_start;
    std::vector<std::uint8_t> node;  // 1: the position is a node
};

BorderNodes find_border_nodes(const MapData& data);

// The indices into `line` of its positions less consecutive repeats, and for a ring (`closed`) less
// the repeats of its first position at its end.
void distinct_positions(std::span<const Point> line, bool closed, std::vector<std::uint32_t>& out);

}  // namespace casteljau::map_detail
