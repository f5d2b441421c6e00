// Error against time as a hand-written SVG: one panel per scene, both axes
// logarithmic (times and errors span decades), one colour per sweep, the
// Pareto front joined by a staircase and its points ringed.
#include "bench/bench.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <cstdio>
#include <map>
#include <sstream>

namespace rl::bench {

namespace {

constexpr double kPanelWidth = 760, kPanelHeight = 440;
constexpr double kLeft = 70, kRight = 190, kTop = 40, kBottom = 50;  // margins; the legend sits on the right
constexpr double kMinError = 1e-3;  // errors below this (identical pictures) are drawn on the axis

const std::map<std::string, const char*>& sweepColours() {
    static const std::map<std::string, const char*> colours = {
        {"modes", "#d62728"},      {"bounces", "#1f77b4"}, {"spp", "#2ca02c"},
        {"resolution", "#9467bd"}, {"models", "#ff7f0e"},  {"strategies", "#8c564b"},
        {"environment", "#17becf"}};
    return colours;
}

const char* colourOf(const std::string& sweep) {
    auto it = sweepColours().find(sweep);
    return it == sweepColours().end() ? "#7f7f7f" : it->second;
}

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

std::string tickLabel(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// A log axis covering [lo, hi], widened to the nearest 1, 2, 5 steps.
struct LogAxis {
    double lo, hi;          // log10 of the ends
    double from, to;        // pixel positions of lo and hi
    double at(double v) const { return from + (std::log10(v) - lo) / (hi - lo) * (to - from); }
    bool covers(double v) const { return std::log10(v) >= lo - 1e-9 && std::log10(v) <= hi + 1e-9; }
};

double stepDown(double v) {  // the largest 1, 2 or 5 times a power of ten <= v
    double decade = std::pow(10.0, std::floor(std::log10(v)));
    for (double k : {5.0, 2.0, 1.0})
        if (k * decade <= v * (1 + 1e-9)) return k * decade;
    return decade;
}

double stepUp(double v) {  // the smallest 1, 2 or 5 times a power of ten >= v
    double decade = std::pow(10.0, std::floor(std::log10(v)));
    for (double k : {1.0, 2.0, 5.0, 10.0})
        if (k * decade >= v * (1 - 1e-9)) return k * decade;
    return 10 * decade;
}

LogAxis makeAxis(double minValue, double maxValue, double from, double to) {
    double lo = std::log10(stepDown(minValue));
    double hi = std::log10(stepUp(maxValue));
    if (hi <= lo) hi = lo + std::log10(2.0);
    return {lo, hi, from, to};
}

// Labels are placed most important first and left out where they would
// overlap one already placed; every point keeps its name as a tooltip.
struct LabelBox {
    double x0, y0, x1, y1;
    bool overlaps(const LabelBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

void panel(std::ostringstream& s, const std::vector<const Measurement*>& rows, double y0) {
    double minMs = 1e300, maxMs = 0, maxErr = kMinError;
    for (const Measurement* m : rows) {
        minMs = std::min(minMs, m->msMedian);
        maxMs = std::max(maxMs, m->msMedian);
        maxErr = std::max(maxErr, m->error.meanLsb);
    }
    minMs = std::max(minMs, 1e-3);
    maxMs = std::max(maxMs, minMs);
    double plotLeft = kLeft, plotRight = kPanelWidth - kRight;
    double plotTop = y0 + kTop, plotBottom = y0 + kPanelHeight - kBottom;
    LogAxis x = makeAxis(minMs, maxMs, plotLeft, plotRight);
    LogAxis y = makeAxis(kMinError, maxErr, plotBottom, plotTop);
    auto px = [&](const Measurement* m) { return x.at(std::max(m->msMedian, 1e-3)); };
    auto py = [&](const Measurement* m) { return y.at(std::max(m->error.meanLsb, kMinError)); };

    const Measurement* first = rows.front();
    s << "<text x='" << num(plotLeft) << "' y='" << num(y0 + 24) << "' font-size='15' font-weight='bold'>"
      << escape(first->scene) << ": error against time per frame</text>\n";
    s << "<rect x='" << num(plotLeft) << "' y='" << num(plotTop) << "' width='" << num(plotRight - plotLeft)
      << "' height='" << num(plotBottom - plotTop) << "' fill='none' stroke='#333'/>\n";

    // Grid lines with labels at 1, 2 and 5 times each power of ten.
    for (double d = std::floor(x.lo); d <= x.hi + 1e-9; d += 1) {
        for (double k : {1.0, 2.0, 5.0}) {
            double v = k * std::pow(10.0, d);
            if (!x.covers(v)) continue;
            double X = x.at(v);
            s << "<line x1='" << num(X) << "' y1='" << num(plotTop) << "' x2='" << num(X) << "' y2='"
              << num(plotBottom) << "' stroke='" << (k == 1 ? "#ccc" : "#eee") << "'/>\n";
            s << "<text x='" << num(X) << "' y='" << num(plotBottom + 16) << "' font-size='11' text-anchor='middle'>"
              << tickLabel(v) << "</text>\n";
        }
    }
    for (double d = std::floor(y.lo); d <= y.hi + 1e-9; d += 1) {
        for (double k : {1.0, 2.0, 5.0}) {
            double v = k * std::pow(10.0, d);
            if (!y.covers(v)) continue;
            double Y = y.at(v);
            s << "<line x1='" << num(plotLeft) << "' y1='" << num(Y) << "' x2='" << num(plotRight) << "' y2='"
              << num(Y) << "' stroke='" << (k == 1 ? "#ccc" : "#eee") << "'/>\n";
            s << "<text x='" << num(plotLeft - 6) << "' y='" << num(Y + 4) << "' font-size='11' text-anchor='end'>"
              << tickLabel(v) << "</text>\n";
        }
    }
    s << "<text x='" << num((plotLeft + plotRight) / 2) << "' y='" << num(plotBottom + 36)
      << "' font-size='12' text-anchor='middle'>median time per frame (ms, log)</text>\n";
    s << "<text x='" << num(plotLeft - 48) << "' y='" << num((plotTop + plotBottom) / 2)
      << "' font-size='12' text-anchor='middle' transform='rotate(-90 " << num(plotLeft - 48) << " "
      << num((plotTop + plotBottom) / 2) << ")'>mean error vs converged reference (8-bit steps, log)</text>\n";

    // The front as a staircase: sorted by time, each step down to the next point's error.
    std::vector<const Measurement*> front;
    for (const Measurement* m : rows)
        if (m->onFront) front.push_back(m);
    std::sort(front.begin(), front.end(), [](const Measurement* a, const Measurement* b) {
        return a->msMedian < b->msMedian || (a->msMedian == b->msMedian && a->error.meanLsb > b->error.meanLsb);
    });
    if (!front.empty()) {
        s << "<polyline fill='none' stroke='#000' stroke-width='1.5' stroke-dasharray='5,3' points='";
        for (std::size_t i = 0; i < front.size(); ++i) {
            if (i > 0) s << num(px(front[i])) << "," << num(py(front[i - 1])) << " ";
            s << num(px(front[i])) << "," << num(py(front[i])) << " ";
        }
        s << num(plotRight) << "," << num(py(front.back())) << "'/>\n";
    }
    for (const Measurement* m : rows) {
        s << "<circle cx='" << num(px(m)) << "' cy='" << num(py(m)) << "' r='4.5' fill='" << colourOf(m->sweep)
          << "'><title>" << escape(m->variant) << ": " << tickLabel(m->msMedian) << " ms, mean "
          << tickLabel(m->error.meanLsb) << " LSB</title></circle>\n";
        if (m->onFront)
            s << "<circle cx='" << num(px(m)) << "' cy='" << num(py(m)) << "' r='8' fill='none' stroke='#000'/>\n";
    }
    // Labels: the two headline modes first, then the front, then the rest.
    std::vector<const Measurement*> order = rows;
    auto rank = [](const Measurement* m) {
        if (m->variant == "specialised" || m->variant == "generic") return 0;
        return m->onFront ? 1 : 2;
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](const Measurement* a, const Measurement* b) { return rank(a) < rank(b); });
    std::vector<LabelBox> placed;
    for (const Measurement* m : rows)  // no label over a point (or its ring)
        placed.push_back({px(m) - 6, py(m) - 6, px(m) + 6, py(m) + 6});
    for (const Measurement* m : order) {
        double width = 5.6 * double(m->variant.size());  // 10 px sans-serif: about 5.6 px per character
        // Right of the point, left of it, above it, below it; the headline
        // modes get their label even where every place is taken.
        const double places[][2] = {{7, -3}, {-7 - width, -3}, {-width / 2, -9}, {-width / 2, 19}, {7, 13}, {-7 - width, 13}};
        for (const auto& place : places) {
            LabelBox box{px(m) + place[0], py(m) + place[1] - 12, px(m) + place[0] + width, py(m) + place[1]};
            bool free = box.x0 >= plotLeft && box.x1 <= plotRight + kRight - 10 && box.y0 >= plotTop &&
                        std::none_of(placed.begin(), placed.end(), [&](const LabelBox& b) { return b.overlaps(box); });
            if (!free && !(rank(m) == 0 && &place == &places[std::size(places) - 1])) continue;
            placed.push_back(box);
            s << "<text x='" << num(box.x0) << "' y='" << num(box.y1 - 3) << "' font-size='10' fill='"
              << (rank(m) == 0 ? "#000' font-weight='bold" : "#333") << "'>" << escape(m->variant) << "</text>\n";
            break;
        }
    }

    // Legend: the sweeps present, then the front.
    double lx = plotRight + 20, ly = plotTop + 10;
    for (const std::string& sweep : sweepNames()) {
        bool present = std::any_of(rows.begin(), rows.end(), [&](const Measurement* m) { return m->sweep == sweep; });
        if (!present) continue;
        s << "<circle cx='" << num(lx) << "' cy='" << num(ly) << "' r='4.5' fill='" << colourOf(sweep) << "'/>\n";
        s << "<text x='" << num(lx + 10) << "' y='" << num(ly + 4) << "' font-size='12'>" << sweep << "</text>\n";
        ly += 20;
    }
    s << "<circle cx='" << num(lx) << "' cy='" << num(ly) << "' r='8' fill='none' stroke='#000'/>\n";
    s << "<text x='" << num(lx + 14) << "' y='" << num(ly + 4) << "' font-size='12'>Pareto front</text>\n";
    ly += 20;
    s << "<text x='" << num(lx - 5) << "' y='" << num(ly + 8) << "' font-size='11' fill='#555'>" << first->width
      << "x" << first->height << " (reference size)</text>\n";
    s << "<text x='" << num(lx - 5) << "' y='" << num(ly + 24) << "' font-size='11' fill='#555'>errors below "
      << tickLabel(kMinError) << " on the axis</text>\n";
    s << "<text x='" << num(lx - 5) << "' y='" << num(ly + 40) << "' font-size='11' fill='#555'>(hover: every name)</text>\n";
}

}  // namespace

std::string errorTimeSvg(const std::vector<Measurement>& measurements) {
    std::vector<std::string> scenes;
    std::map<std::string, std::vector<const Measurement*>> byScene;
    for (const Measurement& m : measurements) {
        if (m.skipped || m.mode == "reference") continue;  // a CPU reference row has no GL frame time
        if (!byScene.count(m.scene)) scenes.push_back(m.scene);
        byScene[m.scene].push_back(&m);
    }
    double height = kPanelHeight * std::max<std::size_t>(1, scenes.size());
    std::ostringstream s;
    s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << num(kPanelWidth) << "' height='" << num(height)
      << "' viewBox='0 0 " << num(kPanelWidth) << " " << num(height) << "' font-family='sans-serif'>\n";
    s << "<rect width='100%' height='100%' fill='#fff'/>\n";
    if (scenes.empty())
        s << "<text x='20' y='40' font-size='14'>no measurements</text>\n";
    for (std::size_t i = 0; i < scenes.size(); ++i) panel(s, byScene[scenes[i]], kPanelHeight * double(i));
    s << "</svg>\n";
    return s.str();
}

}  // namespace rl::bench
