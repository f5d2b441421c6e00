#include "view/input_script.h"

#include "core/error.h"
#include "core/message.h"
#include "core/file_io.h"

#include <cmath>
#include <sstream>

namespace rl {
namespace {

// Frames a drag takes when the script does not say: enough to pass through
// the low-resolution "moving" state, as a hand-made drag does.
constexpr int kDefaultDragSteps = 4;
// Counts (frames, steps, sizes) above a million are typos, not intentions.
constexpr double kMaxCount = 1e6;

class LineReader {
public:
    LineReader(const std::string& line, std::string where) : in_(line), where_(std::move(where)) {}
    std::string word() {
        std::string w;
        in_ >> w;
        return w;
    }
    double number(const char* what) {
        std::string w = word();
        char* end = nullptr;
        double v = std::strtod(w.c_str(), &end);
        if (w.empty() || *end != '\0' || !std::isfinite(v)) fail("expected " + std::string(what) + ", got " + quotedValue(w));
        return v;
    }
    int integer(const char* what, int min) {
        double v = number(what);
        if (v != std::floor(v) || v < min || v > kMaxCount)
            fail(std::string(what) + " must be a whole number >= " + std::to_string(min));
        return int(v);
    }
    bool atEnd() {
        in_ >> std::ws;
        return in_.eof();
    }
    void end() {
        if (!atEnd()) fail("unexpected " + quotedValue(word()) + " at the end of the line");
    }
    [[noreturn]] void fail(const std::string& why) { throw Error(where_ + ": " + why); }

private:
    std::istringstream in_;
    std::string where_;
};

}  // namespace

std::vector<ScriptCommand> parseScriptText(const std::string& text, const std::string& origin) {
    std::vector<ScriptCommand> out;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        LineReader r(line, origin + ":" + std::to_string(number));
        if (r.atEnd()) continue;
        ScriptCommand c;
        c.line = number;
        const std::string verb = r.word();
        using K = ScriptCommand::Kind;
        if (verb == "wait") {
            c.kind = K::Wait;
            c.count = r.integer("a frame count", 0);
        } else if (verb == "sleep") {
            c.kind = K::Sleep;
            c.seconds = r.number("seconds");
            if (c.seconds < 0) r.fail("sleep needs seconds >= 0");
        } else if (verb == "wait-reload") {
            c.kind = K::WaitReload;
            c.seconds = r.number("a time-out in seconds");
            if (c.seconds <= 0) r.fail("wait-reload needs a time-out > 0 s");
        } else if (verb == "drag") {
            c.kind = K::Drag;
            c.from.x = r.number("X0");
            c.from.y = r.number("Y0");
            c.to.x = r.number("X1");
            c.to.y = r.number("Y1");
            c.count = kDefaultDragSteps;
            if (!r.atEnd()) {
                std::string button = r.word();
                if (button == "left")
                    c.button = 0;
                else if (button == "right")
                    c.button = 1;
                else if (button == "middle")
                    c.button = 2;
                else
                    r.fail("drag button must be left, right or middle, not " + quotedValue(button));
            }
            if (!r.atEnd()) c.count = r.integer("a step count", 1);
        } else if (verb == "slide") {
            c.kind = K::Slide;
            c.text = r.word();
            if (c.text != "roughness" && c.text != "metallic" && c.text != "exposure" && c.text != "env-intensity" &&
                c.text != "env-rotation")
                r.fail("slide takes roughness, metallic, exposure, env-intensity or env-rotation, not " +
                       quotedValue(c.text));
            c.startValue = r.number("a start value");
            c.value = r.number("an end value");
            c.count = kDefaultDragSteps;
            if (!r.atEnd()) c.count = r.integer("a step count", 1);
        } else if (verb == "scroll") {
            c.kind = K::Scroll;
            c.value = r.number("wheel steps");
        } else if (verb == "key") {
            c.kind = K::Key;
            c.text = r.word();
            if (c.text.empty()) r.fail("key needs a key name, e.g. key R");
        } else if (verb == "view") {
            c.kind = K::View;
            c.text = r.word();
            if (c.text.empty()) r.fail("view needs a view name, e.g. view normals");
        } else if (verb == "divider") {
            c.kind = K::Divider;
            c.value = r.number("a fraction of the width");
            if (c.value < 0 || c.value > 1) r.fail("divider must be between 0 and 1");
        } else if (verb == "pick") {
            c.kind = K::Pick;
            c.to.x = r.number("a pixel x");
            c.to.y = r.number("a pixel y");
        } else if (verb == "resize") {
            c.kind = K::Resize;
            c.to.x = r.integer("a width", 1);
            c.to.y = r.integer("a height", 1);
        } else if (verb == "screenshot") {
            c.kind = K::Screenshot;
            c.text = r.word();
            if (c.text.empty()) r.fail("screenshot needs a file name");
            if (!r.atEnd()) {
                if (r.word() != "ui") r.fail("screenshot takes a file and optionally `ui`");
                c.withUi = true;
            }
        } else if (verb == "layout") {
            c.kind = ScriptCommand::Kind::Layout;
            c.text = r.word();
            if (c.text.empty()) r.fail("layout needs a file name");
        } else if (verb == "ui-scale") {
            c.kind = ScriptCommand::Kind::UiScale;
            c.value = r.number("a UI scale");
            if (c.value < 0.5 || c.value > 4) r.fail("ui-scale must be between 0.5 and 4");
        } else if (verb == "quit") {
            c.kind = K::Quit;
        } else {
            r.fail(
                "unknown command '" + verb +
                "' (expected wait, sleep, wait-reload, drag, slide, scroll, key, view, divider, pick, resize, screenshot, layout, ui-scale or quit)");
        }
        r.end();
        out.push_back(c);
    }
    return out;
}

std::vector<ScriptCommand> parseScript(const std::string& path) {
    return parseScriptText(readRegularFile(path, kMaxTextFileBytes, "the script"), path);
}

}  // namespace rl
