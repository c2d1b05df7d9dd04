#include "framework/render/tiles.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace rtlab {

std::vector<Tile> makeTiles(int width, int height, int tileSize) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += tileSize)
        for (int x = 0; x < width; x += tileSize)
            tiles.push_back({x, y, std::min(x + tileSize, width), std::min(y + tileSize, height)});
    return tiles;
}

int resolveThreadCount(int threads) {
    if (threads > 0) return threads;
    return std::max(1u, std::thread::hardware_concurrency());
}

void parallelFor(size_t count, int threads, const std::function<void(size_t)>& work) {
    std::atomic<size_t> next{0};
    std::exception_ptr firstError;
    std::mutex errorMutex;
    auto worker = [&] {
        for (size_t i = next++; i < count; i = next++) {
            try {
                work(i);
            } catch (...) {
                std::lock_guard lock(errorMutex);
                if (!firstError) firstError = std::current_exception();
                next = count;  // hand out nothing more
            }
        }
    };
    int threadCount = static_cast<int>(std::min<size_t>(resolveThreadCount(threads), std::max<size_t>(count, 1)));
    std::vector<std::thread> pool;
    for (int t = 1; t < threadCount; ++t) pool.emplace_back(worker);
    worker();  // the calling thread works too
    for (std::thread& thread : pool) thread.join();
    if (firstError) std::rethrow_exception(firstError);
}

}  // namespace rtlab
