// Plays a parsed --script against the window, one step per frame. The
// window implements ScriptTarget with the same functions its GLFW callbacks
// call, so a scripted drag moves the trackball exactly as a hand does.
#pragma once

#include "render/scene_uniforms.h"
#include "view/input_script.h"
#include "view/key_bindings.h"

#include <chrono>
#include <string>
#include <vector>

namespace rl {

class ScriptTarget {
public:
    virtual ~ScriptTarget() = default;
    virtual void scriptMouseButton(int button, bool pressed, glm::dvec2 pixel) = 0;  // GLFW button numbers
    virtual void scriptCursor(glm::dvec2 pixel) = 0;
    virtual void scriptScroll(double steps) = 0;
    virtual void scriptSlide(const std::string& value, double to) = 0;  // a panel slider moved
    virtual void scriptKey(const KeyBinding& binding) = 0;
    virtual void scriptView(View view, int bounce) = 0;
    virtual void scriptDivider(double fraction) = 0;
    virtual void scriptPick(glm::dvec2 pixel) = 0;
    virtual void scriptResize(int width, int height) = 0;
    virtual void scriptScreenshot(const std::string& file, bool withUi) = 0;
    virtual void scriptLayout(const std::string& file) = 0;  // written at the end of this frame
    virtual void scriptUiScale(double scale) = 0;
    virtual void scriptQuit() = 0;
    // Hot reloads applied so far (shaders and scene, good or bad).
    virtual int reloadCount() const = 0;
};

class ScriptPlayer {
public:
    // Checks every key and view name now, so a typo fails before the window
    // opens: rl::Error "demo.txt:3: unknown key 'X' (...)".
    ScriptPlayer(std::vector<ScriptCommand> commands, std::string origin);

    // Runs what this frame's share of the script is. Throws rl::Error when a
    // wait-reload times out.
    void step(ScriptTarget& target);
    bool finished() const { return next_ >= commands_.size(); }

private:
    using Clock = std::chrono::steady_clock;
    std::string where(const ScriptCommand& c) const { return origin_ + ":" + std::to_string(c.line); }
    // Starts commands_[next_]; true when it is done at once (no frames needed).
    bool start(ScriptTarget& target);
    // Continues the running command; true when it is done.
    bool proceed(ScriptTarget& target);

    std::vector<ScriptCommand> commands_;
    std::vector<KeyBinding> keys_;             // per command, for Key
    std::vector<std::pair<View, int>> views_;  // per command, for View
    std::string origin_;
    std::size_t next_ = 0;
    bool running_ = false;          // commands_[next_] has started and takes more frames
    int framesLeft_ = 0;            // Wait
    int dragStep_ = 0;              // Drag: frames done
    Clock::time_point deadline_{};  // Sleep, WaitReload
    int reloadMark_ = 0;            // reloads applied when the previous command finished
};

}  // namespace rl
