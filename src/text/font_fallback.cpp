// Text stage, system font fallback: fontconfig's sorted list of faces per query, the first face
// covering a cluster, the process-wide caches of both, and the answers kept across processes
// (src/text/font_fallback.hpp, src/text/fallback_cache.hpp).
#include "text/font_fallback.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_TRUETYPE_TABLES_H
#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <set>
#include <mutex>
#include <unordered_map>
#include <utility>

#include "casteljau/error.hpp"
#include "text/fallback_cache.hpp"
#include "text/font_impl.hpp"

namespace casteljau::text_detail {

namespace {

// Entries of the (query, cluster) memo before it is emptied: a bound on its memory for processes
// that lay out endless distinct text.
constexpr std::size_t kMaxMemoEntries = 1u << 16;

// One face of a sorted list: its file, index and character set (owned by the list's FcFontSet).
struct Candidate {
    std::string file;
    int index = 0;
    FcCharSet* charset = nullptr;
};

struct SortedList {
    FcFontSet* set = nullptr;
    std::vector<Candidate> faces;
};

// The strings of a fontconfig string list.
std::vector<std::string> strings_of(FcStrList* list) {
    std::vector<std::string> out;
    if (!list) return out;
    while (FcChar8* s = FcStrListNext(list)) out.emplace_back(reinterpret_cast<const char*>(s));
    FcStrListDone(list);
    return out;
}

// What the answers of `config` depend on: its configuration files and their folders, its
// configuration and font folders, and the user configuration files it would read if they existed.
std::vector<std::string> configuration_paths(FcConfig* config) {
    std::vector<std::string> paths;
    for (const std::string& file : strings_of(FcConfigGetConfigFiles(config))) {
        paths.push_back(file);
        const std::size_t slash = file.find_last_of('/');
        if (slash != std::string::npos && slash > 0) paths.push_back(file.substr(0, slash));
    }
    for (const std::string& dir : strings_of(FcConfigGetConfigDirs(config))) paths.push_back(dir);
    for (const std::string& dir : strings_of(FcConfigGetFontDirs(config))) paths.push_back(dir);
    const char* home = std::getenv("HOME");
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const std::string config_home = xdg && *xdg     ? std::string(xdg)
                                    : home && *home ? std::string(home) + "/.config"
                                                    : "";
    if (!config_home.empty())
        for (const char* p : {"/fontconfig", "/fontconfig/fonts.conf", "/fontconfig/conf.d"})
            paths.push_back(config_home + p);
    if (home && *home)
        for (const char* p : {"/.fonts.conf", "/.fonts.conf.d"}) paths.push_back(std::string(home) + p);
    return paths;
}

// The answers kept across processes: read when fallback is first needed, written by the layouts
// that added to them.
struct PersistentAnswers {
    bool read = false;
    bool dirty = false;
    std::string path;
    FallbackCacheData data;
    std::map<std::pair<std::string, int>, int> face_numbers;  // (file, index) -> index in data.faces

    void load() {
        if (read) return;
        read = true;
        path = fallback_cache_path();
        if (auto d = load_fallback_cache(path)) data = std::move(*d);
        for (std::size_t i = 0; i < data.faces.size(); ++i) face_numbers.emplace(data.faces[i], static_cast<int>(i));
    }

    // Called with the stamp of the configuration fontconfig has just read: answers read from a
    // file whose stamp differs from it (something changed between the two) are dropped.
    void check_against(const std::vector<std::pair<std::string, std::string>>& stamp) {
        if (data.stamp.empty() || data.stamp == stamp) return;
        data = FallbackCacheData{};
        face_numbers.clear();
    }

    // The answer for `key`: null when there is none, else the face (null pair when "no face").
    const std::pair<std::string, int>* find(const std::u32string& key, bool& none) const {
        none = false;
        const auto it = data.answers.find(key);
        if (it == data.answers.end()) return nullptr;
        if (it->second < 0) {
            none = true;
            return nullptr;
        }
        return &data.faces[static_cast<std::size_t>(it->second)];
    }

    // Records the answer for `key` (`file` empty: no face).
    void remember(const std::u32string& key, const std::string& file, int index) {
        if (path.empty() || key.size() > kMaxCacheKeyLength) return;
        int face = -1;
        if (!file.empty()) {
            auto [it, added] = face_numbers.emplace(std::pair(file, index), static_cast<int>(data.faces.size()));
            if (added) {
                if (data.faces.size() >= kMaxCacheFaces) {
                    face_numbers.erase(it);
                    return;
                }
                data.faces.emplace_back(file, index);
            }
            face = it->second;
        }
        if (data.answers.size() >= kMaxCacheAnswers) data.answers.clear();
        auto [it, added] = data.answers.emplace(key, face);
        if (!added && it->second == face) return;
        it->second = face;
        dirty = true;
    }

