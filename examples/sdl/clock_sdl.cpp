// example_sdl_clock: the clock of examples/clock.cpp as a live, ticking clock in an SDL2 window.
// Every frame is drawn by a casteljau::Canvas straight into the pixel buffer of a streaming SDL
// texture (SDL_LockTexture gives its memory and pitch; SDL_PIXELFORMAT_RGBA32 is casteljau's byte
// order), which the renderer then presents.
//
//   example_sdl_clock [--frames N] [--time HH:MM:SS] [--screenshot OUT.png] [--size PX]
//
// Without --frames it runs until the window is closed (or Escape); --time freezes the clock at a
// time (for tests); --screenshot writes the last presented frame, read back from the renderer.
// Exit status 0 on success, 1 when SDL or the screenshot fails, 2 for bad arguments.
#include <SDL.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <string>
#include <vector>

#include "../clock_face.hpp"
#include "casteljau/png.hpp"

namespace {

int fail(const char* what) {
    std::fprintf(stderr, "example_sdl_clock: error: %s: %s\n", what, SDL_GetError());
    SDL_Quit();
    return 1;
}

clock_face::Time now() {
    const std::time_t t = std::time(nullptr);
    std::tm local{};
    localtime_r(&t, &local);
    return {local.tm_hour, local.tm_min, local.tm_sec};
}

}  // namespace

int main(int argc, char** argv) {
    long frames = -1;
    int size = 400;
    bool frozen = false;
    clock_face::Time fixed;
    std::string screenshot;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--frames" && has_value)
            frames = std::strtol(argv[++i], nullptr, 10);
        else if (a == "--size" && has_value)
            size = static_cast<int>(std::strtol(argv[++i], nullptr, 10));
        else if (a == "--screenshot" && has_value)
            screenshot = argv[++i];
        else if (a == "--time" && has_value) {
            frozen = true;
            if (!clock_face::parse_time(argv[++i], fixed)) {
                std::fprintf(stderr, "example_sdl_clock: error: expected HH:MM:SS, got '%s'\n", argv[i]);
                return 2;
            }
        } else {
            std::fprintf(
                stderr, "usage: example_sdl_clock [--frames N] [--time HH:MM:SS] [--screenshot OUT.png] [--size PX]\n");
            return 2;
        }
    }
    if (size < 32 || size > 4096 || frames == 0 || frames < -1) {
        std::fprintf(stderr, "example_sdl_clock: error: --size must be 32 to 4096 and --frames positive\n");
        return 2;
    }
    if (SDL_Init(SDL_INIT_VIDEO) != 0) return fail("SDL_Init");
    SDL_Window* window =
        SDL_CreateWindow("casteljau clock", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, size, size, 0);
    if (!window) return fail("SDL_CreateWindow");
    SDL_Renderer* renderer = SDL_CreateRenderer(window, -1, 0);
    if (!renderer) renderer = SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE);
    if (!renderer) return fail("SDL_CreateRenderer");
    SDL_Texture* texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, size, size);
    if (!texture) return fail("SDL_CreateTexture");
    try {
        bool running = true;
        for (long frame = 0; running && (frames < 0 || frame < frames); ++frame) {
            SDL_Event e;
            while (SDL_PollEvent(&e))
                if (e.type == SDL_QUIT || (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE)) running = false;
            void* pixels = nullptr;
            int pitch = 0;
            if (SDL_LockTexture(texture, nullptr, &pixels, &pitch) != 0) return fail("SDL_LockTexture");
            {
                casteljau::Canvas canvas(static_cast<std::uint8_t*>(pixels), size, size,
                                         static_cast<std::size_t>(pitch));
                clock_face::draw_into(canvas, frozen ? fixed : now(), size);
            }
            SDL_UnlockTexture(texture);
            SDL_RenderClear(renderer);
            SDL_RenderCopy(renderer, texture, nullptr, nullptr);
            if (!screenshot.empty() && frames > 0 && frame == frames - 1) {
                // Read the frame back before presenting (the back buffer is undefined afterwards).
                casteljau::Pixmap shot(size, size);
                if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGBA32, shot.data(),
                                         static_cast<int>(shot.stride())) != 0)
                    return fail("SDL_RenderReadPixels");
                casteljau::write_png(shot, screenshot);  // the clock is opaque: straight = premultiplied
            }
            SDL_RenderPresent(renderer);
            SDL_Delay(frozen ? 10 : 100);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "example_sdl_clock: error: %s\n", e.what());
        SDL_Quit();
        return 1;
    }
    SDL_DestroyTexture(texture);
    SDL_DestroyRenderer(renderer);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return 0;
}
