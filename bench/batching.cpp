// SPDX-License-Identifier: MIT
// Sprite batching of e2d::render, three groups, each with its own table:
//  build/<sprites>/<motion>/e2d  the CPU cost of a frame's instance data (SpriteBatcher alone, no
//                                OpenGL): the moving sprites' setPosition(), prepare() (repack the
//                                changed ones) and emit() (cull and copy every sprite's 32 bytes
//                                into the frame's buffer), ns per sprite. The camera pans a little
//                                every frame, so emit() runs every frame even when nothing moves
//                                (a frame where nothing at all changed skips it).
//  frame/<scene>/<engine>        whole frames into a 1024 x 720 offscreen target under Mesa
//                                llvmpipe, glFinish() included, ms per frame: e2d's Renderer,
//                                SFML 2.5 with one sf::Sprite draw per sprite, SFML with one
//                                sf::VertexArray per texture, SDL2's renderer on its OpenGL
//                                backend with one SDL_RenderCopyF per sprite (SDL batches them)
//                                and with one SDL_RenderGeometry per texture, and a naive OpenGL
//                                path (one glDrawArrays per sprite with per-sprite uniforms, as
//                                the seed did).
//  text/<case>/<engine>          the same ~1 000-glyph string (alternating with a same-length
//                                variant, so each frame lays it out anew) laid out, batched and
//                                drawn: e2d's TextRenderer vs sf::Text; ns per glyph.
// Every frame case ends with a read-back of its last frame and reports `lit` (the fraction of
// pixels not the clear colour); the run fails (exit status 1) when a case reports an error or
// the engines of a case disagree on `lit` by more than 1 % of the pixels.
// Flags besides Google Benchmark's: --e2d_table=PATH (the Markdown tables), --e2d_shots=DIR (each
// frame case's last frame as a PNG), --e2d_warmup=N (frames drawn before timing, default 3).
#include <e2d/render/camera.hpp>
#include <e2d/render/renderer.hpp>
#include <e2d/render/text_renderer.hpp>
#include <e2d/render/window.hpp>

#include "ratio_reporter.hpp"
#include "sprite_batcher.hpp"

#include <GL/glew.h>
#include <SDL.h>
#include <SFML/Graphics.hpp>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace e2d::render;

constexpr int kWidth = 1024;
constexpr int kHeight = 720;
constexpr int kTextures = 8;

// ---------------------------------------------------------------------------------------------
// Scenes, the same for every engine.

struct SceneSprite {
    glm::vec2 position; // centre, world units = pixels, origin at the target's centre
    glm::vec2 velocity; // pixels per frame (0 for static sprites)
    int texture;        // 0..kTextures-1 (the sheet case: 0)
    int frame;          // animation frame (the sheet case), else 0
};

struct Scene {
    std::vector<SceneSprite> sprites;
    int spriteSize = 8; // pixels, square
    bool sheet = false; // one 8-frame sheet, every sprite animated
    int moving = 0;     // the first `moving` sprites move
};

Scene makeScene(int count, int movingPercent, bool sheet, int spriteSize) {
    Scene scene;
    scene.sheet = sheet;
    scene.spriteSize = spriteSize;
    scene.moving = count * movingPercent / 100;
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> x(-kWidth * 0.5f + 16.0f, kWidth * 0.5f - 16.0f);
    std::uniform_real_distribution<float> y(-kHeight * 0.5f + 16.0f, kHeight * 0.5f - 16.0f);
    std::uniform_real_distribution<float> v(-1.0f, 1.0f);
    scene.sprites.resize(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        SceneSprite& s = scene.sprites[static_cast<std::size_t>(i)];
        s.position = {x(rng), y(rng)};
        s.velocity = i < scene.moving ? glm::vec2(v(rng), v(rng)) : glm::vec2(0.0f);
        s.texture = sheet ? 0 : i % kTextures;
        s.frame = i % 8;
    }
    return scene;
}

// One frame of the scene's logic: moving sprites bounce inside the view; in the sheet scene
// every sprite shows the next frame every fourth frame (a 15 fps animation at 60 fps), a
// quarter of them each frame. Calls moved(i) / animated(i) for what changed.
template <class Moved, class Animated>
void step(Scene& scene, int frameNumber, Moved&& moved, Animated&& animated) {
    const float hx = kWidth * 0.5f - 8.0f;
    const float hy = kHeight * 0.5f - 8.0f;
    for (int i = 0; i < scene.moving; ++i) {
        SceneSprite& s = scene.sprites[static_cast<std::size_t>(i)];
        s.position += s.velocity;
        if (std::abs(s.position.x) > hx) {
            s.velocity.x = -s.velocity.x;
        }
        if (std::abs(s.position.y) > hy) {
            s.velocity.y = -s.velocity.y;
        }
        moved(i);
    }
    if (scene.sheet) {
        const int count = static_cast<int>(scene.sprites.size());
        for (int i = frameNumber % 4; i < count; i += 4) {
            SceneSprite& s = scene.sprites[static_cast<std::size_t>(i)];
            s.frame = (s.frame + 1) % 8;
            animated(i);
        }
    }
}

// RGBA8 images: 8 textures of solid colours with a darker border (opaque), or one 256 x 32
// sheet of 8 frames, each a disc (alpha 0 or 255) whose colour changes with the frame.
std::vector<std::uint8_t> textureImage(int index, int size) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size * size * 4));
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const bool border = x == 0 || y == 0 || x == size - 1 || y == size - 1;
            std::uint8_t* p = &rgba[static_cast<std::size_t>((y * size + x) * 4)];
            p[0] = static_cast<std::uint8_t>((index & 1) != 0 ? 255 : 60);
            p[1] = static_cast<std::uint8_t>((index & 2) != 0 ? 255 : 60);
            p[2] = static_cast<std::uint8_t>((index & 4) != 0 ? 255 : 60);
            if (border) {
                p[0] /= 2;
                p[1] /= 2;
                p[2] /= 2;
            }
            p[3] = 255;
        }
    }
    return rgba;
}

