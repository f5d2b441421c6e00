#include "core/scene_io.h"

#include "core/float_range.h"

#include "core/error.h"
#include "core/file_io.h"
#include "core/json_text.h"
#include "core/message.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <set>

namespace rl {

using nlohmann::json;

namespace {

// Reads values out of one JSON object, with the field path for messages,
// and remembers which keys were used so the rest can be warned about.
class Reader {
public:
    Reader(const json& object, std::string path, std::string origin, std::vector<std::string>& warnings)
        : object_(object), path_(std::move(path)), origin_(std::move(origin)), warnings_(warnings) {
        if (!object_.is_object()) fail(displayName("") + " must be an object");
    }
    ~Reader() noexcept(false) {
        if (std::uncaught_exceptions()) return;
        for (const auto& [key, value] : object_.items())
            if (!used_.count(key))
                warnings_.push_back(origin_ + ": unknown key " + quotedValue(displayName(key), 60) + " (ignored)");
    }

    bool has(const std::string& key) {
        used_.insert(key);
        return object_.contains(key);
    }
    const json& raw(const std::string& key) {
        used_.insert(key);
        return object_.at(key);
    }
    std::string field(const std::string& key) const { return displayName(key); }

    double number(const std::string& key, double fallback) {
        if (!has(key)) return fallback;
        const json& v = object_.at(key);
        if (!v.is_number()) fail(field(key) + " must be a number, not " + typeName(v));
        double d = v.get<double>();
        if (!std::isfinite(d)) fail(field(key) + " must be finite");
        return d;
    }
    int integer(const std::string& key, int fallback) {
        if (!has(key)) return fallback;
        const json& v = object_.at(key);
        if (!v.is_number_integer() && !(v.is_number() && std::floor(v.get<double>()) == v.get<double>()))
            fail(field(key) + " must be a whole number, not " + describeJsonValue(v));
        double d = v.get<double>();
        if (std::fabs(d) > 1e9) fail(field(key) + " is out of range");
        return int(d);
    }
    // Any finite size: what float32 can carry is decided for the whole scene,
    // in its own unit of length (core/float_range.h).
    glm::dvec3 vec3(const std::string& key, glm::dvec3 fallback) {
        if (!has(key)) return fallback;
        const json& v = object_.at(key);
        if (!v.is_array() || v.size() != 3)
            fail(field(key) + " must be an array of 3 numbers, not " + describeJsonValue(v));
        glm::dvec3 out;
        for (int i = 0; i < 3; ++i) {
            std::string element = key + "[" + std::to_string(i) + "]";
            if (!v[i].is_number()) fail(field(element) + " must be a number, not " + typeName(v[i]));
            out[i] = v[i].get<double>();
            if (!std::isfinite(out[i])) fail(field(element) + " must be finite");
        }
        return out;
    }
    std::string string(const std::string& key, const std::string& fallback) {
        if (!has(key)) return fallback;
        const json& v = object_.at(key);
        if (!v.is_string()) fail(field(key) + " must be a string, not " + typeName(v));
        return v.get<std::string>();
    }
    bool boolean(const std::string& key, bool fallback) {
        if (!has(key)) return fallback;
        const json& v = object_.at(key);
        if (!v.is_boolean()) fail(field(key) + " must be true or false");
        return v.get<bool>();
    }

    [[noreturn]] void fail(const std::string& message) const { throw Error(origin_ + ": " + message); }
    void require(bool ok, const std::string& key, const std::string& rule) const {
        if (!ok) fail(field(key) + " " + rule);
    }

