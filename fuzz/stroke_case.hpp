// fuzz_stroke's reading of an input: a stroke style (widths from 0 to 1e30 and NaN, every cap and
// join, miter limits, dash arrays with zero, negative and huge entries, offsets), a transform and a
// path (path_gen.hpp). Shared with the tests that replay a fuzz_stroke finding through the library.
#pragma once

#include "casteljau/path.hpp"
#include "casteljau/stroke.hpp"
#include "harness.hpp"
#include "path_gen.hpp"

namespace casteljau::fuzz {

struct StrokeCase {
    StrokeStyle style;
    Affine m{};
    Path path;
};

inline StrokeCase read_stroke_case(Bytes& in) {
    StrokeCase c;
    StrokeStyle& st = c.style;
    st.width = in.flag() ? in.number(40) : in.range(0, 40) / 4.0;
    st.cap = static_cast<LineCap>(in.range(0, 2));
    st.join = static_cast<LineJoin>(in.range(0, 3));
    st.miter_limit = in.flag() ? in.number(10) : 4;
    const int ndash = in.range(0, 6);
    for (int i = 0; i < ndash; ++i) st.dashes.push_back(in.flag() ? in.number(20) : in.range(0, 20) / 2.0);
    st.dash_offset = in.flag() ? in.number(50) : 0;
    if (in.flag()) c.m = Affine{in.number(4), in.number(1), in.number(1), in.number(4), 0, 0};
    c.path = random_path(in, 200);
    return c;
}

}  // namespace casteljau::fuzz
