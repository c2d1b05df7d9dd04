// Image tiles handed out to worker threads. Each pixel is computed independently and written
// to its own place, so the image does not depend on which thread renders which tile.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace rtlab {

inline constexpr int kTileSize = 16;

struct Tile {
    int x0, y0;  // first pixel
    int x1, y1;  // one past the last pixel
};

// The tiles of a width x height image in row-major order; edge tiles are clipped.
std::vector<Tile> makeTiles(int width, int height, int tileSize = kTileSize);

// Calls work(index) once for every index in [0, count) on `threads` threads (0 = one per
// hardware thread), handing indices out through an atomic counter. The first exception a call
// throws stops the hand-out and is rethrown here after all threads have finished.
void parallelFor(size_t count, int threads, const std::function<void(size_t)>& work);

// The thread count parallelFor uses for `threads` (0 = hardware concurrency, at least 1).
int resolveThreadCount(int threads);

}  // namespace rtlab
