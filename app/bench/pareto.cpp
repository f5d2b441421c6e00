#include "bench/pareto.h"

#include <cmath>

namespace rl::bench {

namespace {
bool valid(const ParetoPoint& p) { return !std::isnan(p.cost) && !std::isnan(p.error); }
}  // namespace

bool dominates(const ParetoPoint& a, const ParetoPoint& b) {
    if (!valid(a) || !valid(b)) return false;
    bool noWorse = a.cost <= b.cost && a.error <= b.error;
    bool better = a.cost < b.cost || a.error < b.error;
    return noWorse && better;
}

std::vector<bool> paretoFront(const std::vector<ParetoPoint>& points) {
    // O(n^2): a bench has tens of points, and this reads like the definition.
    std::vector<bool> onFront(points.size(), false);
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!valid(points[i])) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < points.size() && !dominated; ++j)
            dominated = j != i && dominates(points[j], points[i]);
        onFront[i] = !dominated;
    }
    return onFront;
}

}  // namespace rl::bench