constexpr int kFrame = 32;
std::vector<std::uint8_t> sheetImage() {
    const int w = kFrame * 8;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w * kFrame * 4));
    for (int y = 0; y < kFrame; ++y) {
        for (int x = 0; x < w; ++x) {
            const int f = x / kFrame;
            const float dx = static_cast<float>(x % kFrame) + 0.5f - kFrame * 0.5f;
            const float dy = static_cast<float>(y) + 0.5f - kFrame * 0.5f;
            const bool inside =
                dx * dx + dy * dy <= (kFrame * 0.5f - 1.0f) * (kFrame * 0.5f - 1.0f);
            std::uint8_t* p = &rgba[static_cast<std::size_t>((y * w + x) * 4)];
            p[0] = static_cast<std::uint8_t>(255 - f * 30);
            p[1] = static_cast<std::uint8_t>(40 + f * 25);
            p[2] = static_cast<std::uint8_t>(y * 8);
            p[3] = inside ? 255 : 0;
        }
    }
    return rgba;
}

// UV rectangle of a sheet frame (fractions, top-left origin).
Rect frameUv(int frame) {
    return Rect{{static_cast<float>(frame) / 8.0f, 0.0f}, {1.0f / 8.0f, 1.0f}};
}

double litFraction(const std::uint8_t* rgba, std::size_t pixels) {
    std::size_t lit = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* p = rgba + i * 4;
        lit += (p[0] | p[1] | p[2]) != 0 ? 1u : 0u;
    }
    return static_cast<double>(lit) / static_cast<double>(pixels);
}

// ---------------------------------------------------------------------------------------------
// build: the CPU side alone.

// `pan`: the camera moves a pixel back and forth every frame (the view always holds every
// sprite), so every frame's instances are culled and copied again; without it a frame in which
// nothing moved writes nothing (as Renderer::render() redraws last frame's instances).
void buildCase(benchmark::State& state, int count, int movingPercent, bool pan) {
    std::vector<detail::TextureFacts> textures(2 + kTextures);
    for (auto& t : textures) {
        t.size = {16.0f, 16.0f};
        t.generation = 1;
    }
    detail::SpriteBatcher batcher(textures, 0, 1);
    Scene scene = makeScene(count, movingPercent, false, 8);
    std::vector<SpriteId> ids;
    ids.reserve(scene.sprites.size());
    for (const SceneSprite& s : scene.sprites) {
        SpriteDef def;
        def.texture = TextureId{static_cast<std::uint32_t>(3 + s.texture), 1};
        def.position = s.position;
        def.size = {8.0f, 8.0f};
        ids.push_back(batcher.create(def));
    }
    std::vector<detail::Instance> dst;
    std::vector<detail::Batch> batches;
    detail::BuildCounts counts;
    int frameNumber = 0;
    std::int64_t emitted = 0;
    auto frame = [&] {
        step(
            scene, frameNumber,
            [&](int i) {
                batcher.setPosition(ids[static_cast<std::size_t>(i)],
                                    scene.sprites[static_cast<std::size_t>(i)].position);
            },
            [](int) {});
        const float dx = pan && (frameNumber & 1) != 0 ? 1.0f : 0.0f;
        detail::CameraState camera{{dx, 0.0f}, 0.0f, 1.0f};
        detail::ViewBounds view{{-kWidth + dx, -kHeight * 1.0f}, {kWidth + dx, kHeight * 1.0f}};
        bool changed = false;
        const std::size_t most = batcher.prepare(camera, view, changed);
        if (changed) {
            if (dst.size() < most) {
                dst.resize(most);
            }
            batcher.emit(dst.data(), batches, counts);
            ++emitted;
        }
        benchmark::DoNotOptimize(dst.data());
        benchmark::ClobberMemory();
        ++frameNumber;
    };
    // The first frame sorts and packs every sprite: setup, not timed.
    frame();
    emitted = 0;
    for (auto _ : state) {
        frame();
    }
    if (counts.drawn != count || batches.size() != kTextures) {
        state.SkipWithError("the batcher did not draw every sprite in one batch per texture");
    }
    state.counters["emitted_frames"] =
        static_cast<double>(emitted) / static_cast<double>(state.iterations());
    state.counters["batches"] = static_cast<double>(batches.size());
    state.SetItemsProcessed(state.iterations() * count);
}

// ---------------------------------------------------------------------------------------------
// Whole frames.

// SDL2's renderer on its OpenGL backend, drawing into a render-target texture of a hidden
// window (its own GL context, as SFML has its own).
struct SdlTarget {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_GLContext context = nullptr;
    SDL_Texture* target = nullptr;

    SdlTarget() = default;
    SdlTarget(const SdlTarget&) = delete;
    SdlTarget& operator=(const SdlTarget&) = delete;
    ~SdlTarget() {
        if (target != nullptr) {
            SDL_DestroyTexture(target);
        }
        if (renderer != nullptr) {
            SDL_DestroyRenderer(renderer);
        }
        if (window != nullptr) {
            SDL_DestroyWindow(window);
        }
        SDL_Quit();
    }

