#include "view/scene_patch.h"

#include "core/error.h"
#include "core/paths.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <vector>

namespace fs = std::filesystem;

namespace rl {
namespace {

// Where each value and object of a JSON text lies. Paths as the scene
// errors name them: "render.exposure", "spheres[2].material.albedo[0]".
struct Span {
    std::size_t begin = 0, end = 0;  // [begin, end) of the value's text
};
struct ObjectSpan {
    std::size_t close = 0;  // offset of its '}'
    bool empty = true;
};

class Locator {
public:
    explicit Locator(const std::string& text) : t_(text) {
        skip();
        value("");
    }
    std::map<std::string, Span> values;
    std::map<std::string, ObjectSpan> objects;

private:
    const std::string& t_;
    std::size_t i_ = 0;

    [[noreturn]] void fail() { throw Error("the scene's text is not the JSON it was read from"); }
    void skip() {
        while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r')) ++i_;
    }
    std::string string() {  // at '"'; returns the raw content (scene keys have no escapes worth decoding)
        if (i_ >= t_.size() || t_[i_] != '"') fail();
        const std::size_t start = ++i_;
        while (i_ < t_.size() && t_[i_] != '"') i_ += t_[i_] == '\\' ? 2 : 1;
        if (i_ >= t_.size()) fail();
        return t_.substr(start, i_++ - start);
    }
    void value(const std::string& path) {
        skip();
        if (i_ >= t_.size()) fail();
        const std::size_t begin = i_;
        const char c = t_[i_];
        if (c == '{') {
            ++i_;
            skip();
            ObjectSpan o;
            while (i_ < t_.size() && t_[i_] != '}') {
                const std::string key = string();
                skip();
                if (i_ >= t_.size() || t_[i_] != ':') fail();
                ++i_;
                value(path.empty() ? key : path + "." + key);
                o.empty = false;
                skip();
                if (i_ < t_.size() && t_[i_] == ',') {
                    ++i_;
                    skip();
                }
            }
            if (i_ >= t_.size()) fail();
            o.close = i_++;
            objects[path] = o;
        } else if (c == '[') {
            ++i_;
            skip();
            int index = 0;
            while (i_ < t_.size() && t_[i_] != ']') {
                value(path + "[" + std::to_string(index++) + "]");
                skip();
                if (i_ < t_.size() && t_[i_] == ',') {
                    ++i_;
                    skip();
                }
            }
            if (i_ >= t_.size()) fail();
            ++i_;
        } else if (c == '"') {
            string();
        } else {
            while (i_ < t_.size() && t_[i_] != ',' && t_[i_] != '}' && t_[i_] != ']' && t_[i_] != ' ' &&
                   t_[i_] != '\n' && t_[i_] != '\r' && t_[i_] != '\t')
                ++i_;
        }
        values[path] = {begin, i_};
    }
};

struct Edit {
    std::size_t begin, end;
    std::string text;
};

class Patcher {
public:
    Patcher(const std::string& text) : text_(text), where_(text) {}

    void number(const std::string& path, double was, double now) {
        if (was != now) set(path, shortestNumber(now));
    }
    void integer(const std::string& path, int was, int now) {
        if (was != now) set(path, std::to_string(now));
    }
    void vec3(const std::string& path, glm::dvec3 was, glm::dvec3 now) {
        if (was == now) return;
        if (where_.values.count(path + "[2]")) {  // element by element: the spacing stays
            for (int c = 0; c < 3; ++c) number(path + "[" + std::to_string(c) + "]", was[c], now[c]);
        } else {
            set(path, "[" + shortestNumber(now.x) + ", " + shortestNumber(now.y) + ", " + shortestNumber(now.z) + "]");
        }
    }
    void word(const std::string& path, const std::string& was, const std::string& now) {
        if (was != now) set(path, now);
    }

    std::string result() {
        // Members the text lacks go into their object (made when missing).
        std::vector<Edit> edits = edits_;
        for (const auto& [object, members] : inserts_) {
            std::string joined;
            for (const auto& [key, value] : members) joined += (joined.empty() ? "" : ", ") + ("\"" + key + "\": " + value);
            insertInto(object, joined, edits);
        }
        std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
        std::string out = text_;
        for (const Edit& e : edits) out.replace(e.begin, e.end - e.begin, e.text);
        return out;
    }

private:
    const std::string& text_;
    Locator where_;
    std::vector<Edit> edits_;
    std::map<std::string, std::vector<std::pair<std::string, std::string>>> inserts_;  // object -> key, value

    void set(const std::string& path, const std::string& value) {
        auto it = where_.values.find(path);
        if (it != where_.values.end()) {
            edits_.push_back({it->second.begin, it->second.end, value});
            return;
        }
        const std::size_t dot = path.rfind('.');
        const std::string object = dot == std::string::npos ? "" : path.substr(0, dot);
        inserts_[object].push_back({path.substr(dot == std::string::npos ? 0 : dot + 1), value});
    }