    // Writes the answers with the stamp of the configuration that made them.
    void write(std::vector<std::pair<std::string, std::string>> stamp) {
        if (!dirty) return;
        dirty = false;
        data.stamp = std::move(stamp);
        store_fallback_cache(path, data);
    }
};

// The process-wide state: fontconfig's configuration (read once, when an answer is not kept from
// an earlier process), one sorted list per query, the memo of answers, the faces that failed to
// load, and the answers kept across processes.
struct Catalog {
    std::mutex mutex;
    bool started = false;
    FcConfig* config = nullptr;
    std::vector<std::pair<std::string, std::string>> stamp;  // made as fontconfig started
    std::map<std::string, SortedList> sorted;
    std::unordered_map<std::u32string, int> memo;    // query key + cluster -> face of the list, -1: none
    std::set<std::pair<std::string, int>> unusable;  // faces casteljau cannot load
    PersistentAnswers persistent;

    ~Catalog() {
        for (auto& [key, list] : sorted)
            if (list.set) FcFontSetDestroy(list.set);
        if (config) FcConfigDestroy(config);
    }

    bool start() {
        if (!started) {
            started = true;
            config = FcInitLoadConfigAndFonts();
            if (config) {
                stamp = make_stamp(configuration_paths(config));
                persistent.check_against(stamp);
            }
        }
        return config != nullptr;
    }

