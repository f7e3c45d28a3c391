// Text stage, coverage: the glyph mask and outline cache (include/casteljau/text.hpp).
//
// glyph outline (font units) --[s 0 0 -s dx dy]--> Rasterizer::fill_mask --> Mask stored under
// (font, variation, glyph, size, subpixel offset). The whole cache is emptied when the masks pass
// the byte budget. Each glyph's topology (classify_topology: may plain accumulation render it
// exactly?) is decided once per (font, variation, glyph) in font units, kept across sizes and
// offsets, and handed to the rasterizer with the fill. Glyphs are always mapped by a similarity
// (uniform scale, y mirrored, translation), so the verdict for similarity maps
// (classify_topology(path, tolerance)) applies too: it also proves glyphs whose thin curved
// strokes have overlapping control hulls (most of a CFF font's), holds for every size from the
// one it was decided for down to half of it and up, and is decided again for a smaller size. It
// costs about twice the plain verdict for such glyphs, more than one small mask saves (a glyph
// seen once at 12 px renders 20 % slower with it), so a glyph first gets the verdict for every
// map, and the one for similarity maps when that was not Simple and a second mask of the glyph is
// asked for, or at once from kSimilarityFirstPx up, where one mask pays for it.
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "casteljau/error.hpp"
#include "casteljau/text.hpp"
#include "core/for_each_index.hpp"
#include "text/font_impl.hpp"

namespace casteljau {

namespace {

struct MaskKey {
    const void* font;
    std::uint64_t variation;
    std::uint64_t size_bits;
    std::uint64_t offset_x_bits, offset_y_bits;
    std::uint32_t glyph;
    bool operator==(const MaskKey&) const = default;
};

struct OutlineKey {
    const void* font;
    std::uint64_t variation;
    std::uint32_t glyph;
    bool operator==(const OutlineKey&) const = default;
};

inline std::size_t mix(std::size_t h, std::uint64_t v) {
    h ^= static_cast<std::size_t>(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return h;
}

struct MaskKeyHash {
    std::size_t operator()(const MaskKey& k) const {
        std::size_t h = std::hash<const void*>()(k.font);
        h = mix(h, k.variation);
        h = mix(h, k.size_bits);
        h = mix(h, k.offset_x_bits);
        h = mix(h, k.offset_y_bits);
        h = mix(h, k.glyph);
        return h;
    }
};

struct OutlineKeyHash {
    std::size_t operator()(const OutlineKey& k) const {
        return mix(mix(std::hash<const void*>()(k.font), k.variation), k.glyph);
    }
};

// Bytes counted per entry besides the mask data (node, key, vector header).
constexpr std::size_t kEntryOverhead = 96;

}  // namespace

struct GlyphCache::Impl {
    std::size_t max_bytes;
    FillOptions fill;
    std::unordered_map<MaskKey, Mask, MaskKeyHash> masks;
    std::unordered_map<OutlineKey, Path, OutlineKeyHash> outlines;
    struct Verdict {
        Topology topology;
        bool similarity;       // classify_topology(path, max_tolerance), else classify_topology(path)
        double max_tolerance;  // in font units: it holds for every size whose tolerance / scale is at most this
    };
    static constexpr double kSimilarityFirstPx = 64;
    std::unordered_map<OutlineKey, Verdict, OutlineKeyHash> topologies;  // a few bytes each, not counted
    std::unordered_map<const void*, std::weak_ptr<const int>> fonts;     // lifetime tokens seen
    GlyphCacheStats stats;

    void clear() {
        masks.clear();
        outlines.clear();
        topologies.clear();
        fonts.clear();
        stats.entries = 0;
        stats.bytes = 0;
    }

    // Forgets everything when `font` sits at the address of a Font the cache knew that has since
    // been destroyed (its token differs).
    // Makes room for an entry of `bytes` (emptying the whole cache when it would pass max_bytes;
    // font tokens stay) and accounts for it.
    void admit(std::size_t bytes) {
        if (stats.bytes + bytes > max_bytes && (!masks.empty() || !outlines.empty())) {
            masks.clear();
            outlines.clear();
            topologies.clear();
            stats.entries = 0;
            stats.bytes = 0;
            ++stats.flushes;
        }
        stats.bytes += bytes;
        ++stats.entries;
    }

