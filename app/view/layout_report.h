// What the window shows where: the rectangles of its widgets (the panel, the
// caption, the error box, the wipe's divider and labels, the side-by-side
// names, the asked-pixel box) and of the subject of the view (the spheres'
// rectangles on screen), in framebuffer pixels, origin top-left. The window
// writes it on the script command `layout FILE` (JSON); layoutProblems()
// holds the rules a projector layout must keep, so the tests and the window
// agree on them.
#pragma once

#include <string>
#include <vector>

namespace rl {

struct LayoutRect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool overlaps(const LayoutRect& o) const {
        return !empty() && !o.empty() && x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
    bool contains(const LayoutRect& o) const { return o.x0 >= x0 && o.y0 >= y0 && o.x1 <= x1 && o.y1 <= y1; }
};

struct LayoutBox {
    enum class Kind {
        Widget,   // inside the window, clear of every other widget and of the subject
        Line,     // the wipe's divider: clear of widgets, crosses the subject (that is its job)
        Part,     // inside `parent` (a widget), e.g. the asked-pixel box in the panel, a text in its frame
        Subject,  // a sphere on screen: what the widgets must leave visible
        Tool,     // the panel, a toast: clear of widgets and inside the window; may cover spheres
                  // (the lecturer shows or hides the panel; a toast goes after 3 s)
        Cover,    // the help: opaque, over the picture and its overlays (which it hides, not
                  // overlaps); clear of the tools, inside the window, its parts whole (no scrolling)
        Dock,     // the panel (or its strip), docked at the left: opaque, a tool that must also
                  // stay clear of the picture and of every sphere the camera frames
        Picture,  // where the picture is drawn (right of the docked panel): no dock over it;
                  // widgets and tools may be (they are the picture's overlays)
    };
    std::string name;  // "caption", "errors", "panel", "sphere 3", ...
    Kind kind = Kind::Widget;
    LayoutRect rect;
    std::string parent;  // Part: the widget it belongs in
};

struct LayoutReport {
    int width = 0, height = 0;  // the window, framebuffer pixels
    float uiScale = 1;
    std::vector<LayoutBox> boxes;
    void add(std::string name, LayoutBox::Kind kind, LayoutRect rect, std::string parent = {});
};

// One line a broken rule: "caption overlaps sphere 2", "errors leaves the
// window (x1 1290 > 1280)", "view-text is cut by its frame view-combo".
// Rectangles touching at an edge do not overlap; half a pixel of slack
// absorbs ImGui's sub-pixel rounding.
std::vector<std::string> layoutProblems(const LayoutReport& report);

std::string layoutJson(const LayoutReport& report);
// Throws rl::Error naming `origin` for a text that is not such a report.
LayoutReport parseLayoutJson(const std::string& text, const std::string& origin);

}  // namespace rl
