// Text stage, font discovery: a list of faces from font folders and the system (fontconfig), CSS
// font matching and per-character fallback over it (include/casteljau/font_database.hpp).
#include "casteljau/font_database.hpp"

#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>
#include <utility>

#include "casteljau/error.hpp"

namespace casteljau {

namespace {

bool same_name(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

// fontconfig's weight scale (0 thin .. 80 regular .. 210 black) to CSS weights (100 .. 900).
int css_weight(double fc_weight) {
    return static_cast<int>(std::lround(std::clamp(FcWeightToOpenTypeDouble(fc_weight), 1.0, 1000.0)));
}

// The point of [lo, hi] nearest to `v`.
double nearest(double v, double lo, double hi) { return std::clamp(v, lo, hi); }

// CSS weight preference (lower is better) of a face covering [lo, hi] for the desired weight.
std::pair<int, double> weight_key(int desired, int lo, int hi) {
    const double w = nearest(desired, lo, hi);
    if (w == desired) return {0, 0};
    if (desired >= 400 && desired <= 500) {
        if (w > desired && w <= 500) return {1, w - desired};
        if (w < desired) return {2, desired - w};
        return {3, w - desired};
    }
    if (desired < 400) return w < desired ? std::pair{1, desired - w} : std::pair{2, w - desired};
    return w > desired ? std::pair{1, w - desired} : std::pair{2, desired - w};
}

int slant_rank(FontSlant want, FontSlant have) {
    if (want == have) return 0;
    if (want == FontSlant::Normal) return have == FontSlant::Oblique ? 1 : 2;
    if (want == FontSlant::Italic) return have == FontSlant::Oblique ? 1 : 2;
    return have == FontSlant::Italic ? 1 : 2;  // oblique
}

// CSS stretch preference (lower is better): narrower first for desired <= 100, wider first above.
std::pair<int, double> stretch_key(double desired, double have) {
    if (have == desired) return {0, 0};
    if (desired <= 100) return have < desired ? std::pair{1, desired - have} : std::pair{2, have - desired};
    return have > desired ? std::pair{1, have - desired} : std::pair{2, desired - have};
}

// The face with the smallest key among those `eligible` accepts (the first one on ties).
template <class Eligible, class KeyOf>
std::optional<std::size_t> best_face(const std::vector<FontFaceInfo>& faces, Eligible eligible, KeyOf key_of) {
    std::optional<std::size_t> best;
    decltype(key_of(faces.front())) best_key{};
    for (std::size_t i = 0; i < faces.size(); ++i) {
        if (!eligible(i)) continue;
        const auto key = key_of(faces[i]);
        if (!best || key < best_key) {
            best = i;
            best_key = key;
        }
    }
    return best;
}

}  // namespace

struct FontDatabase::Impl {
    std::vector<FontFaceInfo> faces;
    std::vector<FcCharSet*> charsets;  // one per face (owned references), may be null
    mutable std::mutex mutex;
    mutable std::map<std::pair<std::string, int>, std::unique_ptr<Font>> loaded;

    ~Impl() {
        for (FcCharSet* c : charsets)
            if (c) FcCharSetDestroy(c);
    }

    // Adds every face `config` lists (named instances of variable fonts are folded into the face
    // they come from). Faces already present (same file and index) are skipped.
    void add_from(FcConfig* config) {
        FcPattern* pat = FcPatternCreate();
        FcObjectSet* os = FcObjectSetBuild(FC_FILE, FC_INDEX, FC_FAMILY, FC_WEIGHT, FC_SLANT, FC_WIDTH, FC_CHARSET,
                                           FC_VARIABLE, static_cast<char*>(nullptr));
        FcFontSet* set = FcFontList(config, pat, os);
        FcObjectSetDestroy(os);
        FcPatternDestroy(pat);
        if (!set) return;
        add_set(set, true);
        FcFontSetDestroy(set);
    }

