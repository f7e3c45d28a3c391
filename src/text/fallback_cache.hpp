// Internal (text module): system font fallback's answers kept across processes, so that a process
// whose clusters were all answered before never starts fontconfig (reading its configuration and
// caches costs more than laying out a line).
//
// An answer is what SystemFallback::find found for one (query, cluster) key: a font file and face
// index, or none. The answers live in one file, `fallback_cache_path()`:
// $CASTELJAU_CACHE_DIR/fallback-1.cache when that variable is set (set and empty: no file),
// else $XDG_CACHE_HOME/casteljau/ (when absolute), else $HOME/.cache/casteljau/.
// With the answers the file keeps a stamp: the environment variables fontconfig reads (its
// configuration file and path, the locale it takes the default language from, the home and XDG
// folders) and the modification time and size of every configuration file, configuration folder
// and font folder fontconfig used (missing ones too: creating one changes the answers). The
// answers are used only while every stamp entry still has its recorded value.
//
// The file is untrusted input: parse_fallback_cache accepts exactly what format_fallback_cache
// writes, within the bounds below, and anything else makes the whole file ignored; a face it names
// is used only if it loads and maps every code point of the cluster. It is written through a
// temporary file renamed over it (casteljau/file_io.hpp), so readers see an old or a new file,
// never a part; of two processes writing at once the later one wins, and the other's new answers
// are only found again. Thread-safety: free functions, no shared state.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace casteljau::text_detail {

// Bounds of a file that is accepted (a real one holds a few hundred answers).
constexpr std::size_t kMaxCacheBytes = std::size_t(16) << 20;
constexpr std::size_t kMaxCacheAnswers = std::size_t(1) << 16;
constexpr std::size_t kMaxCacheFaces = 4096;
constexpr std::size_t kMaxCacheStamp = 4096;
constexpr std::size_t kMaxCacheKeyLength = 4096;  // code points of one key

struct FallbackCacheData {
    // (name, value): "env NAME" -> "=VALUE" or "-" (unset); "path P" -> "MTIME SIZE" or "-".
    std::vector<std::pair<std::string, std::string>> stamp;
    std::vector<std::pair<std::string, int>> faces;   // font file, face index
    std::unordered_map<std::u32string, int> answers;  // key -> index in faces, -1: no face
};

// The file's text for `data`, or nullopt when it cannot be written (a name holding a code point
// outside Unicode, more entries than the bounds above).
std::optional<std::string> format_fallback_cache(const FallbackCacheData& data);
// The data of a file's text, or nullopt unless the text is one format_fallback_cache can write.
std::optional<FallbackCacheData> parse_fallback_cache(std::string_view text);

// The current value of stamp entry `name` (as FallbackCacheData::stamp holds it).
std::string current_stamp_value(const std::string& name);
// The "env" entries of a stamp made now.
std::vector<std::pair<std::string, std::string>> environment_stamp();
// A stamp made now over the environment and `paths` (each file or folder once, in order).
std::vector<std::pair<std::string, std::string>> make_stamp(const std::vector<std::string>& paths);
// Whether every entry of `stamp` has its recorded value now and the environment entries are all there.
bool stamp_is_current(const std::vector<std::pair<std::string, std::string>>& stamp);

// The cache file's path, or "" when there is none (see above).
std::string fallback_cache_path();
// The file's data when it exists, parses and its stamp is current; nullopt otherwise.
std::optional<FallbackCacheData> load_fallback_cache(const std::string& path);
// Writes the file (creating its folder); false when it could not be written.
bool store_fallback_cache(const std::string& path, const FallbackCacheData& data);

}  // namespace casteljau::text_detail
