// Map stage: a layer's opaque round stroke swept before its fills (see stroke_cover.hpp).
#include "map/stroke_cover.hpp"

#include "core/for_each_index.hpp"

namespace casteljau::map_detail {
namespace {

// Records a region's rows and marks in `full` the runs of pixels at coverage 255.
class FullRuns final : public SpanSink {
public:
    FullRuns(CoverageRows& rows, PixelSet& full) : rows_(rows), full_(full) {}
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        rows_.row(y, x, length, coverage);
        for (int i = 0; i < length;) {
            if (coverage[i] != 255) {
                ++i;
                continue;
            }
            const int start = i;
            while (i < length && coverage[i] == 255) ++i;
            full_.insert(y, x + start, x + i);
        }
    }

private:
    CoverageRows& rows_;
    PixelSet& full_;
};

}  // namespace

void StrokeCover::sweep(std::span<const LineSegment> segments, double radius, const IRect& image,
                        const std::vector<IRect>& regions, int threads) {
    rows_.assign(regions.size(), CoverageRows{});
    full_ = PixelSet(image);
    // Regions hold disjoint rows, and each row of the set has words of its own.
    parallel::for_each_index(threads, regions.size(), [&](int, std::size_t k) {
        FullRuns sink(rows_[k], full_);
        round_stroke_spans(segments, radius, regions[k], sink);
    });
}

}  // namespace casteljau::map_detail
