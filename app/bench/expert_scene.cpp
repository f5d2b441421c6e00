#include "bench/expert_scene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace rl::scene_facts {

// Whether sphere j can meet a segment from light L to a point of sphere k:
// j must meet the cone from L around k, no farther than k's far side.
// Conservative: margins far above float32's rounding of the hit point.
bool mayBlock(const glm::dvec3& L, const glm::dvec3& ck, double rk, const glm::dvec3& cj, double rj) {
    glm::dvec3 toK = ck - L, toJ = cj - L;
    double dk = glm::length(toK), dj = glm::length(toJ);
    if (dj <= rj * (1 + 1e-6)) return true;  // the light inside (or on) j
    if (dk <= rk * (1 + 1e-6)) return true;  // inside k: every direction
    double slack = 1e-5 * (dk + rk + dj + rj);
    if (dj - rj > dk + rk + slack) return false;  // j wholly beyond k's far side
    double cosPhi = std::clamp(glm::dot(toK, toJ) / (dk * dj), -1.0, 1.0);
    double phi = std::acos(cosPhi);
    double reach = std::asin(std::min(1.0, rk / dk)) + std::asin(std::min(1.0, rj / dj));
    return phi <= reach + 1e-5 + slack / dk;
}

Facts factsOf(const Scene& scene) {
    Facts f;
    const glm::dvec3 eye = scene.camera.position;
    f.n = int(scene.spheres.size());
    // Lengths in units of a power of two near the scene's size (exact in
    // double): a scene scaled by 1e20 or 1e-20 fits float32 like any other.
    double extent = 0;
    for (const Sphere& s : scene.spheres) extent = std::max(extent, glm::length(s.center - eye) + s.radius);
    for (const Light& l : scene.lights) extent = std::max(extent, glm::length(l.position - eye));
    f.scale = extent > 0 ? std::ldexp(1.0, -std::ilogb(extent)) : 1.0;
    for (const Sphere& s : scene.spheres) {
        glm::dvec3 c = (s.center - eye) * f.scale;
        double r = s.radius * f.scale;
        f.c.push_back(c);
        f.r.push_back(r);
        f.cc.push_back(glm::dot(c, c) - r * r);
        if (f.cc.back() <= 0) f.simple = false;
    }
    for (int i = 0; i < f.n; ++i)
        for (int j = i + 1; j < f.n; ++j)
            if (glm::length(f.c[i] - f.c[j]) < f.r[i] + f.r[j]) f.simple = false;
    for (const Light& l : scene.lights) f.light.push_back((l.position - eye) * f.scale);
    for (const glm::dvec3& L : f.light) {
        double nearest = 1e300, farthest = 0;
        for (int k = 0; k < f.n; ++k) {
            double dc = glm::length(L - f.c[k]) / f.scale, r = f.r[k] / f.scale;
            nearest = std::min(nearest, std::abs(dc - r));
            farthest = std::max(farthest, dc + r);
        }
        f.lightNearest.push_back(nearest);
        f.lightFarthest.push_back(farthest);
    }
    f.huge.assign(f.n, false);
    for (int i = 0; i < f.n && f.n > 1; ++i) {
        double smallest = 1e300;
        for (int j = 0; j < f.n; ++j)
            if (j != i) smallest = std::min(smallest, f.r[j]);
        f.huge[i] = f.r[i] > 64 * smallest;
    }
    f.may.assign(f.light.size(), std::vector<std::vector<bool>>(f.n, std::vector<bool>(f.n, false)));
    for (std::size_t l = 0; l < f.light.size(); ++l)
        for (int k = 0; k < f.n; ++k)
            for (int j = 0; j < f.n; ++j)
                if (j != k) f.may[l][k][j] = mayBlock(f.light[l], f.c[k], f.r[k], f.c[j], f.r[j]);
    return f;
}



namespace {

// The comma-separated items of `list` at bracket depth 0.
std::vector<std::string> topLevelItems(const std::string& list) {
    std::vector<std::string> items(1);
    int depth = 0;
    for (char c : list) {
        depth += (c == '(') - (c == ')');
        if (c == ',' && depth == 0) {
            items.emplace_back();
            continue;
        }
        if (!(items.back().empty() && c == ' ')) items.back() += c;
    }
    return items;
}

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// `text` with every `name[index]` (index without nested brackets) as `name(index)`.
std::string callsForIndexing(const std::string& text, const std::string& name) {
    std::string out;
    std::size_t at = 0;
    for (std::size_t found; (found = text.find(name + "[", at)) != std::string::npos;) {
        const std::size_t close = text.find(']', found);
        if ((found > 0 && identifierChar(text[found - 1])) || close == std::string::npos) {
            out += text.substr(at, found + name.size() + 1 - at);
            at = found + name.size() + 1;
            continue;
        }
        const std::size_t open = found + name.size();
        out += text.substr(at, found - at) + name + "(" + text.substr(open + 1, close - open - 1) + ")";
        at = close + 1;
    }
    return out + text.substr(at);
}

}  // namespace

std::string selectTables(const std::string& text, int maxDistinct) {
    std::istringstream in(text);
    std::string out;
    std::vector<std::string> names;
    for (std::string line; std::getline(in, line);) {
        // const T NAME[N] = T[N](items);
        std::istringstream words(line);
        std::string keyword, type, declared;
        words >> keyword >> type >> declared;
        const std::size_t bracket = declared.find('['), open = line.find('(');
        const bool table = keyword == "const" && bracket != std::string::npos && open != std::string::npos &&
                           line.size() > open + 2 && line.compare(line.size() - 2, 2, ");") == 0;
        std::vector<std::string> items;
        if (table) items = topLevelItems(line.substr(open + 1, line.size() - open - 3));
        std::vector<std::pair<std::string, std::vector<int>>> at;  // distinct values in order of first id, their ids
        for (int i = 0; i < int(items.size()); ++i) {
            auto it = std::find_if(at.begin(), at.end(), [&](const auto& v) { return v.first == items[i]; });
            if (it == at.end()) at.push_back({items[i], {i}});
            else it->second.push_back(i);
        }
        if (!table || items.empty() || int(at.size()) > maxDistinct) {
            out += line + "\n";
            continue;
        }
        const std::string name = declared.substr(0, bracket);
        names.push_back(name);
        // The most frequent value (ties: the last) needs no test; the others
        // in order of their first id.
        std::size_t common = 0;
        for (std::size_t v = 0; v < at.size(); ++v)
            if (at[v].second.size() >= at[common].second.size()) common = v;
        std::string expression = at[common].first;
        for (std::size_t v = at.size(); v-- > 0;) {
            if (v == common) continue;
            std::string test;
            for (int id : at[v].second) test += (test.empty() ? "i == " : " || i == ") + std::to_string(id);
            expression = "(" + test + ") ? " + at[v].first + " : " + expression;
        }
        out += type + " " + name + "(int i) { return " + expression + "; }\n";
    }
    for (const std::string& name : names) out = callsForIndexing(out, name);
    return out;
}

}  // namespace rl::scene_facts