    // `members` ("\"a\": 1, \"b\": 2") into the object at `path`, or, when the
    // text has no such object, the object itself into its parent.
    void insertInto(const std::string& path, const std::string& members, std::vector<Edit>& edits) {
        auto it = where_.objects.find(path);
        if (it != where_.objects.end()) {
            std::size_t at = it->second.close;  // after the last non-space before '}': a one-line object stays one line
            while (at > 0 && (text_[at - 1] == ' ' || text_[at - 1] == '\n' || text_[at - 1] == '\r' ||
                              text_[at - 1] == '\t'))
                --at;
            edits.push_back({at, at, (it->second.empty ? "" : ", ") + members});
            return;
        }
        if (path.empty() || path.back() == ']') throw Error("no object to write " + members + " into");
        const std::size_t dot = path.rfind('.');
        const std::string parent = dot == std::string::npos ? "" : path.substr(0, dot);
        const std::string key = path.substr(dot == std::string::npos ? 0 : dot + 1);
        insertInto(parent, "\"" + key + "\": {" + members + "}", edits);
    }
};

const char* const kToneMaps[] = {"\"reinhard\"", "\"exponential\"", "\"none\""};
const char* const kD[] = {"\"ggx\"", "\"beckmann\""};
const char* const kG[] = {"\"schlick-ggx\"", "\"smith-ggx\"", "\"smith-ggx-correlated\""};
const char* const kF[] = {"\"schlick\"", "\"dielectric\"", "\"conductor\""};
const char* const kFd[] = {"\"lambert\"", "\"burley\""};

}  // namespace

std::string shortestNumber(double v) {
    char text[64];
    const float f = float(v);
    std::to_chars_result r;
    if (double(f) == v && std::isfinite(f))
        r = std::to_chars(text, text + sizeof text, f);  // the panel's float: its own shortest form
    else
        r = std::to_chars(text, text + sizeof text, v);
    return std::string(text, r.ptr);
}

std::string patchSceneText(const std::string& text, const Scene& a, const Scene& b) {
    if (a.spheres.size() != b.spheres.size() || a.lights.size() != b.lights.size())
        throw Error("spheres or lights were added or removed");
    Patcher p(text);
    p.vec3("camera.position", a.camera.position, b.camera.position);
    p.vec3("camera.target", a.camera.target, b.camera.target);
    p.vec3("camera.up", a.camera.up, b.camera.up);
    p.number("camera.fov_y", a.camera.fovYDegrees, b.camera.fovYDegrees);
    const RenderSettings &ra = a.render, &rb = b.render;
    p.integer("render.width", ra.width, rb.width);
    p.integer("render.height", ra.height, rb.height);
    p.integer("render.max_bounces", ra.maxBounces, rb.maxBounces);
    p.integer("render.spp", ra.spp, rb.spp);
    p.number("render.ambient", ra.ambient, rb.ambient);
    p.vec3("render.background", ra.background, rb.background);
    p.number("render.exposure", ra.exposure, rb.exposure);
    p.word("render.tonemap", kToneMaps[int(ra.tonemap)], kToneMaps[int(rb.tonemap)]);
    if (ra.srgb != rb.srgb || (!rb.srgb && ra.gamma != rb.gamma))
        p.word("render.gamma", "", rb.srgb ? "\"srgb\"" : shortestNumber(rb.gamma));
    p.word("model.distribution", kD[int(a.model.distribution)], kD[int(b.model.distribution)]);
    p.word("model.geometry", kG[int(a.model.geometry)], kG[int(b.model.geometry)]);
    p.word("model.fresnel", kF[int(a.model.fresnel)], kF[int(b.model.fresnel)]);
    p.word("model.diffuse", kFd[int(a.model.diffuse)], kFd[int(b.model.diffuse)]);
    p.word("model.blinn_phong", a.model.blinnPhong ? "true" : "false", b.model.blinnPhong ? "true" : "false");
    for (std::size_t i = 0; i < a.spheres.size(); ++i) {
        const std::string s = "spheres[" + std::to_string(i) + "]";
        const Sphere &x = a.spheres[i], &y = b.spheres[i];
        p.vec3(s + ".center", x.center, y.center);
        p.number(s + ".radius", x.radius, y.radius);
        const Material &m = x.material, &n = y.material;
        p.vec3(s + ".material.albedo", m.albedo, n.albedo);
        p.number(s + ".material.roughness", m.roughness, n.roughness);
        p.number(s + ".material.metallic", m.metallic, n.metallic);
        p.number(s + ".material.ao", m.ao, n.ao);
        p.vec3(s + ".material.edge_tint", m.edgeTint, n.edgeTint);
    }
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        const std::string l = "lights[" + std::to_string(i) + "]";
        p.vec3(l + ".position", a.lights[i].position, b.lights[i].position);
        p.vec3(l + ".color", a.lights[i].color, b.lights[i].color);
        p.number(l + ".intensity", a.lights[i].intensity, b.lights[i].intensity);
    }
    return p.result();
}

bool isBundledScene(const std::string& path) {
    std::error_code ec;
    const fs::path scenes = fs::weakly_canonical(sourceRoot() / "scenes", ec);
    const fs::path file = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) return false;
    const auto [end, rest] = std::mismatch(scenes.begin(), scenes.end(), file.begin(), file.end());
    return end == scenes.end();
}

std::string defaultSavePath(const std::string& scenePath) {
    const fs::path scene(scenePath.empty() ? "scene.json" : scenePath);
    const fs::path folder = scenePath.empty() || isBundledScene(scenePath) ? fs::path() : scene.parent_path();
    const std::string stem = scene.stem().string() + "-edited";
    fs::path candidate = folder / (stem + ".json");
    std::error_code ec;
    for (int n = 2; fs::exists(candidate, ec) && n < 1000; ++n)
        candidate = folder / (stem + "-" + std::to_string(n) + ".json");
    return candidate.string();
}

}  // namespace rl
