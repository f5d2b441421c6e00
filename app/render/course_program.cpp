#include "render/course_program.h"

#include "course/exercise_registry.h"

#include "shader/shader_library.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace rl {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A float32 literal that reads back as the same float.
std::string num(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", double(float(v)));
    std::string s = text;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}
std::string vec(const glm::dvec3& v) { return "vec3(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }

template <class T, class F>
std::string array(const char* type, const std::vector<T>& items, F&& text) {
    std::string s = std::string(type) + "[" + std::to_string(items.size()) + "](";
    for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + text(items[i]);
    return s + ")";
}

std::string bit(int j) { return std::to_string(1u << (j % 32)) + "u"; }

// What the host knows about the scene, in double.
struct Facts {
    int n = 0;                       // spheres
    double scale = 1;                // every length below is multiplied by it
    std::vector<glm::dvec3> c;       // centres relative to the camera
    std::vector<double> r, cc;       // radius, |c|^2 - R^2 (camera outside where > 0)
    std::vector<glm::dvec3> light;   // lights relative to the camera
    // Nothing starts inside a sphere: the camera is outside every sphere and
    // no two spheres overlap, so every hit is from outside, every bounce ray
    // starts outside every sphere and no point of a surface lies inside
    // another sphere (touching is allowed).
    bool simple = true;
    // huge[i]: a sphere far larger than every other (a ground): the float
    // |p - c|^2 - R^2 of a point near it cancels, so rays that start on
    // another sphere take it from that sphere's centre (constants per pair).
    std::vector<bool> huge;
    // may[l][k]: bit j set when sphere j can block light l for some point of
    // receiver k (j != k); the receiver itself is handled apart.
    std::vector<std::vector<std::vector<bool>>> may;
};

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


// Conservative pixel bounds (gl_FragCoord units) of sphere (c, r), camera
// relative, for the camera (right, up, fw, tan(fov/2) t, aspect): the tangent
// lines from the eye in the (right, fw) and (up, fw) planes. False where the
// sphere reaches behind the near side of the eye (no bounds: always tested).
struct SphereBounds { double x0, x1, y0, y1; };
bool pixelRect(const glm::dvec3& c, double r, const glm::dvec3& right, const glm::dvec3& up, const glm::dvec3& fw,
               double t, double aspect, int width, int height, SphereBounds& out) {
    const double X = glm::dot(c, right), Y = glm::dot(c, up), Z = glm::dot(c, fw);
    if (Z <= r * 1.001 + 1e-9 * glm::length(c)) return false;
    const double a = Z * Z - r * r;
    auto range = [&](double P, double& lo, double& hi) {
        double root = r * std::sqrt(std::max(0.0, P * P + a));
        lo = (P * Z - root) / a;
        hi = (P * Z + root) / a;
    };
    double u0, u1, v0, v1;
    range(X, u0, u1);
    range(Y, v0, v1);
    // d = fx A + fy B + C: the tangent u = X_d / Z_d = fx 2 t aspect / W - t aspect.
    // Two pixels of margin: a sample lies within half a pixel of gl_FragCoord,
    // and float32's rounding of the direction is far below a pixel.
    const double margin = 2.0;
    out.x0 = (u0 + t * aspect) * width / (2 * t * aspect) - margin;
    out.x1 = (u1 + t * aspect) * width / (2 * t * aspect) + margin;
    out.y0 = (v0 + t) * height / (2 * t) - margin;
    out.y1 = (v1 + t) * height / (2 * t) + margin;
    return true;
}

// Clusters of spheres for bounce rays: recursive median splits along the
// widest axis of the centres until a cluster has at most `size` spheres.
void splitGroups(std::vector<int> ids, const Facts& f, std::size_t size, std::vector<std::vector<int>>& out) {
    if (ids.size() <= size) {
        out.push_back(ids);
        return;
    }
    glm::dvec3 lo(1e300), hi(-1e300);
    for (int i : ids) {
        lo = glm::min(lo, f.c[i]);
        hi = glm::max(hi, f.c[i]);
    }
    glm::dvec3 ext = hi - lo;
    int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    std::sort(ids.begin(), ids.end(), [&](int a, int b) { return f.c[a][axis] < f.c[b][axis]; });
    std::size_t half = ids.size() / 2;
    splitGroups(std::vector<int>(ids.begin(), ids.begin() + half), f, size, out);
    splitGroups(std::vector<int>(ids.begin() + half, ids.end()), f, size, out);
}

}  // namespace