    // Empty, or why SDL's OpenGL renderer is not available.
    std::string create() {
        SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
        SDL_SetHint(SDL_HINT_RENDER_DRIVER, "opengl");
        SDL_SetHint(SDL_HINT_RENDER_BATCHING, "1");
        if (SDL_Init(SDL_INIT_VIDEO) != 0) {
            return std::string("SDL_Init: ") + SDL_GetError();
        }
        window = SDL_CreateWindow("e2d batching bench (SDL2)", 0, 0, kWidth, kHeight,
                                  SDL_WINDOW_OPENGL | SDL_WINDOW_HIDDEN);
        if (window == nullptr) {
            return std::string("SDL_CreateWindow: ") + SDL_GetError();
        }
        renderer =
            SDL_CreateRenderer(window, -1, SDL_RENDERER_ACCELERATED | SDL_RENDERER_TARGETTEXTURE);
        SDL_RendererInfo info{};
        if (renderer == nullptr || SDL_GetRendererInfo(renderer, &info) != 0 ||
            std::string(info.name) != "opengl") {
            return std::string("no SDL OpenGL renderer: ") + SDL_GetError();
        }
        context = SDL_GL_GetCurrentContext();
        // ABGR8888 is R, G, B, A in memory on little-endian machines: Image's byte order.
        target = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_ABGR8888, SDL_TEXTUREACCESS_TARGET,
                                   kWidth, kHeight);
        if (target == nullptr || SDL_SetRenderTarget(renderer, target) != 0) {
            return std::string("SDL render target: ") + SDL_GetError();
        }
        return {};
    }
};

// What every frame engine shares: the e2d window (its context also runs the naive path), the
// SFML render texture (SFML's own context) and SDL's renderer (SDL's own context).
struct Targets {
    std::unique_ptr<Window> window;
    sf::RenderTexture sfml;
    SdlTarget sdl;
    std::string error;
    std::string shots;   // --e2d_shots=DIR: each frame case's last frame as DIR/<case>.png
    std::string running; // the case being run
    int warmup = 3;      // frames drawn before timing

    // Draws `warmup` untimed frames, then one frame per benchmark iteration.
    template <class Frame>
    void run(benchmark::State& state, Frame& frame) const {
        for (int i = 0; i < warmup; ++i) {
            frame();
        }
        for (auto _ : state) {
            frame();
        }
    }

    void shot(const benchmark::State&, Image image) const {
        if (shots.empty()) {
            return;
        }
        std::string name = running;
        for (char& c : name) {
            c = c == '/' ? '_' : c;
        }
        writePng(image, std::filesystem::path(shots) / (name + ".png"));
    }

    // SFML tracks which of its contexts it thinks is current; GLFW changed it behind its back.
    void activateSfml() {
        (void)sfml.setActive(false);
        (void)sfml.setActive(true);
    }
    void activateE2d() {
        (void)sfml.setActive(false);
        window->makeCurrent();
    }
    // SDL skips SDL_GL_MakeCurrent() when it believes its context is still current, which it
    // is not after GLFW or SFML made theirs current: release it first, then take it.
    void activateSdl() {
        SDL_GL_MakeCurrent(sdl.window, nullptr);
        SDL_GL_MakeCurrent(sdl.window, sdl.context);
    }
};

// Frames drawn before timing: llvmpipe compiles each shader variant at its first draw and the
// glyph atlases fill at the first text frame; neither is what a frame costs.
// (Targets::warmup, --e2d_warmup=N; the short CTest run uses 1.)

// Every engine samples its textures the same way: nearest texel, SFML's default (an
// sf::Texture that is not smooth), so each draws the same pixels with the same work.
constexpr TextureDef kSameFilter{.filter = TextureFilter::Nearest};

// e2d's Renderer into an offscreen framebuffer of the hidden window.
void frameE2d(benchmark::State& state, Targets& targets, Scene scene, const RendererDef& base) {
    targets.activateE2d();
    RendererDef def = base;
    def.offscreenSize = {kWidth, kHeight};
    Renderer renderer(*targets.window, def);
    std::vector<TextureId> textures;
    if (scene.sheet) {
        textures.push_back(
            renderer.createTexture(Image{kFrame * 8, kFrame, sheetImage()}, kSameFilter));
    } else {
        for (int t = 0; t < kTextures; ++t) {
            textures.push_back(
                renderer.createTexture(Image{16, 16, textureImage(t, 16)}, kSameFilter));
        }
    }
    std::vector<SpriteId> ids;
    ids.reserve(scene.sprites.size());
    for (const SceneSprite& s : scene.sprites) {
        SpriteDef sd;
        sd.texture = textures[static_cast<std::size_t>(s.texture)];
        sd.position = s.position;
        sd.size = glm::vec2(static_cast<float>(scene.spriteSize));
        if (scene.sheet) {
            sd.uv = frameUv(s.frame);
        }
        ids.push_back(renderer.createSprite(sd));
    }
    CameraDef cd;
    cd.referenceSize = {kWidth, kHeight};
    Camera camera(cd);
    int frameNumber = 0;
    auto frame = [&] {
        step(
            scene, frameNumber,
            [&](int i) {
                renderer.setPosition(ids[static_cast<std::size_t>(i)],
                                     scene.sprites[static_cast<std::size_t>(i)].position);
            },
            [&](int i) {
                renderer.setUv(ids[static_cast<std::size_t>(i)],
                               frameUv(scene.sprites[static_cast<std::size_t>(i)].frame));
            });
        renderer.render(camera);
        glFinish();
        ++frameNumber;
    };
    targets.run(state, frame);
    const Image image = renderer.readPixels();
    targets.shot(state, image);
    state.counters["lit"] = litFraction(image.pixels.data(), image.pixels.size() / 4);
    state.counters["draw_calls"] = renderer.stats().drawCalls;
    state.counters["persistent"] = renderer.persistentMapping() ? 1.0 : 0.0;
    state.SetItemsProcessed(state.iterations());
}

std::vector<sf::Texture> sfmlTextures(const Scene& scene) {
    std::vector<sf::Texture> textures(scene.sheet ? 1 : kTextures);
    if (scene.sheet) {
        (void)textures[0].create(kFrame * 8, kFrame);
        textures[0].update(sheetImage().data());
    } else {
        for (int t = 0; t < kTextures; ++t) {
            (void)textures[static_cast<std::size_t>(t)].create(16, 16);
            textures[static_cast<std::size_t>(t)].update(textureImage(t, 16).data());
        }
    }
    return textures;
}

