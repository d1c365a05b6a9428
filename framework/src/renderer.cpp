#include "raylab/renderer.h"

#include "raylab/terminal.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace raylab {

namespace {

constexpr int kTileSize = 16;

struct Tile {
    int x0, y0, x1, y1;
};

std::vector<Tile> makeTiles(int width, int height) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += kTileSize)
        for (int x = 0; x < width; x += kTileSize)
            tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
    return tiles;
}

} // namespace

Renderer::Renderer(const Scene& scene, const BaseCamera& camera, const Integrator& integrator)
    : m_scene(scene), m_camera(camera), m_integrator(integrator) {}

void Renderer::setThreads(int threads) {
    if (threads < 0) throw std::invalid_argument("Renderer: threads = " + std::to_string(threads) + " is negative");
    m_threads = threads;
}

Color Renderer::renderPixelCentre(int i, int j) const {
    const float sx = (float(i) + 0.5f) / float(m_camera.width());
    const float sy = (float(j) + 0.5f) / float(m_camera.height());
    return m_integrator.Li(m_scene, m_camera.generateRay(sx, sy));
}

Texture Renderer::renderImage() {
    const int width = m_camera.width();
    const int height = m_camera.height();
    Texture image(width, height);
    const std::vector<Tile> tiles = makeTiles(width, height);
    const bool centreOnly = m_nbPixelSamples == 1 && m_sampler == SamplerKind::Center;

    std::atomic<std::size_t> nextTile{0};
    std::atomic<std::size_t> tilesDone{0};
    std::atomic<bool> failed{false};
    std::exception_ptr firstError;
    std::mutex errorMutex;

    auto work = [&] {
        try {
            for (std::size_t t = nextTile++; t < tiles.size() && !failed; t = nextTile++) {
                const Tile& tile = tiles[t];
                for (int j = tile.y0; j < tile.y1; ++j)
                    for (int i = tile.x0; i < tile.x1; ++i) {
                        Color c;
                        if (centreOnly) {
                            c = renderPixelCentre(i, j);
                        } else {
                            PixelSampler sampler(m_sampler, m_nbPixelSamples, m_seed, i, j, width);
                            c = renderPixel(i, j, sampler);
                        }
                        image.setPixel(i, j, c);
                    }
                ++tilesDone;
            }
        } catch (...) {
            std::lock_guard lock(errorMutex);
            if (!failed.exchange(true)) firstError = std::current_exception();
        }
    };

    const auto start = std::chrono::steady_clock::now();
    unsigned threads = m_threads > 0 ? unsigned(m_threads) : std::max(1u, std::thread::hardware_concurrency());
    threads = unsigned(std::min<std::size_t>(threads, tiles.size()));
    std::vector<std::thread> workers;
    for (unsigned k = 1; k < threads; ++k) workers.emplace_back(work);
    if (m_progress) {
        ProgressBar bar(tiles.size());
        // The calling thread watches; the workers render.
        workers.emplace_back(work);
        while (tilesDone < tiles.size() && !failed) {
            bar.update(tilesDone);
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        for (auto& w : workers) w.join();
        bar.finish();
    } else {
        work();
        for (auto& w : workers) w.join();
    }
    if (firstError) std::rethrow_exception(firstError);

    m_stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m_stats.primaryRays = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(centreOnly ? 1 : m_nbPixelSamples);
    return image;
}

} // namespace raylab
