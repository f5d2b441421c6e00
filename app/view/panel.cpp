#include "view/panel.h"

#include "view/imgui_layer.h"
#include "view/key_bindings.h"
#include "view/presets.h"

#include <imgui.h>
#include <imgui_internal.h>  // the widest row (the layout report)

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

namespace rl {
namespace {

// Slider ranges. Exposure (kMinExposure..kMaxExposure, view_state.h) is on a
// logarithmic slider, where equal distances are equal ratios, as in a camera.
constexpr float kMinGamma = 1.0f;         // 1 = no encoding ("gamma off"); below 1 would darken, not a display gamma
constexpr float kMaxGamma = 3.0f;         // beyond any real display's 2.2-2.6
constexpr float kMaxIntensity = 1000.0f;  // W-like units: the lecture scene's key light is 40
// The environment's sliders (issue 24): uniforms of the picture (u_envIntensity,
// u_envRotation), never a recompile. Intensity on a logarithmic slider from
// 1/100 to 100 times the file's 1 (a studio at night to a sunny noon);
// rotation in degrees about +y, a whole turn either way of the file's.
constexpr float kPanelMinEnvIntensity = 0.01f;
constexpr float kPanelMaxEnvIntensity = 100.0f;
constexpr float kPanelMaxEnvRotation = 180.0f;
constexpr int kSppChoices[] = {1, 4, 9, 16};  // square numbers, as the spec requires
constexpr float kMaxPanelFraction = 0.45f;    // of the window's width: the picture keeps the larger part

const ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;  // typed values obey the range too

// A combo box whose longest item shows whole: where the item width left of
// the label column is too narrow for it (the tone map's "exponential" at UI
// scale 3 read "reinh"), the label goes on its own line above a combo as
// wide as the item needs (or the panel allows).
bool fittedCombo(const char* label, int* index, const char* const items[], int count) {
    float longest = 0;
    for (int i = 0; i < count; ++i) longest = std::max(longest, ImGui::CalcTextSize(items[i]).x);
    const float needed = longest + ImGui::GetFrameHeight() + 2.0f * ImGui::GetStyle().FramePadding.x;
    if (needed <= ImGui::CalcItemWidth()) return ImGui::Combo(label, index, items, count);
    ImGui::TextUnformatted(label);
    ImGui::SetNextItemWidth(std::min(needed, ImGui::GetContentRegionAvail().x));
    return ImGui::Combo((std::string("##") + label).c_str(), index, items, count);
}

bool editDouble(const char* label, double& value, float min, float max, const char* format = "%.3f",
                ImGuiSliderFlags flags = 0) {
    float v = float(value);
    if (!ImGui::SliderFloat(label, &v, min, max, format, flags | kClamp)) return false;
    value = v;
    return true;
}

bool editColour(const char* label, glm::dvec3& colour) {
    float c[3] = {float(colour.x), float(colour.y), float(colour.z)};
    // Float: the values are linear reflectances/colours in [0, 1], shown as such.
    // Where three numbers do not fit (UI scale 3 on 1280 px), the swatch
    // alone: a click on it opens the picker with the numbers.
    const bool narrow = ImGui::CalcItemWidth() < 12.0f * ImGui::GetFontSize();
    if (!ImGui::ColorEdit3(label, c, ImGuiColorEditFlags_Float | (narrow ? ImGuiColorEditFlags_NoInputs : 0))) return false;
    colour = {c[0], c[1], c[2]};
    return true;
}

bool editPosition(const char* label, glm::dvec3& p) {
    float v[3] = {float(p.x), float(p.y), float(p.z)};
    // 0.01 scene units per pixel dragged: a light crosses the lecture scene in a few hundred pixels.
    if (!ImGui::DragFloat3(label, v, 0.01f)) return false;
    p = {v[0], v[1], v[2]};
    return true;
}

void frameSection(ViewState& state, const PanelInfo& info) {
    if (!ImGui::CollapsingHeader("Frame", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (info.frameMs > 0)  // short: at UI scale 3 on 1280x720 "ms per frame (0.3 fps)" was cut to "(0.3"
        ImGui::Text("%.1f fps, %.0f ms a frame", 1000.0 / info.frameMs, info.frameMs);
    else
        ImGui::TextDisabled("no frame measured yet");
    if (info.gpuMs > 0) ImGui::Text("GPU %.1f ms (timer query)", info.gpuMs);
    ImGui::Text("%d x %d", info.renderWidth, info.renderHeight);
    if (info.renderWidth != info.windowWidth)  // a line of its own: beside the size it was cut at UI scale 3
        ImGui::TextDisabled("(moving; window %d x %d)", info.windowWidth, info.windowHeight);
    ImGui::Checkbox("adaptive resolution", &state.adaptiveResolution);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("fewer pixels while the camera or a value moves (30 fps)");
    ImGui::Checkbox("render every frame", &state.continuous);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Off: render only when something changes (quiet laptop fans).");
    ImGui::PushTextWrapPos(0.0f);  // the renderer's name wraps at the panel's edge
    ImGui::TextDisabled("%s", info.device.c_str());
    ImGui::PopTextWrapPos();
}

// A section's header: its name and, where the row has room, its detail
// ("Presets (course figures)"); at UI scale 3 on 1280 px the details were cut.
bool header(const char* name, const char* detail, ImGuiTreeNodeFlags flags = 0) {
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetTreeNodeToLabelSpacing();
    const std::string full = std::string(name) + detail;
    const std::string shown = ImGui::CalcTextSize(full.c_str()).x <= room ? full : std::string(name);
    return ImGui::CollapsingHeader((shown + "###" + name).c_str(), flags);
}

// A tree node's label from its parts, as many as fit the row (a label
// does not wrap: at UI scale 1 "<- asked pixel" was cut at the panel's edge);
// the first part always, a part that does not fit shortened to its arrow.
std::string fitLabel(const std::vector<std::string>& parts) {
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetTreeNodeToLabelSpacing();
    std::string label;
    for (const std::string& part : parts) {
        if (label.empty() || ImGui::CalcTextSize((label + part).c_str()).x <= room)
            label += part;
        else if (part.find("<-") != std::string::npos && ImGui::CalcTextSize((label + "  <-").c_str()).x <= room)
            label += "  <-";
    }
    return label;
}

LayoutRect itemRect() {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    const ImVec2 o = ImGui::GetMainViewport()->Pos;
    return {a.x - o.x, a.y - o.y, b.x - o.x, b.y - o.y};
}

void viewSection(ViewState& state, const Scene& scene, ViewRequests& out, PanelRects* rects) {
    if (!ImGui::CollapsingHeader("Teaching view", ImGuiTreeNodeFlags_DefaultOpen)) return;
    static std::vector<std::string> names;  // "1  D, GGX normal distribution (key light)"
    if (names.empty())
        for (const KeyBinding& b : keyBindings())
            if (b.action == Action::SetView) {
                std::string what = b.what;
                if (what.rfind("view: ", 0) == 0) what = what.substr(6);
                names.push_back(std::string(b.keys) + "  " + what);
            }
    int current = int(state.view);
    // The whole width of the panel, its label above: at UI scale 3 on 1280
    // pixels the widget column beside a label held 9 characters, "3  F(v.h"
    // (issue 26); the list opens as wide as its longest name.
    ImGui::TextUnformatted("view");
    ImGui::SetNextItemWidth(-FLT_MIN);
    // The whole name where it fits, else the key and the short name ("3  F(v.h)").
    static const char* const kShortNames[] = {"final picture", "D",          "G",           "F(v.h)",
                                              "diffuse",       "specular",   "n.l",         "shadow",
                                              "normals",       "bounce k",   "F(n.v)",      "E(n) / pi",
                                              "prefiltered",   "split scale", "split bias"};
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetFrameHeight() - 2 * ImGui::GetStyle().FramePadding.x;
    std::string preview = names[std::size_t(current)];
    if (ImGui::CalcTextSize(preview.c_str()).x > room && current < int(std::size(kShortNames)))
        preview = preview.substr(0, preview.find("  ") + 2) + kShortNames[current];
    const char* shown = preview.c_str();
    const bool open = ImGui::BeginCombo("##view", shown);
    if (rects) {
        const LayoutRect frame = itemRect();
        const ImGuiStyle& style = ImGui::GetStyle();
        const float arrow = ImGui::GetFrameHeight();
        rects->viewCombo = {frame.x0, frame.y0, frame.x1 - arrow, frame.y1};
        const ImVec2 text = ImGui::CalcTextSize(shown);
        rects->viewText = {frame.x0 + style.FramePadding.x, frame.y0 + style.FramePadding.y,
                           frame.x0 + style.FramePadding.x + text.x, frame.y0 + style.FramePadding.y + text.y};
    }
    if (open) {
        for (int i = 0; i < int(names.size()); ++i)
            if (ImGui::Selectable(names[std::size_t(i)].c_str(), i == current)) {
                state.view = View(i);
                out.redraw = true;
            }
        ImGui::EndCombo();
    }
    ImGui::Checkbox("caption (K)", &state.showCaptions);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the caption and colour bar on the picture");
    if (state.view == View::Bounce) {
        // One past max bounces: "beyond the limit it is black", shown live.
        if (ImGui::SliderInt("bounce k", &state.viewBounce, 0, std::max(scene.render.maxBounces, 0) + 1, "%d", kClamp))
            out.redraw = true;
    }
}

void displaySection(Scene& scene, ViewRequests& out) {
    if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
    RenderSettings& r = scene.render;
    out.sceneEdited |= editDouble("exposure", r.exposure, float(kMinExposure), float(kMaxExposure), "%.3f",
                                  ImGuiSliderFlags_Logarithmic);
    const char* toneMaps[] = {"reinhard", "exponential", "none"};  // the order of rl::ToneMap
    int op = int(r.tonemap);
    if (fittedCombo("tone map", &op, toneMaps, 3)) {
        r.tonemap = ToneMap(op);
        out.sceneEdited = true;
    }
    out.sceneEdited |= ImGui::Checkbox("sRGB", &r.srgb);
    ImGui::SameLine();
    ImGui::BeginDisabled(r.srgb);
    out.sceneEdited |= editDouble("gamma", r.gamma, kMinGamma, kMaxGamma, "%.2f");
    ImGui::EndDisabled();
}

void renderSection(Scene& scene, ViewRequests& out) {
    if (!ImGui::CollapsingHeader("Render")) return;
    RenderSettings& r = scene.render;
    out.sceneEdited |= ImGui::SliderInt("max bounces", &r.maxBounces, 0, kMaxBounces, "%d", kClamp);
    int sppIndex = 0;
    for (int i = 0; i < 4; ++i)
        if (kSppChoices[i] == r.spp) sppIndex = i;
    const char* sppNames[] = {"1", "4", "9", "16"};
    if (fittedCombo("samples per pixel", &sppIndex, sppNames, 4)) {
        r.spp = kSppChoices[sppIndex];
        out.sceneEdited = true;
    }
    out.sceneEdited |= editDouble("ambient", r.ambient, 0.0f, 1.0f);  // a fraction of the albedo
    out.sceneEdited |= editColour("background", r.background);
}

// The model variants (docs/model-variants.md). A change of model is the one
// panel edit that recompiles: each variant is compiled in only when used.
void modelSection(Scene& scene, ViewRequests& out) {
    if (!header("Model", " (recompiles)")) return;
    ShadingModel& m = scene.model;
    auto choose = [&](const char* label, auto& value, std::initializer_list<const char*> names) {
        int index = int(value);
        std::vector<const char*> list(names);
        if (fittedCombo(label, &index, list.data(), int(list.size()))) {
            value = std::remove_reference_t<decltype(value)>(index);
            out.sceneEdited = true;
        }
    };
    ImGui::BeginDisabled(m.blinnPhong);
    choose("D", m.distribution, {"GGX", "Beckmann"});
    choose("G", m.geometry, {"Schlick-GGX", "Smith GGX", "Smith GGX correlated"});
    choose("F", m.fresnel, {"Schlick", "exact dielectric", "exact conductor"});
    choose("diffuse", m.diffuse, {"Lambert", "Burley"});
    ImGui::EndDisabled();
    out.sceneEdited |= ImGui::Checkbox("Blinn-Phong", &m.blinnPhong);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the course comparison model");
    if (!m.isReference() && ImGui::Button("back to the reference model")) {
        m = ShadingModel{};
        out.sceneEdited = true;
    }
}

// Text wrapped at the panel's edge, a word longer than the row (a path,
// a formula) broken where the row ends: ImGui wraps at spaces only, and at
// UI scale 3 a path ran past the panel's edge, cut.
void textBrokenAnywhere(const std::string& text) {
    const float room = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize());
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.size();
        if (ImGui::CalcTextSize(text.c_str() + at, text.c_str() + end).x > room) {
            // The longest prefix that fits, ended at its last space where it has one.
            std::size_t fit = at + 1;
            while (fit < text.size() && ImGui::CalcTextSize(text.c_str() + at, text.c_str() + fit + 1).x <= room) ++fit;
            const std::size_t space = text.rfind(' ', fit);
            end = space != std::string::npos && space > at ? space : fit;
        }
        ImGui::TextUnformatted(text.c_str() + at, text.c_str() + end);
        at = end;
        while (at < text.size() && text[at] == ' ') ++at;
    }
}

void pickedSection(ViewState& state, PanelRects* rects) {
    if (state.pickedText.empty()) return;
    if (state.revealPicked) ImGui::SetNextItemOpen(true);
    const bool open = header("Asked pixel", " (Ctrl+click, I)");
    if (state.revealPicked) ImGui::SetScrollHereY(0.0f);  // the panel opens at the answer
    if (!open) return;
    // The answer first, wrapped to the panel: the first difference (or that
    // there is none) and the checker's hint; the table below scrolls.
    const std::string& all = state.pickedText;
    for (std::size_t at = 0; at < all.size();) {
        std::size_t end = all.find('\n', at);
        if (end == std::string::npos) end = all.size();
        const std::string line = all.substr(at, end - at);
        at = end + 1;
        const bool bad = line.rfind("first difference", 0) == 0 || line.rfind("a loop of", 0) == 0 ||
                         line.rfind("the pixel debugger cannot", 0) == 0;
        if (!bad && line.rfind("this pixel agrees", 0) != 0 && line.rfind("checker,", 0) != 0) continue;
        ImGui::PushStyleColor(ImGuiCol_Text, bad ? ImVec4(1.0f, 0.35f, 0.35f, 1.0f) : ImVec4(0.6f, 1.0f, 0.6f, 1.0f));
        if (line.rfind("checker,", 0) == 0) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.5f, 1.0f));
        textBrokenAnywhere(line);
        ImGui::PopStyleColor(line.rfind("checker,", 0) == 0 ? 2 : 1);
    }
    // Its own scrolling box: two lights and two bounces are ~25 lines.
    ImGui::BeginChild("##picked", ImVec2(0, 12 * ImGui::GetTextLineHeightWithSpacing()), true,
                      ImGuiWindowFlags_HorizontalScrollbar);
    // The pixel debugger's table (render/pixel_debugger.h): the first value
    // that differs from the reference (">>") and its verdict in red, the
    // values after it that differ too ("!") in orange.
    std::size_t start = 0;
    const std::string& text = state.pickedText;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        if (line.rfind(">>", 0) == 0 || line.rfind("first difference", 0) == 0) {
            ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.35f, 1.0f), "%s", line.c_str());
            if (state.revealPicked && line.rfind(">>", 0) == 0) {
                // In view at once, scrolled right far enough that the
                // model's column (after " | ") shows beside the program's.
                ImGui::SetScrollHereY(0.25f);
                const float right = ImGui::CalcTextSize(line.c_str()).x, room = ImGui::GetContentRegionAvail().x;
                ImGui::SetScrollX(std::max(0.0f, right - room));
            }
        }
        else if (line.rfind(" ~", 0) == 0)  // differs, but not at this pixel
            ImGui::TextColored(ImVec4(0.75f, 0.75f, 0.55f, 1.0f), "%s", line.c_str());
        else if (line.rfind(" !", 0) == 0)
            ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s", line.c_str());
        else
            ImGui::TextUnformatted(line.c_str());
        start = end + 1;
    }
    ImGui::EndChild();
    if (rects) rects->askedPixel = itemRect();
}