// SFML's view: world units = pixels, y up, origin at the centre (as the e2d camera).
sf::View sfmlView() {
    sf::View view(sf::FloatRect(-kWidth * 0.5f, kHeight * 0.5f, kWidth, -kHeight));
    return view;
}

sf::IntRect sfmlFrameRect(const Scene& scene, int frame) {
    return scene.sheet ? sf::IntRect(frame * kFrame, 0, kFrame, kFrame) : sf::IntRect(0, 0, 16, 16);
}

void finishSfml(benchmark::State& state, Targets& targets) {
    const sf::Image image = targets.sfml.getTexture().copyToImage();
    const sf::Vector2u size = image.getSize();
    state.counters["lit"] =
        litFraction(image.getPixelsPtr(), static_cast<std::size_t>(size.x) * size.y);
    // copyToImage() gives rows from the top, as Image has them.
    const std::size_t bytes = static_cast<std::size_t>(size.x) * size.y * 4;
    targets.shot(state, Image{static_cast<int>(size.x), static_cast<int>(size.y),
                              std::vector<std::uint8_t>(image.getPixelsPtr(),
                                                        image.getPixelsPtr() + bytes)});
    state.SetItemsProcessed(state.iterations());
}

void frameSfmlSprites(benchmark::State& state, Targets& targets, Scene scene) {
    targets.activateSfml();
    std::vector<sf::Texture> textures = sfmlTextures(scene);
    std::vector<sf::Sprite> sprites(scene.sprites.size());
    const float scale = static_cast<float>(scene.spriteSize) / (scene.sheet ? kFrame : 16.0f);
    for (std::size_t i = 0; i < sprites.size(); ++i) {
        const SceneSprite& s = scene.sprites[i];
        sf::Sprite& sp = sprites[i];
        sp.setTexture(textures[static_cast<std::size_t>(s.texture)]);
        sp.setTextureRect(sfmlFrameRect(scene, s.frame));
        const sf::IntRect r = sp.getTextureRect();
        sp.setOrigin(static_cast<float>(r.width) * 0.5f, static_cast<float>(r.height) * 0.5f);
        // The view flips y; flip the sprite back so its image is upright as in e2d.
        sp.setScale(scale, -scale);
        sp.setPosition(s.position.x, s.position.y);
    }
    targets.sfml.setView(sfmlView());
    int frameNumber = 0;
    auto frame = [&] {
        step(
            scene, frameNumber,
            [&](int i) {
                const glm::vec2 p = scene.sprites[static_cast<std::size_t>(i)].position;
                sprites[static_cast<std::size_t>(i)].setPosition(p.x, p.y);
            },
            [&](int i) {
                sprites[static_cast<std::size_t>(i)].setTextureRect(
                    sfmlFrameRect(scene, scene.sprites[static_cast<std::size_t>(i)].frame));
            });
        targets.sfml.clear(sf::Color::Black);
        for (const sf::Sprite& sp : sprites) {
            targets.sfml.draw(sp);
        }
        targets.sfml.display();
        glFinish();
        ++frameNumber;
    };
    targets.run(state, frame);
    finishSfml(state, targets);
}

void frameSfmlVertexArrays(benchmark::State& state, Targets& targets, Scene scene) {
    targets.activateSfml();
    std::vector<sf::Texture> textures = sfmlTextures(scene);
    std::vector<sf::VertexArray> arrays(textures.size(), sf::VertexArray(sf::Quads));
    std::vector<std::size_t> slot(scene.sprites.size()); // first vertex of each sprite's quad
    for (std::size_t i = 0; i < scene.sprites.size(); ++i) {
        sf::VertexArray& va = arrays[static_cast<std::size_t>(scene.sprites[i].texture)];
        slot[i] = va.getVertexCount();
        va.resize(va.getVertexCount() + 4);
    }
    const float half = static_cast<float>(scene.spriteSize) * 0.5f;
    auto place = [&](std::size_t i) {
        const SceneSprite& s = scene.sprites[i];
        sf::Vertex* v = &arrays[static_cast<std::size_t>(s.texture)][slot[i]];
        v[0].position = {s.position.x - half, s.position.y + half};
        v[1].position = {s.position.x + half, s.position.y + half};
        v[2].position = {s.position.x + half, s.position.y - half};
        v[3].position = {s.position.x - half, s.position.y - half};
    };
    auto look = [&](std::size_t i) {
        const SceneSprite& s = scene.sprites[i];
        const sf::IntRect r = sfmlFrameRect(scene, s.frame);
        sf::Vertex* v = &arrays[static_cast<std::size_t>(s.texture)][slot[i]];
        const auto l = static_cast<float>(r.left);
        const auto t = static_cast<float>(r.top);
        const auto rr = static_cast<float>(r.left + r.width);
        const auto b = static_cast<float>(r.top + r.height);
        v[0].texCoords = {l, t};
        v[1].texCoords = {rr, t};
        v[2].texCoords = {rr, b};
        v[3].texCoords = {l, b};
    };
    for (std::size_t i = 0; i < scene.sprites.size(); ++i) {
        place(i);
        look(i);
    }
    targets.sfml.setView(sfmlView());
    int frameNumber = 0;
    auto frame = [&] {
        step(
            scene, frameNumber, [&](int i) { place(static_cast<std::size_t>(i)); },
            [&](int i) { look(static_cast<std::size_t>(i)); });
        targets.sfml.clear(sf::Color::Black);
        for (std::size_t t = 0; t < arrays.size(); ++t) {
            targets.sfml.draw(arrays[t], sf::RenderStates(&textures[t]));
        }
        targets.sfml.display();
        glFinish();
        ++frameNumber;
    };
    targets.run(state, frame);
    finishSfml(state, targets);
}