    static std::string typeName(const json& v) {
        if (v.is_string()) return "a string";
        if (v.is_array()) return "an array";
        if (v.is_object()) return "an object";
        if (v.is_boolean()) return "a boolean";
        if (v.is_null()) return "null";
        return "a number";
    }

private:
    std::string displayName(const std::string& key) const {
        if (key.empty()) return path_.empty() ? "the scene" : path_;
        return path_.empty() ? key : path_ + "." + key;
    }
    const json& object_;
    std::string path_;
    std::string origin_;
    std::vector<std::string>& warnings_;
    std::set<std::string> used_;
};

// v scaled so its largest component is +-1: a direction whose length can be
// taken without overflow (1e300) or underflow (1e-300).
glm::dvec3 rescaled(const glm::dvec3& v) {
    double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    return m > 0.0 ? v / m : v;
}

bool inUnit(double x) { return x >= 0.0 && x <= 1.0; }
bool inUnit(const glm::dvec3& v) { return inUnit(v.x) && inUnit(v.y) && inUnit(v.z); }
bool nonNegative(const glm::dvec3& v) { return v.x >= 0 && v.y >= 0 && v.z >= 0; }

template <typename Enum>
Enum choose(Reader& r, const std::string& key, Enum fallback,
            std::initializer_list<std::pair<const char*, Enum>> names) {
    if (!r.has(key)) return fallback;
    std::string value = r.string(key, "");
    std::string all;
    for (const auto& [name, e] : names) {
        if (value == name) return e;
        all += std::string(all.empty() ? "" : ", ") + name;
    }
    r.fail(r.field(key) + " must be one of " + all + ", not " + quotedValue(value));
}

Camera readCamera(const json& j, const std::string& origin, std::vector<std::string>& warnings) {
    Reader r(j, "camera", origin, warnings);
    Camera c;
    c.position = r.vec3("position", c.position);
    c.target = r.vec3("target", c.target);
    c.up = r.vec3("up", c.up);
    c.fovYDegrees = r.number("fov_y", c.fovYDegrees);
    r.require(c.fovYDegrees > 0.0 && c.fovYDegrees < 180.0, "fov_y", "must be between 0 and 180 degrees");
    glm::dvec3 forward = c.target - c.position;
    r.require(glm::length(forward) > 0.0, "target", "must differ from camera.position");
    // up is a direction: stored at unit length, so that [0, 1e300, 0] is "up" and the
    // float32 shader never sees its size. Both are rescaled before any length is taken.
    const char* rule = "must not be zero or parallel to the viewing direction";
    r.require(c.up != glm::dvec3(0.0), "up", rule);
    c.up = glm::normalize(rescaled(c.up));
    glm::dvec3 side = glm::cross(glm::normalize(rescaled(forward)), c.up);
    // 1e-9: sin of the angle between up and the view; below it the side vector is rounding noise.
    r.require(glm::length(side) > 1e-9, "up", rule);
    return c;
}

RenderSettings readRender(const json& j, const std::string& origin, std::vector<std::string>& warnings) {
    Reader r(j, "render", origin, warnings);
    RenderSettings s;
    s.width = r.integer("width", s.width);
    s.height = r.integer("height", s.height);
    r.require(s.width >= 1 && s.width <= kMaxImageSide, "width", "must be between 1 and 16384");
    r.require(s.height >= 1 && s.height <= kMaxImageSide, "height", "must be between 1 and 16384");
    if ((long long)s.width * s.height > kMaxPixels)
        r.fail("render.width x render.height is " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", " +
               std::to_string((long long)s.width * s.height) + " pixels, more than the limit of " +
               std::to_string(kMaxPixels) + " (8192x8192)");
    s.maxBounces = r.integer("max_bounces", s.maxBounces);
    r.require(s.maxBounces >= 0 && s.maxBounces <= kMaxBounces, "max_bounces",
              "must be between 0 and " + std::to_string(kMaxBounces));
    s.spp = r.integer("spp", s.spp);
    int n = int(std::lround(std::sqrt(double(std::max(s.spp, 0)))));
    r.require(s.spp >= 1 && s.spp <= 1024 && n * n == s.spp, "spp", "must be a square number from 1 to 1024 (1, 4, 9, 16, ...)");
    s.ambient = r.number("ambient", s.ambient);
    r.require(s.ambient >= 0.0, "ambient", "must be >= 0");
    s.background = r.vec3("background", s.background);
    r.require(nonNegative(s.background), "background", "must be >= 0 in every channel");
    s.exposure = r.number("exposure", s.exposure);
    r.require(s.exposure > 0.0, "exposure", "must be > 0");
    s.tonemap = choose(r, "tonemap", s.tonemap,
                       {{"reinhard", ToneMap::Reinhard}, {"exponential", ToneMap::Exponential}, {"none", ToneMap::None}});
    if (r.has("gamma")) {
        const json& g = r.raw("gamma");
        if (g.is_string()) {
            r.require(g.get<std::string>() == "srgb", "gamma", "must be a number or \"srgb\"");
            s.srgb = true;
        } else {
            s.gamma = r.number("gamma", s.gamma);
            r.require(s.gamma > 0.0, "gamma", "must be > 0 (or \"srgb\")");
        }
    }
    return s;
}

ShadingModel readModel(const json& j, const std::string& origin, std::vector<std::string>& warnings) {
    Reader r(j, "model", origin, warnings);
    ShadingModel m;
    m.distribution = choose(r, "distribution", m.distribution,
                            {{"ggx", DistributionModel::GGX}, {"beckmann", DistributionModel::Beckmann}});
    m.geometry = choose(r, "geometry", m.geometry,
                        {{"schlick-ggx", GeometryModel::SchlickGGX},
                         {"smith-ggx", GeometryModel::SmithGGXSeparable},
                         {"smith-ggx-correlated", GeometryModel::SmithGGXCorrelated}});
    m.fresnel = choose(r, "fresnel", m.fresnel,
                       {{"schlick", FresnelModel::Schlick}, {"dielectric", FresnelModel::Dielectric},
                        {"conductor", FresnelModel::Conductor}});
    m.diffuse = choose(r, "diffuse", m.diffuse, {{"lambert", DiffuseModel::Lambert}, {"burley", DiffuseModel::Burley}});
    m.blinnPhong = r.boolean("blinn_phong", m.blinnPhong);
    return m;
}

Material readMaterial(const json& j, const std::string& path, const std::string& origin,
                      std::vector<std::string>& warnings) {
    Reader r(j, path, origin, warnings);
    Material m;
    m.albedo = r.vec3("albedo", m.albedo);
    r.require(inUnit(m.albedo), "albedo", "must be in [0, 1] in every channel");
    m.roughness = r.number("roughness", m.roughness);
    r.require(inUnit(m.roughness), "roughness", "must be in [0, 1]");
    m.metallic = r.number("metallic", m.metallic);
    r.require(inUnit(m.metallic), "metallic", "must be in [0, 1]");
    m.ao = r.number("ao", m.ao);
    r.require(inUnit(m.ao), "ao", "must be in [0, 1]");
    m.edgeTint = r.vec3("edge_tint", m.edgeTint);
    r.require(inUnit(m.edgeTint), "edge_tint", "must be in [0, 1] in every channel");
    return m;
}

Sphere readSphere(const json& j, const std::string& path, const std::string& origin,
                  std::vector<std::string>& warnings) {
    Reader r(j, path, origin, warnings);
    Sphere s;
    s.center = r.vec3("center", s.center);
    s.radius = r.number("radius", s.radius);
    r.require(s.radius > 0.0, "radius", "must be > 0");
    if (r.has("material")) s.material = readMaterial(r.raw("material"), path + ".material", origin, warnings);
    return s;
}

Light readLight(const json& j, const std::string& path, const std::string& origin,
                std::vector<std::string>& warnings) {
    Reader r(j, path, origin, warnings);
    Light l;
    l.position = r.vec3("position", l.position);
    l.color = r.vec3("color", l.color);
    r.require(nonNegative(l.color), "color", "must be >= 0 in every channel");
    l.intensity = r.number("intensity", l.intensity);
    r.require(l.intensity >= 0.0, "intensity", "must be >= 0");
    return l;
}

// "environment": the radiance map is read here, relative to the scene file's
// folder, so that a missing or bad image is refused with the scene, in one
// line naming both files.
Environment readEnvironment(const json& j, const std::string& origin, std::vector<std::string>& warnings) {
    Reader r(j, "environment", origin, warnings);
    Environment e;
    r.require(r.has("file"), "file", "is missing: name an equirectangular .hdr or .pfm image");
    e.file = r.string("file", "");
    r.require(!e.file.empty(), "file", "must name an equirectangular .hdr or .pfm image");
    r.require(e.file.find('\0') == std::string::npos, "file", "must not hold a NUL character");
    e.intensity = r.number("intensity", e.intensity);
    r.require(e.intensity >= 0.0 && e.intensity <= kMaxEnvironmentIntensity, "intensity",
              "must be between 0 and 1e6");
    e.rotationDegrees = r.number("rotation", e.rotationDegrees);
    r.require(std::fabs(e.rotationDegrees) <= 1e6, "rotation", "must be between -1e6 and 1e6 degrees");
    std::filesystem::path file(e.file);
    e.path = (file.is_absolute() ? file : std::filesystem::path(origin).parent_path() / file).string();
    try {
        e.image = std::make_shared<const RadianceImage>(loadEnvironmentImage(e.path));
    } catch (const Error& error) {
        r.fail("environment.file " + quotedValue(e.file, 80) + ": " + error.what());
    }
    return e;
}

}  // namespace

LoadedScene parseScene(const std::string& text, const std::string& origin) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
        throw Error(origin + ": the scene file is empty (expected a JSON object)");
    json j = parseJsonText(text, origin);
    LoadedScene out;
    out.scene.sourcePath = origin;
    {  // the top-level reader adds its warnings when it goes out of scope
        Reader top(j, "", origin, out.warnings);
        Scene& s = out.scene;
        // "$schema" points editors at scenes/scene.schema.json; the program has no use for it.
        if (top.has("$schema") && !top.raw("$schema").is_string())
            top.fail("$schema must be a string (the schema's path)");
        if (top.has("camera")) s.camera = readCamera(top.raw("camera"), origin, out.warnings);
        if (top.has("render")) s.render = readRender(top.raw("render"), origin, out.warnings);
        if (top.has("model")) s.model = readModel(top.raw("model"), origin, out.warnings);
        if (top.has("environment")) s.environment = readEnvironment(top.raw("environment"), origin, out.warnings);
        for (const char* list : {"lights", "spheres"}) {
            if (!top.has(list)) continue;
            const json& items = top.raw(list);
            if (!items.is_array()) top.fail(std::string(list) + " must be an array, not " + Reader::typeName(items));
            std::size_t most = list[0] == 'l' ? kMaxLights : kMaxSpheres;
            if (items.size() > most)  // before reading them: a million entries must not take a minute
                top.fail(std::string(list) + " has " + std::to_string(items.size()) + " entries, at most " +
                         std::to_string(most) + " are supported");
            for (std::size_t i = 0; i < items.size(); ++i) {
                std::string path = std::string(list) + "[" + std::to_string(i) + "]";
                if (list[0] == 'l')
                    s.lights.push_back(readLight(items[i], path, origin, out.warnings));
                else
                    s.spheres.push_back(readSphere(items[i], path, origin, out.warnings));
            }
        }
        // Finite in double is not enough: the shader computes in float32.
        std::string range = floatRangeProblem(s);
        if (!range.empty()) throw Error(origin + ": " + range);
    }
    // Unknown keys: the first few by name, then a count, so the terminal is not flooded.
    constexpr std::size_t kMaxWarnings = 8;
    if (out.warnings.size() > kMaxWarnings) {
        std::size_t rest = out.warnings.size() - kMaxWarnings;
        out.warnings.resize(kMaxWarnings);
        out.warnings.push_back(origin + ": " + std::to_string(rest) + " more unknown keys (ignored)");
    }
    return out;
}