    // The key of a mask request; throws for a bad offset or size (mask() documents which).
    MaskKey key_of(const Font& font, std::uint32_t glyph, double size, Point offset) {
        if (!(offset.x >= 0 && offset.x < 1 && offset.y >= 0 && offset.y < 1))
            throw Error(ErrorKind::InvalidArgument, "glyph cache: the subpixel offset must be in [0, 1)");
        check_font_size(size);
        check_font(font);
        auto bits = [](double v) {
            std::uint64_t b;
            std::memcpy(&b, &v, sizeof b);
            return b;
        };
        return MaskKey{&font.impl(),         font.variation_key(), bits(size),
                       bits(offset.x + 0.0), bits(offset.y + 0.0), glyph};
    }

    // What rasterizing one mask needs: the outline in font units (read on the calling thread:
    // a font's FreeType face serves one thread at a time), its map to pixels and its topology.
    struct MaskJob {
        MaskKey key;
        Path outline;
        Affine to_pixels;
        FillOptions fill;
    };
    MaskJob job(const MaskKey& key, const Font& font, std::uint32_t glyph, double size, Point offset) {
        MaskJob j{key, font.glyph_path(glyph), font.glyph_transform(size, offset), fill};
        const double scale = similarity_scale(j.to_pixels);  // (glyph_transform is a similarity)
        if (!j.outline.empty() && scale > 0) {
            const OutlineKey okey{&font.impl(), font.variation_key(), glyph};
            const double lambda = fill.tolerance / scale;  // the tolerance in font units
            Verdict& v = topologies.try_emplace(okey, Verdict{Topology::Unknown, false, 0}).first->second;
            const bool similar =
                v.topology == Topology::Unknown
                    ? size >= kSimilarityFirstPx
                    : (v.similarity ? lambda > v.max_tolerance : v.topology != Topology::Simple);  // a second mask
            if (similar)
                v = {classify_topology(j.outline, 2 * lambda), true, 2 * lambda};
            else if (v.topology == Topology::Unknown)
                v = {classify_topology(j.outline), false, INFINITY};
            j.fill.topology = v.topology;
        }
        return j;
    }
    static Mask rasterize(const MaskJob& j, Rasterizer& raster) {
        return j.outline.empty() ? Mask{} : raster.fill_mask(j.outline, j.to_pixels, j.fill);
    }
    const Mask& store(const MaskKey& key, Mask m) {
        admit(m.data.size() + kEntryOverhead);
        return masks.emplace(key, std::move(m)).first->second;
    }