    const SortedList& list_for(const std::string& key, const std::string& family, const std::string& language,
                               int weight, bool italic) {
        auto it = sorted.find(key);
        if (it != sorted.end()) return it->second;
        SortedList list;
        FcPattern* p = FcPatternCreate();
        if (!p) throw std::bad_alloc();
        FcPatternAddString(p, FC_FAMILY, reinterpret_cast<const FcChar8*>(family.c_str()));
        if (!language.empty()) FcPatternAddString(p, FC_LANG, reinterpret_cast<const FcChar8*>(language.c_str()));
        FcPatternAddDouble(p, FC_WEIGHT, FcWeightFromOpenTypeDouble(weight));
        FcPatternAddInteger(p, FC_SLANT, italic ? FC_SLANT_ITALIC : FC_SLANT_ROMAN);
        FcConfigSubstitute(config, p, FcMatchPattern);
        FcDefaultSubstitute(p);
        FcResult result = FcResultMatch;
        list.set = FcFontSort(config, p, FcFalse, nullptr, &result);
        FcPatternDestroy(p);
        if (list.set) {
            for (int i = 0; i < list.set->nfont; ++i) {
                FcPattern* f = list.set->fonts[i];
                FcChar8* file = nullptr;
                int index = 0;
                FcCharSet* cs = nullptr;
                FcBool scalable = FcTrue, color = FcFalse;
                if (FcPatternGetString(f, FC_FILE, 0, &file) != FcResultMatch) continue;
                FcPatternGetInteger(f, FC_INDEX, 0, &index);
                if ((index >> 16) != 0) continue;  // a named instance: its variable face is listed too
                if (FcPatternGetCharSet(f, FC_CHARSET, 0, &cs) != FcResultMatch) continue;
                FcPatternGetBool(f, FC_SCALABLE, 0, &scalable);
                FcPatternGetBool(f, FC_COLOR, 0, &color);
                if (!scalable && !color) continue;  // bitmap text fonts: not drawable at any size
                list.faces.push_back({reinterpret_cast<const char*>(file), index, cs});
            }
        }
        return sorted.emplace(key, std::move(list)).first->second;
    }
};

Catalog& catalog() {
    static Catalog c;
    return c;
}

int base_weight(const Font& font) {
    for (std::size_t i = 0; i < font.axes().size(); ++i)
        if (font.axes()[i].tag == "wght") return static_cast<int>(font.variation_coordinates()[i]);
    const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(font.impl().face, FT_SFNT_OS2));
    if (os2 && os2->version != 0xffff && os2->usWeightClass >= 1 && os2->usWeightClass <= 1000)
        return os2->usWeightClass;
    return (font.impl().face->style_flags & FT_STYLE_FLAG_BOLD) ? 700 : 400;
}

// The code points with the Unicode property Emoji_Presentation (Unicode 15.0, as ICU 72 has
// them), as inclusive ranges in order: shown as emoji even without U+FE0F.
constexpr std::pair<char32_t, char32_t> kEmojiPresentation[] = {
    {0x231A, 0x231B},   {0x23E9, 0x23EC},   {0x23F0, 0x23F0},   {0x23F3, 0x23F3},   {0x25FD, 0x25FE},
    {0x2614, 0x2615},   {0x2648, 0x2653},   {0x267F, 0x267F},   {0x2693, 0x2693},   {0x26A1, 0x26A1},
    {0x26AA, 0x26AB},   {0x26BD, 0x26BE},   {0x26C4, 0x26C5},   {0x26CE, 0x26CE},   {0x26D4, 0x26D4},
    {0x26EA, 0x26EA},   {0x26F2, 0x26F3},   {0x26F5, 0x26F5},   {0x26FA, 0x26FA},   {0x26FD, 0x26FD},
    {0x2705, 0x2705},   {0x270A, 0x270B},   {0x2728, 0x2728},   {0x274C, 0x274C},   {0x274E, 0x274E},
    {0x2753, 0x2755},   {0x2757, 0x2757},   {0x2795, 0x2797},   {0x27B0, 0x27B0},   {0x27BF, 0x27BF},
    {0x2B1B, 0x2B1C},   {0x2B50, 0x2B50},   {0x2B55, 0x2B55},   {0x1F004, 0x1F004}, {0x1F0CF, 0x1F0CF},
    {0x1F18E, 0x1F18E}, {0x1F191, 0x1F19A}, {0x1F1E6, 0x1F1FF}, {0x1F201, 0x1F201}, {0x1F21A, 0x1F21A},
    {0x1F22F, 0x1F22F}, {0x1F232, 0x1F236}, {0x1F238, 0x1F23A}, {0x1F250, 0x1F251}, {0x1F300, 0x1F320},
    {0x1F32D, 0x1F335}, {0x1F337, 0x1F37C}, {0x1F37E, 0x1F393}, {0x1F3A0, 0x1F3CA}, {0x1F3CF, 0x1F3D3},
    {0x1F3E0, 0x1F3F0}, {0x1F3F4, 0x1F3F4}, {0x1F3F8, 0x1F43E}, {0x1F440, 0x1F440}, {0x1F442, 0x1F4FC},
    {0x1F4FF, 0x1F53D}, {0x1F54B, 0x1F54E}, {0x1F550, 0x1F567}, {0x1F57A, 0x1F57A}, {0x1F595, 0x1F596},
    {0x1F5A4, 0x1F5A4}, {0x1F5FB, 0x1F64F}, {0x1F680, 0x1F6C5}, {0x1F6CC, 0x1F6CC}, {0x1F6D0, 0x1F6D2},
    {0x1F6D5, 0x1F6D7}, {0x1F6DC, 0x1F6DF}, {0x1F6EB, 0x1F6EC}, {0x1F6F4, 0x1F6FC}, {0x1F7E0, 0x1F7EB},
    {0x1F7F0, 0x1F7F0}, {0x1F90C, 0x1F93A}, {0x1F93C, 0x1F945}, {0x1F947, 0x1F9FF}, {0x1FA70, 0x1FA7C},
    {0x1FA80, 0x1FA88}, {0x1FA90, 0x1FABD}, {0x1FABF, 0x1FAC5}, {0x1FACE, 0x1FADB}, {0x1FAE0, 0x1FAE8},
    {0x1FAF0, 0x1FAF8},
};

bool is_emoji_presentation(char32_t c) {
    const auto* end = std::end(kEmojiPresentation);
    const auto* it = std::upper_bound(std::begin(kEmojiPresentation), end, c,
                                      [](char32_t v, const std::pair<char32_t, char32_t>& r) { return v < r.first; });
    return it != std::begin(kEmojiPresentation) && c <= (it - 1)->second;
}

bool covers(const Candidate& c, std::u32string_view needed) {
    return std::all_of(needed.begin(), needed.end(),
                       [&](char32_t ch) { return FcCharSetHasChar(c.charset, static_cast<FcChar32>(ch)); });
}

bool maps_all(const Font& font, std::u32string_view needed) {
    return std::all_of(needed.begin(), needed.end(), [&](char32_t ch) { return font.has_glyph(ch); });
}

}  // namespace