    // Adds the faces of font files read directly (no fontconfig configuration or cache involved).
    void add_files(const std::vector<std::string>& files) {
        FcFontSet* set = FcFontSetCreate();
        if (!set) throw std::bad_alloc();
        for (const std::string& f : files) {
            int count = 0;
            FcFreeTypeQueryAll(reinterpret_cast<const FcChar8*>(f.c_str()), -1, nullptr, &count, set);
        }
        add_set(set, false);
        FcFontSetDestroy(set);
    }

    // `system`: the faces come from the system's configuration (FontFaceInfo::system).
    void add_set(FcFontSet* set, bool system) {
        std::map<std::pair<std::string, int>, std::size_t> seen;
        for (std::size_t i = 0; i < faces.size(); ++i) seen[{faces[i].path, faces[i].index}] = i;
        // fontconfig lists in no particular order: sort by file so that the database order (the
        // fallback order) is stable.
        std::vector<FcPattern*> pats(set->fonts, set->fonts + set->nfont);
        auto file_of = [](FcPattern* p) {
            FcChar8* f = nullptr;
            return FcPatternGetString(p, FC_FILE, 0, &f) == FcResultMatch ? std::string(reinterpret_cast<char*>(f))
                                                                          : std::string();
        };
        std::stable_sort(pats.begin(), pats.end(), [&](FcPattern* a, FcPattern* b) { return file_of(a) < file_of(b); });
        for (FcPattern* p : pats) {
            const std::string file = file_of(p);
            int index = 0;
            FcPatternGetInteger(p, FC_INDEX, 0, &index);
            if (file.empty() || (index >> 16) != 0) continue;  // named instances: the variable face covers them
            FcBool variable = FcFalse;
            FcPatternGetBool(p, FC_VARIABLE, 0, &variable);
            FontFaceInfo info;
            info.path = file;
            info.index = index;
            info.variable = variable;
            info.system = system;
            FcChar8* fam = nullptr;
            for (int k = 0; FcPatternGetString(p, FC_FAMILY, k, &fam) == FcResultMatch; ++k)
                info.families.emplace_back(reinterpret_cast<char*>(fam));
            FcValue v;
            if (FcPatternGet(p, FC_WEIGHT, 0, &v) == FcResultMatch) {
                if (v.type == FcTypeRange) {
                    double lo = 0, hi = 0;
                    FcRangeGetDouble(v.u.r, &lo, &hi);
                    info.min_weight = css_weight(lo);
                    info.max_weight = css_weight(hi);
                    info.weight = std::clamp(400, info.min_weight, info.max_weight);
                } else {
                    const double w = v.type == FcTypeInteger ? v.u.i : v.type == FcTypeDouble ? v.u.d : 80;
                    info.weight = info.min_weight = info.max_weight = css_weight(w);
                }
            }
            int slant = FC_SLANT_ROMAN;
            FcPatternGetInteger(p, FC_SLANT, 0, &slant);
            info.slant = slant == FC_SLANT_ITALIC    ? FontSlant::Italic
                         : slant == FC_SLANT_OBLIQUE ? FontSlant::Oblique
                                                     : FontSlant::Normal;
            if (FcPatternGet(p, FC_WIDTH, 0, &v) == FcResultMatch) {
                if (v.type == FcTypeInteger)
                    info.stretch = v.u.i;
                else if (v.type == FcTypeDouble)
                    info.stretch = v.u.d;
            }
            FcCharSet* cs = nullptr;
            if (FcPatternGetCharSet(p, FC_CHARSET, 0, &cs) != FcResultMatch) cs = nullptr;
            if (auto it = seen.find({file, index}); it != seen.end()) {
                // The variable face and its default instance are listed separately: keep one, with
                // the variable face's ranges.
                if (variable) {
                    FontFaceInfo& old = faces[it->second];
                    old.variable = true;
                    old.min_weight = info.min_weight;
                    old.max_weight = info.max_weight;
                }
                continue;
            }
            if (info.families.empty()) continue;
            seen[{file, index}] = faces.size();
            faces.push_back(std::move(info));
            charsets.push_back(cs ? FcCharSetCopy(cs) : nullptr);
        }
    }
};

void check_font_sources(const FontDatabaseOptions& options) {
    namespace fs = std::filesystem;
    for (const std::string& dir : options.font_dirs) {
        std::error_code ec;
        if (!fs::is_directory(dir, ec))
            throw Error(ErrorKind::Io, "font folder '" + dir + "' does not exist or is not a folder");
    }
    for (const std::string& file : options.font_files) {
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) throw Error(ErrorKind::Io, "font file '" + file + "' does not exist");
    }
}

FontDatabase::FontDatabase(const FontDatabaseOptions& options) : impl_(std::make_unique<Impl>()) {
    namespace fs = std::filesystem;
    check_font_sources(options);
    std::vector<std::string> files;
    auto is_font = [](const fs::path& p) {
        std::string ext = p.extension().string();
        for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return ext == ".ttf" || ext == ".otf" || ext == ".ttc" || ext == ".otc";
    };
    for (const std::string& dir : options.font_dirs) {
        std::error_code ec;
        std::vector<std::string> found;
        for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, ec);
             !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
            if (it->is_regular_file(ec) && is_font(it->path())) found.push_back(it->path().string());
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    }
    files.insert(files.end(), options.font_files.begin(), options.font_files.end());
    impl_->add_files(files);
    if (options.system_fonts) {
        if (FcConfig* config = FcInitLoadConfigAndFonts()) {
            impl_->add_from(config);
            FcConfigDestroy(config);
        }
    }
}