    void check_font(const Font& font) {
        const Font::Impl* fi = &font.impl();
        auto it = fonts.find(fi);
        if (it == fonts.end()) {
            fonts.emplace(fi, fi->token);
            return;
        }
        const std::weak_ptr<const int>& w = it->second;
        if (w.owner_before(fi->token) || fi->token.owner_before(w)) {
            clear();
            ++stats.flushes;
            fonts.emplace(fi, fi->token);
        }
    }
};

GlyphCache::GlyphCache(std::size_t max_bytes, double tolerance) : impl_(std::make_unique<Impl>()) {
    if (!(tolerance >= 1e-4 && tolerance <= 10))
        throw Error(ErrorKind::InvalidArgument, "glyph cache: tolerance must be in [1e-4, 10] px");
    impl_->max_bytes = max_bytes;
    impl_->fill.tolerance = tolerance;
}
GlyphCache::~GlyphCache() = default;
GlyphCache::GlyphCache(GlyphCache&&) noexcept = default;
GlyphCache& GlyphCache::operator=(GlyphCache&&) noexcept = default;

void GlyphCache::clear() { impl_->clear(); }
std::size_t GlyphCache::max_bytes() const { return impl_->max_bytes; }
double GlyphCache::tolerance() const { return impl_->fill.tolerance; }
const GlyphCacheStats& GlyphCache::stats() const { return impl_->stats; }

const Mask& GlyphCache::mask(const Font& font, std::uint32_t glyph, double size, Point offset, Rasterizer& raster) {
    Impl& c = *impl_;
    const MaskKey key = c.key_of(font, glyph, size, offset);
    if (auto it = c.masks.find(key); it != c.masks.end()) {
        ++c.stats.hits;
        return it->second;
    }
    ++c.stats.misses;
    return c.store(key, Impl::rasterize(c.job(key, font, glyph, size, offset), raster));
}

std::vector<const Mask*> GlyphCache::masks(std::span<const MaskRequest> requests, Rasterizer& raster) {
    Impl& c = *impl_;
    // Keys first: a font check may empty the cache, which must happen before any entry is taken.
    std::vector<MaskKey> keys;
    keys.reserve(requests.size());
    for (const MaskRequest& r : requests) {
        if (!r.font) throw Error(ErrorKind::InvalidArgument, "glyph cache: a mask request has no font");
        keys.push_back(c.key_of(*r.font, r.glyph, r.size, r.offset));
    }
    std::vector<const Mask*> out(requests.size(), nullptr);
    std::vector<Impl::MaskJob> jobs;  // one per distinct key not cached
    std::vector<std::size_t> job_of(requests.size(), SIZE_MAX);
    std::unordered_map<MaskKey, std::size_t, MaskKeyHash> pending;
    for (std::size_t i = 0; i < requests.size(); ++i) {
        if (auto it = c.masks.find(keys[i]); it != c.masks.end()) {
            ++c.stats.hits;
            out[i] = &it->second;
        } else if (auto p = pending.find(keys[i]); p != pending.end()) {
            ++c.stats.hits;  // as mask() would find it, made by the request before
            job_of[i] = p->second;
        } else {
            ++c.stats.misses;
            const MaskRequest& r = requests[i];
            pending.emplace(keys[i], jobs.size());
            job_of[i] = jobs.size();
            jobs.push_back(c.job(keys[i], *r.font, r.glyph, r.size, r.offset));
        }
    }
    // Rasterize on the pool: worker 0 is this thread with the caller's rasterizer, the others
    // make one of their own on first use (each worker id serves one thread at a time).
    std::vector<Mask> made(jobs.size());
    std::vector<std::unique_ptr<Rasterizer>> own(static_cast<std::size_t>(parallel::thread_count()));
    parallel::for_each_index(parallel::thread_count(), jobs.size(), [&](int w, std::size_t j) {
        Rasterizer* r = &raster;
        if (w > 0) {
            std::unique_ptr<Rasterizer>& mine = own[static_cast<std::size_t>(w)];
            if (!mine) mine = std::make_unique<Rasterizer>();
            r = mine.get();
        }
        made[j] = Impl::rasterize(jobs[j], *r);
    });
    const std::size_t flushes = c.stats.flushes;
    std::vector<const Mask*> stored(jobs.size());
    for (std::size_t j = 0; j < jobs.size(); ++j) stored[j] = &c.store(jobs[j].key, std::move(made[j]));
    if (c.stats.flushes != flushes) {
        // The masks did not fit in the cache together: give each glyph through mask() instead.
        std::vector<const Mask*> none;
        return none;
    }
    for (std::size_t i = 0; i < requests.size(); ++i)
        if (!out[i]) out[i] = stored[job_of[i]];
    return out;
}

const Path& GlyphCache::outline(const Font& font, std::uint32_t glyph) {
    Impl& c = *impl_;
    c.check_font(font);
    const OutlineKey key{&font.impl(), font.variation_key(), glyph};
    if (auto it = c.outlines.find(key); it != c.outlines.end()) {
        ++c.stats.hits;
        return it->second;
    }
    ++c.stats.misses;
    Path p = font.glyph_path(glyph);
    c.admit(p.points().size() * sizeof(Point) + p.verbs().size() + kEntryOverhead);
    return c.outlines.emplace(key, std::move(p)).first->second;
}

}  // namespace casteljau
