// The Pareto front of (cost, error) points: the measurements that no other
// measurement beats on both time and error at once. `raylab bench` marks
// them in its table and its plot; everything off the front is a setting that
// is slower AND less accurate than some other one.
#pragma once

#include <vector>

namespace rl::bench {

struct ParetoPoint {
    double cost = 0;   // e.g. median GPU ms per frame (smaller is better)
    double error = 0;  // e.g. mean 8-bit error against the reference (smaller is better)
};

// True when `a` dominates `b`: no worse in both, strictly better in one.
bool dominates(const ParetoPoint& a, const ParetoPoint& b);

// onFront[i] is true when no point dominates points[i]. Equal points do not
// dominate each other, so duplicates are on the front together. NaN
// coordinates are never on the front and never dominate.
std::vector<bool> paretoFront(const std::vector<ParetoPoint>& points);

}  // namespace rl::bench