FontDatabase::~FontDatabase() = default;

const std::vector<FontFaceInfo>& FontDatabase::faces() const { return impl_->faces; }

std::optional<std::size_t> FontDatabase::match(std::string_view family, int weight, FontSlant slant,
                                               double stretch) const {
    // Stretch narrows first, then style, then weight (CSS Fonts 4, 5.2 step 4).
    return best_face(
        impl_->faces,
        [&](std::size_t i) {
            const auto& names = impl_->faces[i].families;
            return std::any_of(names.begin(), names.end(), [&](const std::string& n) { return same_name(n, family); });
        },
        [&](const FontFaceInfo& f) {
            return std::make_tuple(stretch_key(stretch, f.stretch), slant_rank(slant, f.slant),
                                   weight_key(weight, f.min_weight, f.max_weight));
        });
}

bool FontDatabase::covers(std::size_t face, char32_t c) const {
    if (face >= impl_->faces.size()) return false;
    if (FcCharSet* cs = impl_->charsets[face]) return FcCharSetHasChar(cs, static_cast<FcChar32>(c));
    try {
        return open(face).has_glyph(c);
    } catch (const Error&) { return false; }
}

std::optional<std::size_t> FontDatabase::fallback(char32_t c, int weight, FontSlant slant, double stretch,
                                                  bool system_faces) const {
    // Any family: the style matters most, then stretch and weight.
    return best_face(
        impl_->faces, [&](std::size_t i) { return (system_faces || !impl_->faces[i].system) && covers(i, c); },
        [&](const FontFaceInfo& f) {
            return std::make_tuple(slant_rank(slant, f.slant), stretch_key(stretch, f.stretch),
                                   weight_key(weight, f.min_weight, f.max_weight));
        });
}

Font FontDatabase::open(std::size_t face) const {
    if (face >= impl_->faces.size()) throw Error(ErrorKind::InvalidArgument, "font face index out of range");
    const FontFaceInfo& f = impl_->faces[face];
    std::lock_guard<std::mutex> lock(impl_->mutex);
    std::unique_ptr<Font>& slot = impl_->loaded[{f.path, f.index}];
    if (!slot) slot = std::make_unique<Font>(Font::load(f.path, f.index));
    return slot->clone();
}

}  // namespace casteljau