void materialsSection(Scene& scene, ViewState& state, ViewRequests& out) {
    if (state.revealPicked && state.pickedSphere >= 0) ImGui::SetNextItemOpen(true);
    if (!ImGui::CollapsingHeader("Materials")) return;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        Material& m = scene.spheres[i].material;
        ImGui::PushID(int(i));
        ImVec4 swatch(float(m.albedo.x), float(m.albedo.y), float(m.albedo.z), 1.0f);
        ImGui::ColorButton("##swatch", swatch, ImGuiColorEditFlags_NoTooltip);
        ImGui::SameLine();
        const bool picked = int(i) == state.pickedSphere;
        if (picked && state.revealPicked) ImGui::SetNextItemOpen(true);  // opened; the panel scrolls to the answer
        // The asked pixel's sphere is selected: highlighted, and marked.
        // Named as the scene file's errors name them (spheres[0] is the first).
        char values[64];
        std::snprintf(values, sizeof values, "  rough %.2f  metal %.2f", m.roughness, m.metallic);
        const std::string label = fitLabel({"spheres[" + std::to_string(i) + "]", values, picked ? "  <- asked pixel" : ""});
        if (ImGui::TreeNodeEx("sphere", picked ? ImGuiTreeNodeFlags_Selected : 0, "%s", label.c_str())) {
            out.sceneEdited |= editColour("albedo", m.albedo);
            out.sceneEdited |= editDouble("roughness", m.roughness, 0.0f, 1.0f);
            out.sceneEdited |= editDouble("metallic", m.metallic, 0.0f, 1.0f);
            out.sceneEdited |= editDouble("ao", m.ao, 0.0f, 1.0f);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

void lightsSection(Scene& scene, ViewRequests& out) {
    if (!ImGui::CollapsingHeader("Lights")) return;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        Light& l = scene.lights[i];
        ImGui::PushID(int(i));
        const std::string label = fitLabel({"lights[" + std::to_string(i) + "]", i == 0 ? "  (key light of the term views)" : ""});
        if (ImGui::TreeNode("light", "%s", label.c_str())) {
            out.sceneEdited |= editPosition("position", l.position);
            out.sceneEdited |= editColour("colour", l.color);
            out.sceneEdited |=
                editDouble("intensity", l.intensity, 0.0f, kMaxIntensity, "%.1f", ImGuiSliderFlags_Logarithmic);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

// Environment light (docs/model.md): its intensity and its rotation about +y,
// values the program reads as uniforms: dragging them never recompiles.
void environmentSection(Scene& scene, ViewRequests& out) {
    if (!scene.environment) return;
    if (!header("Environment", " (sky light)", ImGuiTreeNodeFlags_DefaultOpen)) return;
    Environment& e = *scene.environment;
    ImGui::TextDisabled("%s", e.file.c_str());
    out.sceneEdited |= editDouble("env intensity", e.intensity, kPanelMinEnvIntensity, kPanelMaxEnvIntensity,
                                  "%.3f", ImGuiSliderFlags_Logarithmic);
    out.sceneEdited |= editDouble("env rotation", e.rotationDegrees, -kPanelMaxEnvRotation,
                                  kPanelMaxEnvRotation, "%.1f deg");
}

void presetsSection(Scene& scene, const Scene& fromFile, const PanelInfo& info, ViewRequests& out) {
    if (!header("Presets", " (course figures)")) return;
    const char* group = "";
    for (const SettingPreset& p : settingPresets()) {
        if (std::strcmp(group, p.group) != 0) {
            group = p.group;
            ImGui::Text("%-12s", group);
        }
        ImGui::SameLine();
        ImGui::PushID(p.group);
        if (ImGui::SmallButton(p.label)) {
            p.apply(scene, fromFile);
            out.sceneEdited = true;
        }
        ImGui::PopID();
    }
    if (!info.presets) return;
    ImGui::TextDisabled("scenes (PageUp / PageDown):");
    for (int i = 0; i < int(info.presets->size()); ++i) {
        const auto& file = (*info.presets)[std::size_t(i)];
        std::string label = presetTitle(file) + "##" + file.string();
        if (ImGui::Selectable(label.c_str(), i == info.currentPreset)) out.openPreset = i;
    }
}

void compareSection(ViewState& state, const PanelInfo& info, ViewRequests& out) {
    if (info.right.empty() || !ImGui::CollapsingHeader("Compare", ImGuiTreeNodeFlags_DefaultOpen)) return;
    out.redraw |= ImGui::Checkbox("wipe (C)", &state.wipe);
    ImGui::TextDisabled("left: %s | right: %s", info.left.c_str(), info.right.c_str());
    out.redraw |= editDouble("divider", state.divider, 0.0f, 1.0f, "%.2f");
}

void sceneSection(ViewState& state, const PanelInfo& info, ViewRequests& out) {
    if (state.askOverwrite) ImGui::SetNextItemOpen(true);
    if (!ImGui::CollapsingHeader("Scene file")) return;
    ImGui::TextWrapped("%s", info.scenePath.empty() ? "embedded default scene" : info.scenePath.c_str());
    char path[512];
    std::snprintf(path, sizeof path, "%s", state.savePath.c_str());
    if (ImGui::InputText("save as", path, sizeof path)) state.savePath = path;
    ImGui::Checkbox("with this camera", &state.saveCamera);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("save the current view as the scene's camera");
    if (ImGui::Button("Save (Ctrl+S)")) out.save = true;
    ImGui::TextDisabled("only changed values are written; the file's layout stays");
    if (state.askOverwrite) ImGui::OpenPopup("Overwrite a bundled scene?");
    if (ImGui::BeginPopupModal("Overwrite a bundled scene?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(state.savePath.c_str());
        ImGui::TextUnformatted("is a scene of the course (scenes/). Write over it?");
        if (ImGui::Button("Overwrite")) {
            out.saveConfirmed = true;
            state.askOverwrite = false;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) {
            state.askOverwrite = false;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
}

void interfaceSection(const PanelInfo& info, ViewRequests& out) {
    if (!ImGui::CollapsingHeader("Interface")) return;
    float scale = info.uiScale;
    if (ImGui::SliderFloat("UI scale (- / +)", &scale, ImGuiLayer::kMinScale, ImGuiLayer::kMaxScale, "%.2f"))
        out.uiScale = scale;
    if (ImGui::Button("Screenshot (P)")) out.screenshot = true;
    ImGui::SameLine();
    if (ImGui::Button("with panel (F12)")) out.screenshotWithUi = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset camera (R)")) out.resetCamera = true;
}

}  // namespace

PanelRect panelRect(float windowWidth, float windowHeight, float uiScale) {
    const float s = uiScale;
    PanelRect r;
    r.x = 10 * s;
    r.y = 10 * s;
    // 340 px at scale 1 fits the label column (9 em) and a usable slider;
    // never more than kMaxPanelFraction of the window, so the picture stays
    // the larger part even at UI scale 3 on 1280x720.
    r.width = std::min(340 * s, kMaxPanelFraction * windowWidth);
    r.height = std::max(1.0f, windowHeight - 20 * s);
    return r;
}

namespace {
LayoutRect windowRect() {
    const ImVec2 p = ImGui::GetWindowPos(), size = ImGui::GetWindowSize(), o = ImGui::GetMainViewport()->Pos;
    return {p.x - o.x, p.y - o.y, p.x - o.x + size.x, p.y - o.y + size.y};
}

// The presenter's strip: the panel folded to one column of buttons at the
// left edge (the views by key, unfold), so the picture has the room.
void drawStrip(ViewState& state, float s, ViewRequests& out, PanelRects* rects) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + 10 * s, viewport->Pos.y + 10 * s), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(viewport->Size.x, viewport->Size.y - 20 * s));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove;
    if (ImGui::Begin("##strip", nullptr, flags)) {
        if (rects) rects->panel = windowRect();
        if (ImGui::Button(">>")) state.panelStrip = false;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("unfold the panel");
        for (const KeyBinding& b : keyBindings()) {
            if (b.action != Action::SetView) continue;
            const bool current = int(state.view) == b.argument;
            if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
            if (ImGui::Button(b.keys, ImVec2(ImGui::GetFrameHeight() * 1.4f, 0))) {
                state.view = View(b.argument);
                out.redraw = true;
            }
            if (current) ImGui::PopStyleColor();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", b.what);
        }
    }
    ImGui::End();
}
}  // namespace

ViewRequests drawPanel(Scene& scene, const Scene& fromFile, ViewState& state, const PanelInfo& info,
                       PanelRects* rects) {
    ViewRequests out;
    if (rects) *rects = {};
    if (!state.showPanel) return out;
    if (state.panelStrip) {
        drawStrip(state, info.uiScale, out, rects);
        return out;
    }
    const float s = info.uiScale;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const PanelRect rect = panelRect(viewport->Size.x, viewport->Size.y, s);
    // Placed again whenever the UI scale or the window size changes (the
    // user's own moves and resizes last until then): a panel sized for the
    // old scale would clip its widgets or leave the window.
    const bool relayout = state.panelLayoutScale != s || state.panelLayoutWidth != viewport->Size.x ||
                          state.panelLayoutHeight != viewport->Size.y;
    const ImGuiCond when = relayout ? ImGuiCond_Always : ImGuiCond_Once;
    state.panelLayoutScale = s;
    state.panelLayoutWidth = viewport->Size.x;
    state.panelLayoutHeight = viewport->Size.y;
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + rect.x, viewport->Pos.y + rect.y), when);
    ImGui::SetNextWindowSize(ImVec2(rect.width, rect.height), when);
    // The title says the two keys in words where they fit, in keys where
    // not (at UI scale 3 on 1280 pixels the words were cut at "Tab:"); the
    // ### part keeps the window's identity whatever the text.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float titleRoom = rect.width - 2 * style.FramePadding.x - ImGui::GetFontSize() - style.ItemInnerSpacing.x -
                            ImGui::GetFontSize() - style.ItemInnerSpacing.x;  // collapse arrow, close button
    const char* title = "raylab  (H: keys, Tab: hide)";
    if (ImGui::CalcTextSize(title).x > titleRoom) title = "raylab (H, Tab)";
    const std::string titleId = std::string(title) + "###raylab-panel";
    if (info.backgroundCleared) ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0, 0, 0, 0));  // ImGui skips it
    const bool shown = ImGui::Begin(titleId.c_str(), &state.showPanel);
    if (info.backgroundCleared) ImGui::PopStyleColor();
    if (shown) {
        if (rects) {
            rects->panel = windowRect();
            const LayoutRect& p = rects->panel;
            const float arrow = ImGui::GetFontSize() + style.ItemInnerSpacing.x;  // the collapse arrow
            const float x0 = p.x0 + style.FramePadding.x + arrow;
            rects->titleBar = {x0, p.y0, p.x1 - style.FramePadding.x - arrow, p.y0 + ImGui::GetFrameHeight()};
            const ImVec2 text = ImGui::CalcTextSize(title);
            rects->title = {x0, p.y0 + style.FramePadding.y, x0 + text.x, p.y0 + style.FramePadding.y + text.y};
        }
        // Widgets take what is left after a label column of ~9 characters,
        // and never less than 6 characters (at UI scale 3 on 1280 px the
        // panel is 576 px: 351 for the labels, 200 for the widgets).
        if (ImGui::SmallButton("<< strip")) state.panelStrip = true;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("fold the panel to a narrow strip (presenter layout)");
        ImGui::PushItemWidth(std::max(4.5f * ImGui::GetFontSize(),
                                      ImGui::GetContentRegionAvail().x - 9.0f * ImGui::GetFontSize()));
        ImGui::PushTextWrapPos(0.0f);  // every text wraps at the panel's edge (at UI scale 3 on 1280 px "(0.3 fps" was cut)
        // The view first: at UI scale 3 on 1280x720 it was below the fold.
        viewSection(state, scene, out, rects);
        frameSection(state, info);
        compareSection(state, info, out);
        displaySection(scene, out);
        renderSection(scene, out);
        modelSection(scene, out);
        pickedSection(state, rects);
        materialsSection(scene, state, out);
        state.revealPicked = false;
        lightsSection(scene, out);
        environmentSection(scene, out);
        presetsSection(scene, fromFile, info, out);
        sceneSection(state, info, out);
        interfaceSection(info, out);
        if (!info.status.empty()) ImGui::TextWrapped("%s", info.status.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopItemWidth();
        if (rects) {  // the widest row against the room for it (a text wider than the panel is cut at its edge)
            const ImGuiWindow* w = ImGui::GetCurrentWindow();
            const ImVec2 o = viewport->Pos;
            rects->content = {w->WorkRect.Min.x - o.x, w->InnerClipRect.Min.y - o.y, w->WorkRect.Max.x - o.x,
                              w->InnerClipRect.Max.y - o.y};
            rects->rows = {rects->content.x0, rects->content.y0, w->DC.CursorMaxPos.x - o.x, rects->content.y1};
        }
    }
    ImGui::End();
    return out;
}

}  // namespace rl