// SDL2: textures as SDL makes them, nearest sampling and alpha blending as the other engines.
std::vector<SDL_Texture*> sdlTextures(SDL_Renderer* renderer, const Scene& scene) {
    std::vector<SDL_Texture*> textures;
    const int count = scene.sheet ? 1 : kTextures;
    for (int t = 0; t < count; ++t) {
        const int w = scene.sheet ? kFrame * 8 : 16;
        const int h = scene.sheet ? kFrame : 16;
        SDL_Texture* texture =
            SDL_CreateTexture(renderer, SDL_PIXELFORMAT_ABGR8888, SDL_TEXTUREACCESS_STATIC, w, h);
        const std::vector<std::uint8_t> rgba = scene.sheet ? sheetImage() : textureImage(t, 16);
        SDL_UpdateTexture(texture, nullptr, rgba.data(), w * 4);
        SDL_SetTextureScaleMode(texture, SDL_ScaleModeNearest);
        SDL_SetTextureBlendMode(texture, SDL_BLENDMODE_BLEND);
        textures.push_back(texture);
    }
    return textures;
}

// SDL's pixels: origin at the target's top-left, y down; the scene's: centre, y up.
SDL_FPoint sdlPoint(glm::vec2 p) { return {p.x + kWidth * 0.5f, kHeight * 0.5f - p.y}; }

// Reads the target back (rows from the top), frees the textures, reports `lit`.
void finishSdl(benchmark::State& state, Targets& targets, std::vector<SDL_Texture*>& textures) {
    Image image{kWidth, kHeight,
                std::vector<std::uint8_t>(static_cast<std::size_t>(kWidth * kHeight * 4))};
    if (SDL_RenderReadPixels(targets.sdl.renderer, nullptr, SDL_PIXELFORMAT_ABGR8888,
                             image.pixels.data(), kWidth * 4) != 0) {
        state.SkipWithError("SDL_RenderReadPixels failed");
    }
    state.counters["lit"] = litFraction(image.pixels.data(), image.pixels.size() / 4);
    targets.shot(state, std::move(image));
    for (SDL_Texture* texture : textures) {
        SDL_DestroyTexture(texture);
    }
    state.SetItemsProcessed(state.iterations());
}

// One SDL_RenderCopyF per sprite in the scene's order, as sf::Sprite: SDL queues them and
// draws the queue at the flush.
void frameSdlCopy(benchmark::State& state, Targets& targets, Scene scene) {
    targets.activateSdl();
    SDL_Renderer* renderer = targets.sdl.renderer;
    std::vector<SDL_Texture*> textures = sdlTextures(renderer, scene);
    const float size = static_cast<float>(scene.spriteSize);
    const int source = scene.sheet ? kFrame : 16;
    int frameNumber = 0;
    auto frame = [&] {
        step(
            scene, frameNumber, [](int) {}, [](int) {});
        SDL_SetRenderDrawColor(renderer, 0, 0, 0, 255);
        SDL_RenderClear(renderer);
        for (const SceneSprite& s : scene.sprites) {
            const SDL_Rect from{scene.sheet ? s.frame * kFrame : 0, 0, source, source};
            const SDL_FPoint at = sdlPoint(s.position);
            const SDL_FRect to{at.x - size * 0.5f, at.y - size * 0.5f, size, size};
            SDL_RenderCopyF(renderer, textures[static_cast<std::size_t>(s.texture)], &from, &to);
        }
        SDL_RenderFlush(renderer);
        glFinish();
        ++frameNumber;
    };
    targets.run(state, frame);
    finishSdl(state, targets, textures);
}

// One SDL_RenderGeometry per texture over all of its sprites (two triangles each), vertices
// kept between frames and updated where sprites moved or animated, as sf::VertexArray.
void frameSdlGeometry(benchmark::State& state, Targets& targets, Scene scene) {
    targets.activateSdl();
    SDL_Renderer* renderer = targets.sdl.renderer;
    std::vector<SDL_Texture*> textures = sdlTextures(renderer, scene);
    std::vector<std::vector<SDL_Vertex>> vertices(textures.size());
    std::vector<std::vector<int>> indices(textures.size());
    std::vector<std::size_t> slot(scene.sprites.size()); // first vertex of each sprite's quad
    for (std::size_t i = 0; i < scene.sprites.size(); ++i) {
        std::vector<SDL_Vertex>& v = vertices[static_cast<std::size_t>(scene.sprites[i].texture)];
        std::vector<int>& index = indices[static_cast<std::size_t>(scene.sprites[i].texture)];
        slot[i] = v.size();
        const int first = static_cast<int>(v.size());
        index.insert(index.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
        v.resize(v.size() + 4, SDL_Vertex{{0.0f, 0.0f}, {255, 255, 255, 255}, {0.0f, 0.0f}});
    }
    const float half = static_cast<float>(scene.spriteSize) * 0.5f;
    auto place = [&](std::size_t i) {
        const SceneSprite& s = scene.sprites[i];
        SDL_Vertex* v = &vertices[static_cast<std::size_t>(s.texture)][slot[i]];
        const SDL_FPoint c = sdlPoint(s.position);
        v[0].position = {c.x - half, c.y - half};
        v[1].position = {c.x + half, c.y - half};
        v[2].position = {c.x + half, c.y + half};
        v[3].position = {c.x - half, c.y + half};
    };
    auto look = [&](std::size_t i) {
        const SceneSprite& s = scene.sprites[i];
        const Rect uv = scene.sheet ? frameUv(s.frame) : kFullUv;
        SDL_Vertex* v = &vertices[static_cast<std::size_t>(s.texture)][slot[i]];
        v[0].tex_coord = {uv.min.x, uv.min.y};
        v[1].tex_coord = {uv.max().x, uv.min.y};
        v[2].tex_coord = {uv.max().x, uv.max().y};
        v[3].tex_coord = {uv.min.x, uv.max().y};
    };
    for (std::size_t i = 0; i < scene.sprites.size(); ++i) {
        place(i);
        look(i);
    }
    int frameNumber = 0;
    auto frame = [&] {
        step(
            scene, frameNumber, [&](int i) { place(static_cast<std::size_t>(i)); },
            [&](int i) { look(static_cast<std::size_t>(i)); });
        SDL_SetRenderDrawColor(renderer, 0, 0, 0, 255);
        SDL_RenderClear(renderer);
        for (std::size_t t = 0; t < textures.size(); ++t) {
            SDL_RenderGeometry(renderer, textures[t], vertices[t].data(),
                               static_cast<int>(vertices[t].size()), indices[t].data(),
                               static_cast<int>(indices[t].size()));
        }
        SDL_RenderFlush(renderer);
        glFinish();
        ++frameNumber;
    };
    targets.run(state, frame);
    finishSdl(state, targets, textures);
}

// The naive path: one draw call per sprite, its rectangle, UV and texture set by uniforms and
// glBindTexture, blending on (as the seed drew every sprite).
GLuint compile(GLenum type, const char* source) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    return shader;
}

