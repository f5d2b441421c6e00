#include "view/layout_report.h"

#include "core/error.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace rl {
namespace {

// ImGui places windows and text on fractional pixels; half a pixel either
// way is rounding, not an overlap or a cut (a real overlap is a line of text,
// 13 pixels at UI scale 1).
constexpr float kSlack = 0.5f;

const char* const kKindNames[] = {"widget", "line", "part", "subject", "tool", "cover", "dock", "picture"};
constexpr int kKinds = 8;

std::string number(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", double(v));
    return text;
}

LayoutRect shrunk(LayoutRect r) { return {r.x0 + kSlack, r.y0 + kSlack, r.x1 - kSlack, r.y1 - kSlack}; }

LayoutRect grown(LayoutRect r) { return {r.x0 - kSlack, r.y0 - kSlack, r.x1 + kSlack, r.y1 + kSlack}; }

std::string describe(const LayoutRect& r) {
    return "(" + number(r.x0) + ", " + number(r.y0) + ") - (" + number(r.x1) + ", " + number(r.y1) + ")";
}

}  // namespace

void LayoutReport::add(std::string name, LayoutBox::Kind kind, LayoutRect rect, std::string parent) {
    boxes.push_back({std::move(name), kind, rect, std::move(parent)});
}

std::vector<std::string> layoutProblems(const LayoutReport& report) {
    using K = LayoutBox::Kind;
    std::vector<std::string> out;
    const LayoutRect window{0, 0, float(report.width), float(report.height)};
    const auto& boxes = report.boxes;
    for (const LayoutBox& b : boxes) {
        if (b.kind == K::Subject || b.rect.empty()) continue;
        if (b.kind != K::Part && !grown(window).contains(b.rect))
            out.push_back(b.name + " leaves the window: " + describe(b.rect) + " in " + describe(window));
        if (b.kind != K::Part) continue;
        // A part sideways inside its parent: the panel scrolls, so rows above
        // or below its height are scrolled away, not cut; a text wider than
        // its frame is cut.
        bool found = false;
        for (const LayoutBox& p : boxes)
            if (p.name == b.parent) {
                found = true;
                // In a cover (the help: it never scrolls) rows beyond its height are cut too.
                const bool rowsCut = p.kind == K::Cover && (b.rect.y0 < p.rect.y0 - kSlack || b.rect.y1 > p.rect.y1 + kSlack);
                if (b.rect.x0 < p.rect.x0 - kSlack || b.rect.x1 > p.rect.x1 + kSlack || rowsCut)
                    out.push_back(b.name + " is cut by " + p.name + ": " + describe(b.rect) + " in " + describe(p.rect));
            }
        if (!found) out.push_back(b.name + ": no " + b.parent + " in the report");
    }
    // Pairs: widgets and the panel clear of each other; the divider clear of
    // both; widgets (not the panel, not the divider) clear of the subject.
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j) {
            const LayoutBox &a = boxes[i], &b = boxes[j];
            if (a.kind == K::Part || b.kind == K::Part) continue;  // checked through their widget
            // The docked panel is opaque: over the picture or a sphere it
            // hides part of what the camera frames (issue 37: two of five
            // spheres at 720p, UI scale 3).
            const bool aDock = a.kind == K::Dock, bDock = b.kind == K::Dock;
            if (aDock || bDock) {
                const LayoutBox& other = aDock ? b : a;
                if ((other.kind == K::Picture || other.kind == K::Subject) && shrunk(a.rect).overlaps(shrunk(b.rect)))
                    out.push_back((aDock ? a : b).name + " covers " + other.name + ": " +
                                  describe((aDock ? a : b).rect) + " over " + describe(other.rect));
                if (other.kind == K::Picture || other.kind == K::Subject) continue;
            }
            if (a.kind == K::Picture || b.kind == K::Picture) continue;  // the overlays are over it by design
            const bool aSubject = a.kind == K::Subject, bSubject = b.kind == K::Subject;
            if (aSubject && bSubject) continue;                          // spheres may hide each other
            if (a.kind == K::Line && b.kind == K::Line) continue;        // the divider's own pieces
            if ((aSubject && b.kind != K::Widget) || (bSubject && a.kind != K::Widget)) continue;
            // The cover hides what is under it; only the tools (the panel) must stay clear of it.
            const bool aTool = a.kind == K::Tool || aDock, bTool = b.kind == K::Tool || bDock;
            if ((a.kind == K::Cover && !bTool) || (b.kind == K::Cover && !aTool)) continue;
            if (shrunk(a.rect).overlaps(shrunk(b.rect)))
                out.push_back(a.name + " overlaps " + b.name + ": " + describe(a.rect) + " and " + describe(b.rect));
        }
    return out;
}

std::string layoutJson(const LayoutReport& report) {
    nlohmann::json j;
    j["width"] = report.width;
    j["height"] = report.height;
    j["ui_scale"] = report.uiScale;
    j["boxes"] = nlohmann::json::array();
    for (const LayoutBox& b : report.boxes) {
        nlohmann::json box = {{"name", b.name},
                              {"kind", kKindNames[int(b.kind)]},
                              {"rect", {b.rect.x0, b.rect.y0, b.rect.x1, b.rect.y1}}};
        if (!b.parent.empty()) box["parent"] = b.parent;
        j["boxes"].push_back(box);
    }
    j["problems"] = layoutProblems(report);
    return j.dump(1) + "\n";
}

LayoutReport parseLayoutJson(const std::string& text, const std::string& origin) {
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        LayoutReport r;
        r.width = j.at("width").get<int>();
        r.height = j.at("height").get<int>();
        r.uiScale = j.at("ui_scale").get<float>();
        for (const auto& b : j.at("boxes")) {
            LayoutBox box;
            box.name = b.at("name").get<std::string>();
            const std::string kind = b.at("kind").get<std::string>();
            bool known = false;
            for (int k = 0; k < kKinds; ++k)
                if (kind == kKindNames[k]) {
                    box.kind = LayoutBox::Kind(k);
                    known = true;
                }
            if (!known) throw Error(origin + ": unknown box kind '" + kind + "'");
            const auto& rect = b.at("rect");
            box.rect = {rect.at(0).get<float>(), rect.at(1).get<float>(), rect.at(2).get<float>(), rect.at(3).get<float>()};
            if (b.contains("parent")) box.parent = b.at("parent").get<std::string>();
            r.boxes.push_back(box);
        }
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw Error(origin + ": not a layout report: " + e.what());
    }
}

}  // namespace rl
