// Replays inputs through a fuzz target's LLVMFuzzerTestOneInput without libFuzzer, so that the
// seed corpus and the regression corpus (every input that ever failed) run under ctest with the
// normal compiler, and under AddressSanitizer in the sanitizer build.
// Usage: replay_TARGET FILE_OR_FOLDER...   (folders are read recursively; exit 0 when all ran)
// The target's LLVMFuzzerInitialize, when it has one, runs first, as under libFuzzer.
//
// Like libFuzzer's -malloc_limit_mb and -rss_limit_mb, the replay bounds memory: one allocation
// above 1 GiB (CASTELJAU_REPLAY_MALLOC_LIMIT_MB to change it) stops the replay with a message
// naming the input, and the address space is capped at 4 GiB. So an input that makes the code
// under test ask for far more than its size (a header declaring a 2 GiB chunk) fails here too,
// instead of passing on a machine with memory to spare and overcommit. Not under the sanitizers,
// which have their own allocator and need terabytes of address space for shadow memory.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
// A target's set-up, run once before the inputs as libFuzzer runs it (limits the target lowers);
// a weak reference, null for the targets that have none.
extern "C" [[gnu::weak]] int LLVMFuzzerInitialize(int* argc, char*** argv);

namespace {

[[maybe_unused]] std::size_t g_malloc_limit = 0;  // 0 until main() sets it: no check during static initialisation
[[maybe_unused]] const char* g_current = "";      // the input being replayed, for the message

int replay(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "replay: cannot read %s\n", file.string().c_str());
        return 1;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string name = file.string();
    g_current = name.c_str();
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    return 0;
}

#if defined(__SANITIZE_ADDRESS__)
#define CASTELJAU_REPLAY_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define CASTELJAU_REPLAY_SANITIZED 1
#endif
#endif

}  // namespace

#ifndef CASTELJAU_REPLAY_SANITIZED
// glibc's allocator under its own names; the replay's malloc, calloc and realloc check the size
// and forward (memalign and friends, rare and never sized by input here, go straight to glibc).
extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);

namespace {
[[noreturn]] void allocation_too_large(std::size_t bytes) {
    char msg[512];
    const int n = std::snprintf(msg, sizeof msg,
                                "replay: %s: one allocation of %zu bytes, above the %zu-byte limit (like libFuzzer's "
                                "-malloc_limit_mb)\n",
                                g_current, bytes, g_malloc_limit);
    if (n > 0) (void)!write(2, msg, static_cast<std::size_t>(std::min(n, static_cast<int>(sizeof msg) - 1)));
    std::abort();
}
}  // namespace

extern "C" void* malloc(std::size_t n) {
    if (g_malloc_limit != 0 && n > g_malloc_limit) allocation_too_large(n);
    return __libc_malloc(n);
}
extern "C" void* calloc(std::size_t n, std::size_t size) {
    if (g_malloc_limit != 0 && size != 0 && n > g_malloc_limit / size) allocation_too_large(n * size);
    return __libc_calloc(n, size);
}
extern "C" void* realloc(void* p, std::size_t n) {
    if (g_malloc_limit != 0 && n > g_malloc_limit) allocation_too_large(n);
    return __libc_realloc(p, n);
}
#endif

namespace {

void cap_memory() {
#ifndef CASTELJAU_REPLAY_SANITIZED
    long long mb = 1024;
    if (const char* env = std::getenv("CASTELJAU_REPLAY_MALLOC_LIMIT_MB")) mb = std::atoll(env);
    if (mb > 0) g_malloc_limit = static_cast<std::size_t>(mb) << 20;
    const rlimit lim{rlim_t{4} << 30, rlim_t{4} << 30};
    if (setrlimit(RLIMIT_AS, &lim) != 0) std::perror("replay: setrlimit");
#endif
}

}  // namespace

int main(int argc, char** argv) {
    cap_memory();
    if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
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