void frameNaive(benchmark::State& state, Targets& targets, Scene scene) {
    targets.activateE2d();
    const char* vs = R"(#version 330 core
uniform vec4 rect;  // clip-space x0, y0, x1, y1
uniform vec4 uvRect; // u0, v0 (top), u1, v1 (bottom)
out vec2 uv;
void main() {
    vec2 c = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(mix(rect.xy, rect.zw, c), 0.0, 1.0);
    uv = vec2(mix(uvRect.x, uvRect.z, c.x), mix(uvRect.w, uvRect.y, c.y));
})";
    const char* fs = R"(#version 330 core
uniform sampler2D image;
in vec2 uv;
out vec4 colour;
void main() { colour = texture(image, uv); })";
    GLuint program = glCreateProgram();
    GLuint v = compile(GL_VERTEX_SHADER, vs);
    GLuint f = compile(GL_FRAGMENT_SHADER, fs);
    glAttachShader(program, v);
    glAttachShader(program, f);
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (linked == 0) {
        state.SkipWithError("naive shaders did not link");
        return;
    }
    const GLint rectLoc = glGetUniformLocation(program, "rect");
    const GLint uvLoc = glGetUniformLocation(program, "uvRect");
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    GLuint fbo = 0;
    GLuint colour = 0;
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kWidth, kHeight);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    std::vector<GLuint> textures(scene.sheet ? 1 : kTextures);
    glGenTextures(static_cast<GLsizei>(textures.size()), textures.data());
    for (std::size_t t = 0; t < textures.size(); ++t) {
        glBindTexture(GL_TEXTURE_2D, textures[t]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        const std::vector<std::uint8_t> rgba =
            scene.sheet ? sheetImage() : textureImage(static_cast<int>(t), 16);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, scene.sheet ? kFrame * 8 : 16,
                     scene.sheet ? kFrame : 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    }
    const float half = static_cast<float>(scene.spriteSize) * 0.5f;
    int frameNumber = 0;
    auto frame = [&] {
        step(
            scene, frameNumber, [](int) {}, [](int) {});
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, kWidth, kHeight);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_SCISSOR_TEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glUseProgram(program);
        glBindVertexArray(vao);
        glActiveTexture(GL_TEXTURE0);
        for (const SceneSprite& s : scene.sprites) {
            glBindTexture(GL_TEXTURE_2D, textures[static_cast<std::size_t>(s.texture)]);
            const float x0 = (s.position.x - half) / (kWidth * 0.5f);
            const float y0 = (s.position.y - half) / (kHeight * 0.5f);
            const float x1 = (s.position.x + half) / (kWidth * 0.5f);
            const float y1 = (s.position.y + half) / (kHeight * 0.5f);
            glUniform4f(rectLoc, x0, y0, x1, y1);
            if (scene.sheet) {
                const Rect uv = frameUv(s.frame);
                glUniform4f(uvLoc, uv.min.x, uv.min.y, uv.max().x, uv.max().y);
            } else {
                glUniform4f(uvLoc, 0.0f, 0.0f, 1.0f, 1.0f);
            }
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        }
        glFinish();
        ++frameNumber;
    };
    targets.run(state, frame);
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(kWidth * kHeight * 4));
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    state.counters["lit"] = litFraction(pixels.data(), pixels.size() / 4);
    Image top{kWidth, kHeight, std::vector<std::uint8_t>(pixels.size())};
    const std::size_t row = static_cast<std::size_t>(kWidth) * 4;
    for (std::size_t y = 0; y < static_cast<std::size_t>(kHeight); ++y) {
        std::copy_n(pixels.data() + (kHeight - 1 - y) * row, row, top.pixels.data() + y * row);
    }
    targets.shot(state, std::move(top));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &colour);
    glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
    glDeleteShader(v);
    glDeleteShader(f);
    state.SetItemsProcessed(state.iterations());
}

// ---------------------------------------------------------------------------------------------
// Text.

// ~1 000 printable glyphs on 20 lines; `variant` swaps one letter per line so each frame's
// string differs from the last (both engines then lay it out anew).
std::string textBlock(int variant) {
    const std::string line = "The quick brown fox jumps over the lazy dog 0123456789 AVAWAY";
    std::string text;
    for (int l = 0; l < 20; ++l) {
        std::string copy = line;
        copy[4] = (l + variant) % 2 == 0 ? 'q' : 'Q';
        text += copy;
        text += '\n';
    }
    return text;
}

int glyphCount(const std::string& text) {
    int n = 0;
    for (char c : text) {
        n += c != ' ' && c != '\n' ? 1 : 0;
    }
    return n;
}