bool is_fallback_ignorable(char32_t c) {
    return c == 0x200c || c == 0x200d || (c >= 0xfe00 && c <= 0xfe0f) || (c >= 0xe0100 && c <= 0xe01ef) ||
           (c >= 0xe0020 && c <= 0xe007f) || c == 0x034f || (c >= 0x180b && c <= 0x180d) || c == 0x2060 || c == 0xfeff;
}

bool is_emoji_cluster(std::u32string_view cluster) {
    if (cluster.empty()) return false;
    if (is_emoji_presentation(cluster[0])) return true;
    return std::any_of(cluster.begin() + 1, cluster.end(),
                       [](char32_t c) { return c == 0xfe0f || c == 0x20e3 || (c >= 0x1f3fb && c <= 0x1f3ff); });
}

SystemFallback::SystemFallback(const Font& base, std::string language)
    : family_(base.family_name()),
      language_(std::move(language)),
      weight_(base_weight(base)),
      italic_((base.impl().face->style_flags & FT_STYLE_FLAG_ITALIC) != 0) {}

SystemFallback::~SystemFallback() {
    Catalog& cat = catalog();
    try {
        std::lock_guard<std::mutex> lock(cat.mutex);
        if (cat.config) cat.persistent.write(cat.stamp);
    } catch (...) {}  // the answers are found again by the next process
}

const Font* SystemFallback::find(std::u32string_view cluster) {
    std::u32string needed;
    for (char32_t c : cluster)
        if (!is_fallback_ignorable(c)) needed.push_back(c);
    if (needed.empty()) return nullptr;
    const bool emoji = is_emoji_cluster(cluster);
    const std::string& family = emoji ? std::string("emoji") : family_;
    const std::string key = family + '\n' + language_ + '\n' + std::to_string(weight_) + (italic_ ? "i" : "r");

    std::u32string memo_key;
    for (const unsigned char c : key) memo_key.push_back(c);
    memo_key += U'\0';
    memo_key += needed;

    Catalog& cat = catalog();
    std::lock_guard<std::mutex> lock(cat.mutex);
    cat.persistent.load();
    bool none = false;
    if (const auto* face = cat.persistent.find(memo_key, none)) {
        if (const Font* f = font_for(face->first, face->second, &needed)) return f;
    } else if (none) {
        return nullptr;
    }
    if (!cat.start()) return nullptr;
    const SortedList& list = cat.list_for(key, family, language_, weight_, italic_);
    const auto memo = cat.memo.find(memo_key);
    std::size_t i = memo != cat.memo.end() ? static_cast<std::size_t>(memo->second) : 0;
    // The first face that covers the cluster and loads (a face that fails to load is skipped from
    // then on, and the answer is looked for again).
    for (; i < list.faces.size(); ++i) {
        const Candidate& c = list.faces[i];
        if (cat.unusable.count({c.file, c.index}) || !covers(c, needed)) continue;
        if (const Font* f = font_for(c.file, c.index)) {
            cat.persistent.remember(memo_key, c.file, c.index);
            if (memo == cat.memo.end()) {
                if (cat.memo.size() >= kMaxMemoEntries) cat.memo.clear();
                cat.memo.emplace(std::move(memo_key), static_cast<int>(i));
            }
            return f;
        }
        cat.unusable.insert({c.file, c.index});
    }
    cat.persistent.remember(memo_key, std::string(), 0);
    if (memo == cat.memo.end()) {
        if (cat.memo.size() >= kMaxMemoEntries) cat.memo.clear();
        cat.memo.emplace(std::move(memo_key), static_cast<int>(list.faces.size()));
    }
    return nullptr;
}

const Font* SystemFallback::font_for(const std::string& file, int index, const std::u32string* must_map) {
    for (std::size_t k = 0; k < font_ids_.size(); ++k)
        if (font_ids_[k].first == file && font_ids_[k].second == index)
            return !must_map || maps_all(*fonts_[k], *must_map) ? fonts_[k].get() : nullptr;
    std::shared_ptr<Font> font;
    try {
        font = std::make_shared<Font>(Font::load(file, index));
        if (must_map && !maps_all(*font, *must_map)) return nullptr;
        for (const VariationAxis& a : font->axes())
            if (a.tag == "wght") font->set_variations(std::vector<Variation>{{"wght", static_cast<double>(weight_)}});
    } catch (const Error&) { return nullptr; }
    fonts_.push_back(font);
    font_ids_.emplace_back(file, index);
    return font.get();
}

}  // namespace casteljau::text_detail
