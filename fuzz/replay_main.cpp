// Replays inputs through a fuzz target's LLVMFuzzerTestOneInput without libFuzzer, so that the
// seed corpus and the regression corpus (every input that ever failed) run under ctest with the
// normal compiler, and under AddressSanitizer in the sanitizer build.
// Usage: replay_TARGET FILE_OR_FOLDER...   (folders are read recursively; exit 0 when all ran)
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

int replay(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "replay: cannot read %s\n", file.string().c_str());
        return 1;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    int files = 0, failures = 0;
    for (int i = 1; i < argc; ++i) {
        const fs::path p(argv[i]);
        if (fs::is_directory(p)) {
            std::vector<fs::path> all;
            for (const auto& e : fs::recursive_directory_iterator(p))
                if (e.is_regular_file()) all.push_back(e.path());
            std::sort(all.begin(), all.end());
            for (const fs::path& f : all) failures += replay(f), ++files;
        } else if (fs::exists(p)) {
            failures += replay(p), ++files;
        }
    }
    std::printf("replayed %d inputs\n", files);
    if (files == 0) {
        std::fprintf(stderr, "replay: no inputs found\n");
        return 1;
    }
    return failures == 0 ? 0 : 1;
}