void textE2d(benchmark::State& state, Targets& targets) {
    targets.activateE2d();
    RendererDef def;
    def.offscreenSize = {kWidth, kHeight};
    Renderer renderer(*targets.window, def);
    TextRenderer text(renderer);
    Font* font = text.font(kDefaultFontPath, 16);
    if (font == nullptr) {
        state.SkipWithError("no font");
        return;
    }
    CameraDef cd;
    cd.referenceSize = {kWidth, kHeight};
    Camera camera(cd);
    const std::array<std::string, 2> strings{textBlock(0), textBlock(1)};
    TextStyle style;
    TextDraw where;
    where.position = {-kWidth * 0.5f + 8.0f, kHeight * 0.5f - 8.0f};
    int frameNumber = 0;
    std::size_t glyphs = 0;
    auto frame = [&] {
        const TextLayout layout =
            text.draw(*font, strings[static_cast<std::size_t>(frameNumber & 1)], style, where);
        glyphs = layout.quads.size();
        renderer.render(camera);
        glFinish();
        ++frameNumber;
    };
    targets.run(state, frame);
    const Image image = renderer.readPixels();
    targets.shot(state, image);
    state.counters["lit"] = litFraction(image.pixels.data(), image.pixels.size() / 4);
    state.counters["glyphs"] = static_cast<double>(glyphs);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(glyphs));
}

void textSfml(benchmark::State& state, Targets& targets) {
    targets.activateSfml();
    sf::Font font;
    if (!font.loadFromFile(kDefaultFontPath)) {
        state.SkipWithError("SFML could not load the font");
        return;
    }
    const std::array<std::string, 2> strings{textBlock(0), textBlock(1)};
    sf::Text label;
    label.setFont(font);
    label.setCharacterSize(16);
    label.setFillColor(sf::Color::White);
    label.setPosition(8.0f, 8.0f);
    targets.sfml.setView(targets.sfml.getDefaultView());
    int frameNumber = 0;
    auto frame = [&] {
        label.setString(strings[static_cast<std::size_t>(frameNumber & 1)]);
        targets.sfml.clear(sf::Color::Black);
        targets.sfml.draw(label);
        targets.sfml.display();
        glFinish();
        ++frameNumber;
    };
    targets.run(state, frame);
    finishSfml(state, targets);
    const int glyphs = glyphCount(strings[0]);
    state.counters["glyphs"] = glyphs;
    state.SetItemsProcessed(state.iterations() * glyphs);
}

// Prints as the console reporter does and hands every run to `forward` as well.
class GroupReporter : public benchmark::ConsoleReporter {
public:
    explicit GroupReporter(std::function<void(const std::vector<Run>&)> forward)
        : forward_(std::move(forward)) {}
    void ReportRuns(const std::vector<Run>& reports) override {
        ConsoleReporter::ReportRuns(reports);
        for (const Run& run : reports) {
            failed_ = failed_ || run.error_occurred;
            const auto lit = run.counters.find("lit");
            const std::string& name = run.run_name.function_name;
            const auto last = name.rfind('/');
            if (lit != run.counters.end() && last != std::string::npos) {
                lit_[name.substr(0, last)][name.substr(last + 1)] = lit->second.value;
            }
        }
        forward_(reports);
    }

    // Every case ran, and every engine of a case covered the same share of the target (within
    // 1 % of the pixels; the engines may differ in which of two equal-z sprites is on top but
    // not in what is covered). Prints what is wrong.
    [[nodiscard]] bool consistent() const {
        bool ok = !failed_;
        if (failed_) {
            std::fprintf(stderr, "batching: a case reported an error\n");
        }
        for (const auto& [name, byEngine] : lit_) {
            for (const auto& [engine, value] : byEngine) {
                const double reference = byEngine.begin()->second;
                if (std::abs(value - reference) > 0.01) {
                    std::fprintf(stderr, "batching: %s: %s covers %.4f of the target, %s %.4f\n",
                                 name.c_str(), engine.c_str(), value,
                                 byEngine.begin()->first.c_str(), reference);
                    ok = false;
                }
            }
        }
        return ok;
    }

private:
    std::function<void(const std::vector<Run>&)> forward_;
    bool failed_ = false;
    std::map<std::string, std::map<std::string, double>> lit_;
};

} // namespace