LoadedScene loadSceneFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(path + ": scene file not found");
    if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, expected a scene file (.json)");
    // A FIFO, a device, a file over 16 MiB: refused without blocking or reading it all.
    return parseScene(readRegularFile(path, kMaxTextFileBytes, "the scene file"), path);
}

Scene defaultScene() { return parseScene(defaultSceneJson(), "<default>").scene; }

std::string toneMapName(ToneMap op) {
    switch (op) {
        case ToneMap::Reinhard: return "reinhard";
        case ToneMap::Exponential: return "exponential";
        case ToneMap::None: return "none";
    }
    return "reinhard";
}

json sceneToJson(const Scene& s) {
    auto v = [](const glm::dvec3& x) { return json::array({x.x, x.y, x.z}); };
    json j;
    j["camera"] = {{"position", v(s.camera.position)}, {"target", v(s.camera.target)},
                   {"up", v(s.camera.up)}, {"fov_y", s.camera.fovYDegrees}};
    const RenderSettings& r = s.render;
    j["render"] = {{"width", r.width}, {"height", r.height}, {"max_bounces", r.maxBounces}, {"spp", r.spp},
                   {"ambient", r.ambient}, {"background", v(r.background)}, {"exposure", r.exposure},
                   {"tonemap", toneMapName(r.tonemap)}};
    j["render"]["gamma"] = r.srgb ? json("srgb") : json(r.gamma);
    if (!s.model.isReference()) {
        const char* d[] = {"ggx", "beckmann"};
        const char* g[] = {"schlick-ggx", "smith-ggx", "smith-ggx-correlated"};
        const char* f[] = {"schlick", "dielectric", "conductor"};
        const char* fd[] = {"lambert", "burley"};
        j["model"] = {{"distribution", d[int(s.model.distribution)]}, {"geometry", g[int(s.model.geometry)]},
                      {"fresnel", f[int(s.model.fresnel)]}, {"diffuse", fd[int(s.model.diffuse)]},
                      {"blinn_phong", s.model.blinnPhong}};
    }
    j["lights"] = json::array();
    for (const Light& l : s.lights)
        j["lights"].push_back({{"position", v(l.position)}, {"color", v(l.color)}, {"intensity", l.intensity}});
    j["spheres"] = json::array();
    for (const Sphere& sp : s.spheres) {
        const Material& m = sp.material;
        json mat = {{"albedo", v(m.albedo)}, {"roughness", m.roughness}, {"metallic", m.metallic}, {"ao", m.ao}};
        if (m.edgeTint != glm::dvec3(1.0)) mat["edge_tint"] = v(m.edgeTint);
        j["spheres"].push_back({{"center", v(sp.center)}, {"radius", sp.radius}, {"material", mat}});
    }
    if (s.environment)
        j["environment"] = {{"file", s.environment->file}, {"intensity", s.environment->intensity},
                            {"rotation", s.environment->rotationDegrees}};
    return j;
}

void saveSceneFile(const Scene& scene, const std::string& path) {
    json j = sceneToJson(scene);
    if (scene.environment) {
        // The image stays where it is: its path is written relative to the new file's folder.
        namespace fs = std::filesystem;
        std::error_code ec;
        fs::path image = fs::absolute(scene.environment->path, ec).lexically_normal();
        fs::path folder = fs::absolute(fs::path(path), ec).parent_path().lexically_normal();
        fs::path relative = image.lexically_relative(folder);
        j["environment"]["file"] = (relative.empty() ? image : relative).generic_string();
    }
    writeFileAtomic(path, j.dump(2) + "\n", WriteOptions{"the scene file"});
}

}  // namespace rl
