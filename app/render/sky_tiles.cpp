#include "render/sky_tiles.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace rl {
namespace {

// Whether some ray t (x, y, 1), t > 0, x in [x0, x1], y in [y0, y1] (camera
// space: right, up, forward) can meet the sphere at q (camera space) of
// radius r. The rays lie in the cone around the rectangle's centre ray whose
// half-angle reaches the farthest corner; the sphere subtends asin(r / |q|)
// around q. Margins: 1e-4 radians and 1e-4 of the sphere's angular radius,
// where float32 errs on a camera ray's direction by about 1e-7 and on a
// hit-or-miss decision by a few u of the distance.
bool coneMayHit(double x0, double x1, double y0, double y1, glm::dvec3 q, double r) {
    double distance = glm::length(q);
    if (distance <= r * (1.0 + 1e-6) + 1e-300) return true;  // the camera inside or on the sphere
    glm::dvec3 axis = glm::normalize(glm::dvec3(0.5 * (x0 + x1), 0.5 * (y0 + y1), 1.0));
    double halfAngle = 0.0;
    for (double x : {x0, x1})
        for (double y : {y0, y1})
            halfAngle = std::max(halfAngle, std::acos(std::clamp(glm::dot(axis, glm::normalize(glm::dvec3(x, y, 1.0))), -1.0, 1.0)));
    double toCentre = std::acos(std::clamp(glm::dot(axis, q / distance), -1.0, 1.0));
    double angularRadius = std::asin(std::min(1.0, r / distance));
    return toCentre <= halfAngle + angularRadius * (1.0 + 1e-4) + 1e-4;
}

// Rectangles of equal tiles: runs along each row, then runs of identical
// extent in consecutive rows joined.
std::vector<PixelRect> mergeRuns(const std::vector<std::vector<std::pair<int, int>>>& runsPerRow, int tile, int width,
                                 int height) {
    std::vector<PixelRect> done;
    std::map<std::pair<int, int>, PixelRect> open;  // keyed by the run's [first, last] tile
    for (int row = 0; row < int(runsPerRow.size()); ++row) {
        std::map<std::pair<int, int>, PixelRect> next;
        for (const auto& run : runsPerRow[row]) {
            int y = row * tile, h = std::min(tile, height - y);
            auto it = open.find(run);
            if (it != open.end()) {
                PixelRect r = it->second;
                r.height += h;
                next[run] = r;
                open.erase(it);
            } else {
                int x = run.first * tile;
                next[run] = PixelRect{x, y, std::min((run.second + 1) * tile, width) - x, h};
            }
        }
        for (const auto& [run, r] : open) done.push_back(r);
        open = std::move(next);
    }
    for (const auto& [run, r] : open) done.push_back(r);
    return done;
}

}  // namespace

std::vector<PixelRect> tileRects(const std::vector<bool>& chosen, int columns, int tile, int width, int height) {
    const int rows = columns > 0 ? int(chosen.size()) / columns : 0;
    std::vector<std::vector<std::pair<int, int>>> runs(rows);
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns;) {
            if (!chosen[std::size_t(row) * columns + column]) {
                ++column;
                continue;
            }
            int last = column;
            while (last + 1 < columns && chosen[std::size_t(row) * columns + last + 1]) ++last;
            runs[row].push_back({column, last});
            column = last + 1;
        }
    return mergeRuns(runs, tile, width, height);
}

SkyTiles skyTiles(const Scene& scene, const FrameSettings& frame, int tile) {
    SkyTiles out;
    const int width = frame.width, height = frame.height;
    const int columns = (width + tile - 1) / tile, rows = (height + tile - 1) / tile;
    const glm::dvec3 right(frame.cameraToWorld[0]), up(frame.cameraToWorld[1]), back(frame.cameraToWorld[2]);
    const glm::dvec3 eye(frame.cameraToWorld[3]);
    const double t = std::tan(0.5 * frame.fovYRadians), aspect = double(width) / double(height);
    std::vector<std::pair<glm::dvec3, double>> spheres;  // camera space
    for (const Sphere& s : scene.spheres) {
        glm::dvec3 v = s.center - eye;
        spheres.push_back({glm::dvec3(glm::dot(v, right), glm::dot(v, up), -glm::dot(v, back)), s.radius});
    }
    // exercise 01: a sample at pixel position p (0..width) looks along
    // (ndc.x t aspect, ndc.y t, 1), ndc = 2 p / resolution - 1.
    auto planeX = [&](double px) { return (2.0 * px / width - 1.0) * t * aspect; };
    auto planeY = [&](double py) { return (2.0 * py / height - 1.0) * t; };
    std::vector<std::vector<std::pair<int, int>>> skyRuns(rows), sceneRuns(rows);
    long skyPixels = 0;
    for (int row = 0; row < rows; ++row) {
        double y0 = planeY(row * tile), y1 = planeY(std::min((row + 1) * tile, height));
        int runStart = 0;
        bool runSky = false;
        for (int column = 0; column <= columns; ++column) {
            bool sky = false;
            if (column < columns) {
                double x0 = planeX(column * tile), x1 = planeX(std::min((column + 1) * tile, width));
                sky = std::none_of(spheres.begin(), spheres.end(),
                                   [&](const auto& s) { return coneMayHit(x0, x1, y0, y1, s.first, s.second); });
                if (sky)
                    skyPixels += long(std::min((column + 1) * tile, width) - column * tile) *
                                 (std::min((row + 1) * tile, height) - row * tile);
            }
            if (column == columns || (column > 0 && sky != runSky)) {
                (runSky ? skyRuns : sceneRuns)[row].push_back({runStart, column - 1});
                runStart = column;
            }
            runSky = sky;
        }
    }
    out.sky = mergeRuns(skyRuns, tile, width, height);
    out.scene = mergeRuns(sceneRuns, tile, width, height);
    out.skyShare = double(skyPixels) / (double(width) * height);
    return out;
}

}  // namespace rl