int main(int argc, char** argv) {
    const std::string tablePath = e2d::bench::RatioReporter::takeTableFlag(argc, argv);
    std::string shots;
    int warmup = 3;
    {
        int kept = 0;
        for (int i = 0; i < argc; ++i) {
            const std::string arg = argv[i];
            if (arg.rfind("--e2d_shots=", 0) == 0) {
                shots = arg.substr(12);
            } else if (arg.rfind("--e2d_warmup=", 0) == 0) {
                warmup = std::stoi(arg.substr(13));
            } else {
                argv[kept++] = argv[i];
            }
        }
        argc = kept;
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 2;
    }
    if (!shots.empty()) {
        std::filesystem::create_directories(shots);
    }
    Targets targets;
    targets.shots = shots;
    targets.warmup = warmup;

    // Every case is registered; --benchmark_filter picks among them as usual.
    auto add = [&](const std::string& name, auto&& function) -> benchmark::internal::Benchmark* {
        return benchmark::RegisterBenchmark(name.c_str(),
                                            [&targets, name, function](benchmark::State& state) {
                                                targets.running = name;
                                                function(state);
                                            });
    };
    auto unit = [](benchmark::internal::Benchmark* b, benchmark::TimeUnit u, bool realTime) {
        if (b != nullptr) {
            b->Unit(u);
            if (realTime) {
                b->UseRealTime();
            }
        }
    };

    // build: no OpenGL.
    for (int count : {1000, 10000, 100000, 1000000}) {
        struct Motion {
            const char* name;
            int moving;
            bool pan;
        };
        for (const Motion& m : {Motion{"static", 0, false}, Motion{"static_pan", 0, true},
                                Motion{"moving10", 10, false}, Motion{"moving100", 100, false}}) {
            const int moving = m.moving;
            const bool pan = m.pan;
            unit(add("build/" + std::to_string(count) + "/" + m.name + "/e2d",
                     [count, moving, pan](benchmark::State& s) {
                         buildCase(s, count, moving, pan);
                     }),
                 benchmark::kMicrosecond, false);
        }
    }

    try {
        WindowDef wd;
        wd.title = "e2d batching bench";
        wd.size = {kWidth, kHeight};
        wd.visible = false;
        wd.vsync = false;
        targets.window = std::make_unique<Window>(wd);
    } catch (const std::exception& e) {
        targets.error = e.what();
    }
    const bool gl = targets.window != nullptr && targets.sfml.create(kWidth, kHeight);
    const std::string sdlError = gl ? targets.sdl.create() : std::string("no OpenGL");
    const bool sdl = sdlError.empty();
    // The seed's demo (12 000 animated sprites from one sheet, 32 x 32, static positions) and
    // 100 000 8 x 8 sprites over 8 textures, 10 % of them moving. Live until the runs are done.
    const Scene demo = makeScene(12000, 0, true, 32);
    const Scene many = makeScene(100000, 10, false, 8);
    if (gl) {
        struct Frame {
            const char* name;
            const Scene* scene;
        };
        const std::array<Frame, 2> frames{Frame{"frame/demo_12k_animated", &demo},
                                          Frame{"frame/100k_8_textures", &many}};
        // Everything in the GLFW context first, then everything in SFML's: SFML keeps its own
        // idea of the current context and does not recover well from many switches.
        for (const Frame& f : frames) {
            const std::string base = f.name;
            const Scene& scene = *f.scene;
            for (bool gl33 : {false, true}) {
                RendererDef def;
                def.forceGl33 = gl33;
                unit(add(base + (gl33 ? "/e2d_gl33" : "/e2d"),
                         [&targets, &scene, def](benchmark::State& s) {
                             frameE2d(s, targets, scene, def);
                         }),
                     benchmark::kMillisecond, true);
            }
            unit(add(base + "/naive",
                     [&targets, &scene](benchmark::State& s) { frameNaive(s, targets, scene); }),
                 benchmark::kMillisecond, true);
        }
        unit(add("text/1000_glyphs/e2d", [&targets](benchmark::State& s) { textE2d(s, targets); }),
             benchmark::kMicrosecond, true);
        for (const Frame& f : frames) {
            const std::string base = f.name;
            const Scene& scene = *f.scene;
            unit(add(base + "/sfml_vertexarray",
                     [&targets, &scene](benchmark::State& s) {
                         frameSfmlVertexArrays(s, targets, scene);
                     }),
                 benchmark::kMillisecond, true);
            unit(add(base + "/sfml_sprite",
                     [&targets, &scene](benchmark::State& s) {
                         frameSfmlSprites(s, targets, scene);
                     }),
                 benchmark::kMillisecond, true);
        }
        unit(add("text/1000_glyphs/sfml_text",
                 [&targets](benchmark::State& s) { textSfml(s, targets); }),
             benchmark::kMicrosecond, true);
        // SDL's context last, after SFML's.
        if (sdl) {
            for (const Frame& f : frames) {
                const std::string base = f.name;
                const Scene& scene = *f.scene;
                unit(add(base + "/sdl_geometry",
                         [&targets, &scene](benchmark::State& s) {
                             frameSdlGeometry(s, targets, scene);
                         }),
                     benchmark::kMillisecond, true);
                unit(add(base + "/sdl_copy",
                         [&targets, &scene](benchmark::State& s) {
                             frameSdlCopy(s, targets, scene);
                         }),
                     benchmark::kMillisecond, true);
            }
        } else {
            std::fprintf(stderr, "batching: no SDL2 OpenGL renderer (%s): SDL cases skipped\n",
                         sdlError.c_str());
        }
    } else {
        std::fprintf(stderr, "batching: no OpenGL (%s): frame and text cases skipped\n",
                     targets.error.c_str());
    }

    // One run, in registration order (all GLFW-context cases, then all SFML ones); each group
    // has its own unit, so its runs also go to a RatioReporter of its own for its table.
    struct Group {
        const char* prefix;
        const char* title;
        const char* unit;
        double nsPerUnit;
        std::vector<std::string> engines;
    };
    const std::vector<Group> groups{
        {"build/", "CPU: per-frame instance data", "ns per sprite", 1.0, {"e2d"}},
        {"frame/",
         "Whole frames, 1024 x 720, llvmpipe",
         "ms per frame",
         1e6,
         {"e2d", "e2d_gl33", "sfml_vertexarray", "sfml_sprite", "sdl_geometry", "sdl_copy",
          "naive"}},
        {"text/", "Text laid out, batched and drawn", "ns per glyph", 1.0, {"e2d", "sfml_text"}},
    };
    std::ostringstream quiet;
    std::vector<std::unique_ptr<e2d::bench::RatioReporter>> tablesBy;
    for (const Group& g : groups) {
        tablesBy.push_back(std::make_unique<e2d::bench::RatioReporter>("e2d", g.engines));
        tablesBy.back()->SetOutputStream(&quiet);
        tablesBy.back()->SetErrorStream(&quiet);
    }
    GroupReporter reporter([&](const std::vector<benchmark::BenchmarkReporter::Run>& runs) {
        if (runs.empty()) {
            return;
        }
        const std::string& name = runs.front().run_name.function_name;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            if (name.rfind(groups[g].prefix, 0) == 0) {
                tablesBy[g]->ReportRuns(runs);
            }
        }
    });
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::string tables;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::string table = tablesBy[g]->markdownTable(groups[g].unit, groups[g].nsPerUnit);
        if (table.find("\n| " + std::string(groups[g].prefix)) != std::string::npos) {
            tables += std::string("\n### ") + groups[g].title + "\n\n" + table;
        }
    }
    benchmark::Shutdown();
    std::printf("%s", tables.c_str());
    if (!tablePath.empty()) {
        std::ofstream(tablePath) << tables;
    }
    return reporter.consistent() ? 0 : 1;
}
