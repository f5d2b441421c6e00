#include "view/script_player.h"

#include "core/error.h"

#include <cstdio>

namespace rl {

ScriptPlayer::ScriptPlayer(std::vector<ScriptCommand> commands, std::string origin)
    : commands_(std::move(commands)), origin_(std::move(origin)) {
    keys_.resize(commands_.size());
    views_.resize(commands_.size());
    for (std::size_t i = 0; i < commands_.size(); ++i) {
        const ScriptCommand& c = commands_[i];
        try {
            if (c.kind == ScriptCommand::Kind::Key) keys_[i] = bindingByName(c.text);
            if (c.kind == ScriptCommand::Kind::View) views_[i].first = parseView(c.text, views_[i].second);
        } catch (const Error& e) {
            throw Error(where(c) + ": " + e.what());
        }
    }
}

void ScriptPlayer::step(ScriptTarget& target) {
    while (!finished()) {
        const bool done = running_ ? proceed(target) : start(target);
        if (!done) {
            running_ = true;
            return;  // continues next frame
        }
        running_ = false;
        reloadMark_ = target.reloadCount();
        const ScriptCommand::Kind kind = commands_[next_].kind;
        ++next_;
        // A screenshot or a resize shows in this frame's picture: the next
        // command waits for the next frame.
        if (kind == ScriptCommand::Kind::Screenshot || kind == ScriptCommand::Kind::Resize ||
            kind == ScriptCommand::Kind::Layout || kind == ScriptCommand::Kind::UiScale)
            return;
    }
}

bool ScriptPlayer::start(ScriptTarget& target) {
    using K = ScriptCommand::Kind;
    const ScriptCommand& c = commands_[next_];
    switch (c.kind) {
        case K::Wait: framesLeft_ = c.count; return c.count == 0;
        case K::Sleep:
        case K::WaitReload:
            deadline_ =
                Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(c.seconds));
            return proceed(target);
        case K::Drag:
            target.scriptCursor(c.from);
            target.scriptMouseButton(c.button, true, c.from);
            dragStep_ = 0;
            return false;
        case K::Slide:
            target.scriptSlide(c.text, c.startValue);
            dragStep_ = 0;
            return false;
        case K::Scroll: target.scriptScroll(c.value); return true;
        case K::Key: target.scriptKey(keys_[next_]); return true;
        case K::View: target.scriptView(views_[next_].first, views_[next_].second); return true;
        case K::Divider: target.scriptDivider(c.value); return true;
        case K::Pick: target.scriptPick(c.to); return true;
        case K::Resize: target.scriptResize(int(c.to.x), int(c.to.y)); return true;
        case K::Screenshot: target.scriptScreenshot(c.text, c.withUi); return true;
        case K::Layout: target.scriptLayout(c.text); return true;
        case K::UiScale: target.scriptUiScale(c.value); return true;
        case K::Quit: target.scriptQuit(); return true;
    }
    return true;
}

bool ScriptPlayer::proceed(ScriptTarget& target) {
    using K = ScriptCommand::Kind;
    const ScriptCommand& c = commands_[next_];
    switch (c.kind) {
        case K::Wait: return --framesLeft_ <= 0;
        case K::Sleep: return Clock::now() >= deadline_;
        case K::WaitReload:
            if (target.reloadCount() > reloadMark_) return true;
            if (Clock::now() >= deadline_) {
                char seconds[32];
                std::snprintf(seconds, sizeof seconds, "%g", c.seconds);
                throw Error(where(c) + ": wait-reload: no hot reload within " + seconds + " s");
            }
            return false;
        case K::Drag: {
            ++dragStep_;
            if (dragStep_ <= c.count) {
                const double t = double(dragStep_) / c.count;
                target.scriptCursor(c.from + (c.to - c.from) * t);
                return false;
            }
            target.scriptMouseButton(c.button, false, c.to);
            return true;
        }
        case K::Slide: {
            ++dragStep_;
            const double t = double(dragStep_) / c.count;
            target.scriptSlide(c.text, c.startValue + (c.value - c.startValue) * t);
            return dragStep_ >= c.count;
        }
        default: return true;
    }
}

}  // namespace rl