bool courseProgramApplies(const Scene& scene, const ImplementationFacts& facts) {
    return scene.model.isReference() && facts.exercisesFinished &&
           facts.courseFiles.size() == allExercises().size();
}

std::string courseProgramSource(const Scene& original, const CourseProgramOptions& options) {
    // A sphere equal to an earlier one (centre and radius) is never the
    // nearest hit (ties go to the first) and blocks what that one blocks.
    Scene scene = original;
    scene.spheres.clear();
    for (const Sphere& s : original.spheres) {
        bool duplicate = false;
        for (const Sphere& kept : scene.spheres) duplicate = duplicate || (kept.center == s.center && kept.radius == s.radius);
        if (!duplicate) scene.spheres.push_back(s);
    }
    const Facts f = factsOf(scene);
    const RenderSettings& rs = scene.render;
    const int n = f.n, lights = int(f.light.size());
    std::ostringstream s;
    s << "// the course picture program: generated by app/render/course_program.cpp for one scene\n";
    s << "layout(location = 0) out vec4 o_display;\nlayout(location = 1) out vec4 o_radiance;\n";
    s << "const float INF = 3.0e38;\n";
    const glm::dvec3 bg = rs.background;
    const bool blackSky = bg == glm::dvec3(0.0);

    // Per-sphere constants for the hit (indexed by the hit's id).
    if (n > 0) {
        std::vector<int> idx(n);
        for (int i = 0; i < n; ++i) idx[i] = i;
        auto mat = [&](int i) -> const Material& { return scene.spheres[i].material; };
        auto rough = [&](int i) { return std::clamp(mat(i).roughness, 0.045, 1.0); };
        auto f0 = [&](int i) { return glm::mix(glm::dvec3(0.04), mat(i).albedo, mat(i).metallic); };
        s << "const vec3 SC[" << n << "] = " << array("vec3", idx, [&](int i) { return vec(f.c[i]); }) << ";\n";
        s << "const float SIR[" << n << "] = " << array("float", idx, [&](int i) { return num(1.0 / f.r[i]); }) << ";\n";
        s << "const vec3 SF0[" << n << "] = " << array("vec3", idx, [&](int i) { return vec(f0(i)); }) << ";\n";
        s << "const vec3 SKD[" << n << "] = "  // (1 - metallic) albedo / pi
          << array("vec3", idx, [&](int i) { return vec((1 - mat(i).metallic) * mat(i).albedo / kPi); }) << ";\n";
        s << "const vec3 SAMB[" << n << "] = "
          << array("vec3", idx, [&](int i) { return vec(rs.ambient * mat(i).albedo * mat(i).ao); }) << ";\n";
        s << "const float SA2[" << n << "] = "
          << array("float", idx, [&](int i) { double r = rough(i); return num(r * r * r * r); }) << ";\n";
        s << "const float SK[" << n << "] = "
          << array("float", idx, [&](int i) { double r = rough(i); return num((r + 1) * (r + 1) / 8); }) << ";\n";
        if (rs.maxBounces > 0) {
            s << "const vec3 SFR[" << n << "] = "  // max(1 - r, F0) - F0
              << array("vec3", idx, [&](int i) { return vec(glm::max(glm::dvec3(1 - rough(i)), f0(i)) - f0(i)); }) << ";\n";
            if (!f.simple)
                s << "const float S2R[" << n << "] = " << array("float", idx, [&](int i) { return num(2 * f.r[i]); }) << ";\n";
        }
        for (int i = 0; i < n && rs.maxBounces > 0; ++i) {
            if (!f.huge[i]) continue;
            s << "const float HK" << i << "[" << n << "] = " << array("float", idx, [&](int k) {
                glm::dvec3 d = f.c[k] - f.c[i];
                return num(k == i ? 0.0 : glm::dot(d, d) - f.r[i] * f.r[i] + f.r[k] * f.r[k]);
            }) << ";\n";
            s << "const vec3 HD" << i << "[" << n << "] = " << array("vec3", idx, [&](int k) {
                return vec(k == i ? glm::dvec3(0.0) : 2 * f.r[k] * (f.c[k] - f.c[i]));
            }) << ";\n";
        }
        for (int l = 0; l < lights; ++l) {
            for (int half = 0; half < (n > 32 ? 2 : 1); ++half) {
                std::vector<unsigned> masks;
                for (int k = 0; k < n; ++k) {
                    unsigned m = 0;
                    for (int j = half * 32; j < std::min(n, half * 32 + 32); ++j)
                        if (f.may[l][k][j]) m |= 1u << (j % 32);
                    masks.push_back(m);
                }
                s << "const uint M" << l << "_" << half << "[" << n << "] = "
                  << array("uint", masks, [](unsigned m) { return std::to_string(m) + "u"; }) << ";\n";
            }
            if (!f.simple) {  // inside hits: a light outside the receiver is behind its wall
                s << "const bool LOUT" << l << "[" << n << "] = " << array("bool", idx, [&](int k) {
                    glm::dvec3 d = f.light[l] - f.c[k];
                    return std::string(glm::dot(d, d) - f.r[k] * f.r[k] > 0 ? "true" : "false");
                }) << ";\n";
            }
        }
    }

    // The nearest hit from the camera: branch-free selects over constants.
    // The camera: one pixel-to-direction expression, d = fx A + fy B + C.
    const Camera& cam = scene.camera;
    glm::dvec3 fw = glm::normalize(cam.target - cam.position);
    glm::dvec3 right = glm::normalize(glm::cross(fw, cam.up));
    glm::dvec3 up = glm::cross(right, fw);
    double t = std::tan(cam.fovYDegrees * kPi / 360.0), aspect = double(rs.width) / rs.height;
    const std::size_t globalsAt = std::size_t(s.tellp());
    std::ostringstream globals;  // constants written while the code is (the shadow lists)
    s << "\nvec3 radiance(vec3 d, vec2 f) {\n";
    if (n == 0) {
        s << "    return " << vec(bg) << ";\n}\n";
    } else {
        s << "    float best = INF, m, disc, t, sq;\n    int id = -1;\n    vec3 q;\n    bool h;\n";
        for (int i = 0; i < n; ++i) {
            SphereBounds box{};
            const bool bounded = options.screenRects &&
                                 pixelRect(f.c[i], f.r[i], right, up, fw, t, aspect, rs.width, rs.height, box);
            if (bounded && (box.x1 < 0 || box.y1 < 0 || box.x0 > rs.width || box.y0 > rs.height)) continue;  // off screen
            const bool whole = !bounded || (box.x0 <= 0 && box.y0 <= 0 && box.x1 >= rs.width && box.y1 >= rs.height);
            if (!whole)
                s << "    if (f.x >= " << num(box.x0) << " && f.x <= " << num(box.x1) << " && f.y >= " << num(box.y0)
                  << " && f.y <= " << num(box.y1) << ") {\n";
            // The quarter discriminant: m^2 - (|c|^2 - R^2) where the camera is
            // inside or within R^2 of the surface (no cancellation: the constant
            // is exact), else from the perpendicular distance (docs/model.md).
            if (f.cc[i] < f.r[i] * f.r[i])
                s << "    m = dot(" << vec(f.c[i]) << ", d); disc = m * m - " << num(f.cc[i]) << "; sq = sqrt(max(disc, 0.0));\n";
            else
                s << "    m = dot(" << vec(f.c[i]) << ", d); q = " << vec(f.c[i]) << " - m * d; disc = "
                  << num(f.r[i] * f.r[i]) << " - dot(q, q); sq = sqrt(max(disc, 0.0));\n";
            if (f.cc[i] > 0)  // outside: the near root in one expression
                s << "    t = " << num(f.cc[i]) << " / (m + sq); h = m > 0.0 && disc >= 0.0 && t < best;\n";
            else  // inside: the far root, stable either way
                s << "    t = m >= 0.0 ? m + sq : " << num(f.cc[i]) << " / (m - sq); h = t > 0.0 && t < best;\n";
            s << "    best = h ? t : best; id = h ? " << i << " : id;\n";
            if (!whole) s << "    }\n";
        }
        s << "    if (id < 0) return " << vec(bg) << ";\n";
        s << "    vec3 p = best * d, sum = vec3(0.0)" << (rs.maxBounces > 0 ? ", T = vec3(1.0)" : "") << ";\n";
        if (rs.maxBounces > 0) s << "    for (int bounce = 0;; ++bounce) {\n";
        else s << "    {\n";
        const char* T = rs.maxBounces > 0 ? "T * " : "";
        s << "        vec3 no = (p - SC[id]) * SIR[id];\n"
             "        float nd = dot(no, d);\n"
             "        bool inside = nd > 0.0;\n"
             "        vec3 n = inside ? -no : no, v = -d;\n"
             "        float NoV = clamp(abs(nd), 1e-4, 1.0);\n"
             "        vec3 c = SAMB[id], F0 = SF0[id], KD = SKD[id];\n"
             "        float a2 = SA2[id], k1 = SK[id], gv = 0.25 / (NoV * (1.0 - k1) + k1), x, x5;\n";
        if (lights > 0) s << "        vec3 lu, s, F;\n        float d2, il, NoL, E, ss, ns, den;\n        bool blk;\n";
        for (int l = 0; l < lights; ++l) {
            const Light& light = scene.lights[l];
            // The model's d2 <= 1e-12 (a light on the surface adds nothing), in
            // the scene's units: a light within 1e-6 of every surface point is
            // left out; the test is written only where some point is that close.
            double nearest = 1e300, farthest = 0;
            for (int k = 0; k < n; ++k) {
                double dc = glm::length(f.light[l] - f.c[k]) / f.scale, r = f.r[k] / f.scale;
                nearest = std::min(nearest, std::abs(dc - r));
                farthest = std::max(farthest, dc + r);
            }
            if (farthest * farthest <= 1e-12) continue;
            const std::string onSurface =
                nearest * nearest <= 1e-12 * (1 + 1e-6) ? " && d2 > " + num(1e-12 * f.scale * f.scale) : "";
            s << "        lu = " << vec(f.light[l]) << " - p; d2 = dot(lu, lu); il = inversesqrt(d2); NoL = dot(n, lu) * il;\n";
            // Lights behind the surface skip everything, whole pixel groups at a time.
            s << "        if (NoL > 0.0" << onSurface << (f.simple ? "" : " && !(inside && LOUT" + std::to_string(l) + "[id])") << ") {\n";
            s << "            blk = false;\n";
            // The occluder candidates of (light, receiver) as a list walked by a
            // loop: llvmpipe runs every `if` body for its whole pixel group (the
            // condition only masks the writes), but a loop stops when no pixel of
            // the group needs another turn, so a receiver with 3 candidates of 30
            // pays for 3 tests, and a group stops at its first blocker.
            std::vector<std::vector<int>> lists(n);
            bool listable = options.shadowLists;
            for (int k = 0; k < n; ++k)
                for (int j = 0; j < n; ++j)
                    if (f.may[l][k][j]) {
                        glm::dvec3 oc = f.light[l] - f.c[j];
                        if (glm::dot(oc, oc) - f.r[j] * f.r[j] <= 0) listable = false;  // the light inside j
                        lists[k].push_back(j);
                    }
            std::size_t total = 0;
            for (auto& list : lists) {
                // Likelier blockers first: larger as seen from the light.
                std::sort(list.begin(), list.end(), [&](int a, int b) {
                    return f.r[a] / glm::length(f.light[l] - f.c[a]) > f.r[b] / glm::length(f.light[l] - f.c[b]);
                });
                total += list.size();
            }
            if (listable && total > 0) {
                std::vector<int> flat, starts;
                for (const auto& list : lists) {
                    starts.push_back(int(flat.size()));
                    flat.insert(flat.end(), list.begin(), list.end());
                }
                starts.push_back(int(flat.size()));
                std::vector<int> all(n);
                for (int j = 0; j < n; ++j) all[j] = j;
                const std::string L = std::to_string(l);
                auto ints = [](int v) { return std::to_string(v); };
                globals << "const int SLJ" << L << "[" << flat.size() << "] = " << array("int", flat, ints) << ";\n";
                globals << "const int SLS" << L << "[" << starts.size() << "] = " << array("int", starts, ints) << ";\n";
                globals << "const vec4 SLC" << L << "[" << n << "] = " << array("vec4", all, [&](int j) {
                    glm::dvec3 oc = f.light[l] - f.c[j];
                    return "vec4(" + num(oc.x) + ", " + num(oc.y) + ", " + num(oc.z) + ", " +
                           num(glm::dot(oc, oc) - f.r[j] * f.r[j]) + ")";
                }) << ";\n";
                s << "            for (int q = SLS" << L << "[id], e = SLS" << L << "[id + 1]; q < e && !blk; ++q) {"
                  << " vec4 o = SLC" << L << "[SLJ" << L << "[q]]; E = dot(o.xyz, lu); blk = E > 0.0 && E * E >= d2 * o.w";
                if (f.simple) s << " && E < d2; }\n";
                else s << " && (E < d2 || d2 - 2.0 * E + o.w <= 0.0); }\n";
            }
            bool any = false;
            for (int j = 0; j < n && !(listable && total > 0); ++j) {
                bool used = false;
                for (int k = 0; k < n; ++k) used = used || f.may[l][k][j];
                if (!used) continue;
                if (!any) {
                    s << "            uint m0 = M" << l << "_0[id]" << (n > 32 ? ", m1 = M" + std::to_string(l) + "_1[id]" : "")
                      << ";\n";
                    any = true;
                }
                glm::dvec3 oc = f.light[l] - f.c[j];
                double cl = glm::dot(oc, oc) - f.r[j] * f.r[j];
                if (cl > 0 && options.branchFreeShadows) {
                    // Branch-free (llvmpipe runs an `if` body for the whole group
                    // anyway): the receiver itself by its id; a sphere outside the
                    // (light, receiver) mask fails the test by geometry (the mask's
                    // margins are far above float32's error of E).
                    s << "            E = dot(" << vec(oc) << ", lu); blk = blk || (id != " << j
                      << " && E > 0.0 && E * E >= d2 * " << num(cl);
                    if (f.simple) s << " && E < d2);\n";
                    else s << " && (E < d2 || d2 - 2.0 * E + " << num(cl) << " <= 0.0));\n";
                    continue;
                }
                s << "            if (!blk && (m" << j / 32 << " & " << bit(j) << ") != 0u) {";
                if (cl > 0) {
                    // From the light's side: the segment L -> p enters sphere j
                    // before p. E = (L - c).(p - L) negated; no square root.
                    s << " E = dot(" << vec(oc) << ", lu); blk = E > 0.0 && E * E >= d2 * " << num(cl);
                    if (f.simple) s << " && E < d2;";
                    else s << " && (E < d2 || d2 - 2.0 * E + " << num(cl) << " <= 0.0);";
                } else {  // the light inside j: blocked where p is outside j
                    s << " vec3 w = p - " << vec(f.c[j]) << "; blk = dot(w, w) > " << num(f.r[j] * f.r[j]) << ";";
                }
                s << " }\n";
            }
            // P / d2 with d2 in the scaled units: P scaled by scale^2.
            const glm::dvec3 power = light.color * light.intensity * (f.scale * f.scale);
            s << "            if (!blk) {\n"
                 "                s = lu * il + v; ss = dot(s, s); ns = dot(n, s); vec3 cx = cross(n, s);\n"
                 // D = a2 / (pi ((n.h)^2 (a2 - 1) + 1)^2) with h = s/|s|, 1 - (n.h)^2 = |n x s|^2/|s|^2
                 "                den = a2 * ns * ns + dot(cx, cx);\n"
                 "                x = 1.0 - min(0.5 * sqrt(ss), 1.0); x5 = x * x; x5 *= x5 * x;\n"
                 "                F = F0 + (1.0 - F0) * x5;\n"
                 // G / (4 NoL NoV) = gv / (NoL (1 - k) + k)
                 "                c += ((1.0 - F) * KD + F * (a2 * ss * ss / ("
              << num(kPi) << " * den * den) * gv / (NoL * (1.0 - k1) + k1))) * (" << vec(power)
              << " * (NoL / d2));\n"
                 "            }\n        }\n";
        }
        s << "        sum += " << T << "c;\n";
        if (rs.maxBounces > 0) {
            s << "        if (bounce == " << rs.maxBounces << ") break;\n"
                 "        x = 1.0 - NoV; x5 = x * x; x5 *= x5 * x;\n";
            s << "        T *= SF0[id] + SFR[id] * x5;\n"
                 "        d += (2.0 * abs(nd)) * n;\n"
                 "        int k = id;\n        best = INF; id = -1;\n        vec3 oc; float b, cq;\n";
            // Huge spheres alone; the others in clusters behind a bounding-sphere test.
            std::vector<std::vector<int>> groups;
            std::vector<int> clustered;
            for (int i = 0; i < n; ++i) {
                if (f.huge[i] || !options.bounceGroups || n < 8) groups.push_back({i});
                else clustered.push_back(i);
            }
            if (!clustered.empty()) splitGroups(clustered, f, 4, groups);
            for (const std::vector<int>& group : groups) {
              const bool guarded = group.size() > 1;
              if (guarded) {
                glm::dvec3 lo(1e300), hi(-1e300);
                for (int i : group) {
                    lo = glm::min(lo, f.c[i] - glm::dvec3(f.r[i]));
                    hi = glm::max(hi, f.c[i] + glm::dvec3(f.r[i]));
                }
                const glm::dvec3 gc = 0.5 * (lo + hi);
                double gr = 0;
                for (int i : group) gr = std::max(gr, glm::length(f.c[i] - gc) + f.r[i]);
                // Margin far above float32's rounding of p and d (relative 1e-3 of
                // the cluster and of its distance from the camera).
                gr = gr * 1.001 + 1e-4 * glm::length(gc);
                s << "        oc = p - " << vec(gc) << "; b = dot(oc, d); cq = dot(oc, oc) - " << num(gr * gr)
                  << ";\n        if (cq <= 0.0 || (b < 0.0 && b * b >= cq)) {\n";
              }
              for (int i : group) {
                if (f.huge[i])  // p = c_k + R_k no: |p - c|^2 - R^2 = |c_k - c|^2 - R^2 + R_k^2 + 2 R_k no.(c_k - c)
                    s << "        b = dot(p - " << vec(f.c[i]) << ", d); cq = HK" << i << "[k] + dot(no, HD" << i
                      << "[k]); disc = b * b - cq; sq = sqrt(max(disc, 0.0));\n";
                else
                    s << "        oc = p - " << vec(f.c[i]) << "; b = dot(oc, d); q = oc - b * d; disc = "
                      << num(f.r[i] * f.r[i]) << " - dot(q, q); cq = dot(oc, oc) - " << num(f.r[i] * f.r[i])
                      << "; sq = sqrt(max(disc, 0.0));\n";
                if (f.simple)  // every ray starts outside sphere i: the near root
                    s << "        t = cq / (sq - b); h = k != " << i << " && b < 0.0 && disc >= 0.0 && t > 0.0 && t < best;\n";
                else
                    s << "        t = cq > 0.0 ? (b < 0.0 ? cq / (sq - b) : INF) : (b <= 0.0 ? sq - b : cq / (-b - sq));\n"
                      << "        h = k != " << i << " && disc >= 0.0 && t > 0.0 && t < best;\n";
                s << "        best = h ? t : best; id = h ? " << i << " : id;\n";
              }
              if (guarded) s << "        }\n";
            }
            if (!f.simple)  // leaving the inside of k: its far side, 2R (n.d)
                s << "        if (inside) { t = S2R[k] * dot(n, d); if (t < best) { best = t; id = k; } }\n";
            s << "        if (id < 0) { " << (blackSky ? "" : "sum += T * " + vec(bg) + "; ") << "break; }\n"
                 "        p += best * d;\n";
        }
        s << "    }\n    return sum;\n}\n";
    }

    // The camera: one pixel-to-direction expression, d = fx A + fy B + C.
    glm::dvec3 A = right * (2 * t * aspect / rs.width), B = up * (2 * t / rs.height);
    glm::dvec3 C = fw - right * (t * aspect) - up * t;  // gl_FragCoord is the pixel's centre
    int grid = int(std::lround(std::sqrt(double(rs.spp))));
    s << "\nvoid main() {\n    vec2 f = gl_FragCoord.xy;\n";
    if (grid <= 1) {
        s << "    vec3 L = radiance(normalize(f.x * " << vec(A) << " + f.y * " << vec(B) << " + " << vec(C) << "), f);\n";
    } else {
        s << "    vec3 L = vec3(0.0);\n    for (int a = 0; a < " << grid << "; ++a)\n        for (int b = 0; b < " << grid
          << "; ++b) {\n            vec2 g = f + (vec2(a, b) + 0.5) * " << num(1.0 / grid) << " - 0.5;\n"
          << "            L += radiance(normalize(g.x * " << vec(A) << " + g.y * " << vec(B) << " + " << vec(C) << "), f);\n"
          << "        }\n    L *= " << num(1.0 / (grid * grid)) << ";\n";
    }
    s << "    vec3 c = L * " << num(rs.exposure) << ";\n";
    switch (rs.tonemap) {
    case ToneMap::Reinhard: s << "    c = c / (1.0 + c);\n"; break;
    case ToneMap::Exponential: s << "    c = 1.0 - exp(-c);\n"; break;
    case ToneMap::None: s << "    c = clamp(c, 0.0, 1.0);\n"; break;
    }
    if (rs.srgb)
        s << "    c = mix(12.92 * c, 1.055 * pow(c, vec3(" << num(1 / 2.4) << ")) - 0.055, step(0.0031308, c));\n";
    else
        s << "    c = pow(c, vec3(" << num(1.0 / rs.gamma) << "));\n";
    s << "    o_display = vec4(c, 1.0);\n    o_radiance = vec4(L, 1.0);\n}\n";
    std::string text = s.str();
    text.insert(globalsAt, globals.str());
    if (!options.uniformTables) return text;
    // The tables indexed by a value (the hit's id, a list position) as uniforms
    // with their values as initialisers: a dynamically indexed const array is
    // built anew by every pixel group on llvmpipe, a uniform is read in place.
    std::istringstream in(text);
    std::string out;
    for (std::string line; std::getline(in, line);) {
        const std::size_t bracket = line.find('['), equals = line.find('=');
        if (line.rfind("const ", 0) == 0 && bracket != std::string::npos && equals != std::string::npos && bracket < equals)
            line = "uniform " + line.substr(6);
        out += line + "\n";
    }
    return out;
}

ShaderProgram buildCourseProgram(const Scene& scene, const CourseProgramOptions& options) {
    AssembledSource fragment;
    std::istringstream lines(shaderPrelude({}) + courseProgramSource(scene, options));
    int number = 0;
    for (std::string line; std::getline(lines, line);) fragment.append(line, {"<course picture program>", ++number});
    Implementation none;
    return ShaderProgram(assembleShader("fullscreen.vert", none, {}), fragment);
}

}  // namespace rl

namespace rl {

PictureProgram buildCoursePicture(const Scene& scene, const CourseProgramOptions& options) {
    PictureProgram picture{buildCourseProgram(scene, options), std::nullopt};
    if (options.skyTiles && !scene.spheres.empty()) {
        // The tiles no camera ray can hit a sphere in (render/sky_tiles.h):
        // the same generator with no sphere writes the same background pixel.
        Scene sky = scene;
        sky.spheres.clear();
        picture.sky = buildCourseProgram(sky, options);
    }
    return picture;
}

}  // namespace rl
