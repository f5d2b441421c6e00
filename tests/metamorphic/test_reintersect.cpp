// pbrt-v4's re-intersection test as a yardstick (issue #23; pbrt-v4,
// src/pbrt/shapes_test.cpp, FullSphere.Reintersect): spheres of radius
// 10^[-4, 4], each hit from outside by a ray from an origin whose components
// are up to 10^8 away, and from that hit rays leave in random directions. A ray that
// leaves the side the normal faces must not meet the same surface again (a
// self-hit); one that leaves into the surface (n.w < -0.05) must meet it
// (else it wrongly passed through it). The GLSL runs through the probe
// machinery of `raylab check` (probe.glsl, PROBE_REINTERSECT) with the
// course's files: the offset of exercise 04 alone (every sphere asked, its
// own included: what pbrt tests), the offset with the framework's handling
// of the sphere a ray leaves (closestHit's `leaving`), and the bounce of 09
// (along reflect(d, n)). The CPU reference runs the same rays (its offset
// Hit::error alone, and nextHit()).
//
// The same through the code of `raylab render`'s program (issue #33): each
// sphere's numbers compiled in as the picture program compiles them
// (Purpose::Picture's defines, render/define_table.h), one program a sphere.
//
// CI draws 100 spheres x 100 rays (0.2 s of probes), and 20 spheres x 100
// rays through the picture's code (a compile each); RAYLAB_REINTERSECT_FULL=1
// draws pbrt's 1000 x 1000 both ways.
#include "accuracy/accuracy_support.h"
#include "checks/probe_runner.h"
#include "render/define_table.h"
#include "render/implementation_facts.h"
#include "shader/shader_library.h"
#include "core/paths.h"
#include "metamorphic/random_scene.h"
#include "reference/cpu_reference.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace rl::meta {
namespace {

using glm::dvec3;

// Inward rays nearer the tangent plane than this may miss legitimately: from
// the offset origin, delta above a sphere of radius r, a ray with
// n.w = -c meets the sphere only for c > sqrt(2 delta / r) (about 1e-3 for
// the offsets here).
constexpr double kInwardMargin = 0.05;

struct Counts {
    long tested = 0, selfHits = 0, passThroughs = 0, firstMissed = 0;
    std::string first;  // the first failure, for the message
    void fail(long& counter, const std::string& what) {
        ++counter;
        if (first.empty()) first = what;
    }
    std::string summary() const {
        return std::to_string(tested) + " rays: " + std::to_string(selfHits) + " self-hits, " +
               std::to_string(passThroughs) + " pass-throughs (" + std::to_string(firstMissed) +
               " first rays missed)" + (first.empty() ? "" : "; first: " + first);
    }
};

struct Generator {
    std::uint64_t state;
    double uniform() {
        state += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }
    double exp10(double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * uniform()); }
    dvec3 unitVector() {
        double z = 2 * uniform() - 1, phi = 2 * M_PI * uniform(), s = std::sqrt(std::max(0.0, 1 - z * z));
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
};

struct Yardstick {
    int spheres = 100, rays = 100;
    explicit Yardstick(bool specialised = false) {
        if (specialised) spheres = 20;
        if (const char* full = std::getenv("RAYLAB_REINTERSECT_FULL"); full && *full && std::string(full) != "0") {
            spheres = 1000;
            rays = 1000;
        }
    }
};

// Sphere k: radius 10^[-4, 4], its centre anywhere up to 10^6 from the
// world's origin (the GLSL sees it relative to the anchor, the CPU in world
// coordinates), a ray origin outside it whose components are 10^[-8, 8]
// from it (pbrt's pExp, with random signs), at most 2^22 radii away,
// towards a random point of its bounding box.
struct SphereCase {
    Scene scene;
    dvec3 origin, dir;
    std::vector<dvec3> outgoing;
};

SphereCase sphereCase(int k, int rays) {
    Generator g{std::uint64_t(k) * 7919 + 23};
    SphereCase c;
    double r = g.exp10(-4, 4);
    dvec3 centre = g.exp10(0, 6) * g.unitVector();
    Material m;
    c.scene.spheres = {sphere(centre, r, m)};
    c.scene.camera.position = centre;  // the probe's anchor (probe_runner.cpp): the sphere's centre, as sceneAnchor()
    c.scene.camera.target = centre + dvec3(0, 0, -1);
    dvec3 offset(0.0);
    // Outside the sphere (drawn again until it is): from inside, the side the
    // normal faces is the sphere's inside, where meeting the far wall is right.
    // And at most 2^22 radii away: farther, float32 rounds the hit point
    // o + t d by more than a quarter of the radius, the hit's normal is
    // noise, and the loader refuses a scene whose camera sees such a sphere
    // wider than a pixel (floatRangeProblem(), core/float_range.h).
    while (glm::length(offset) <= 1.001 * r || glm::length(offset) > 4194304.0 * r)
        for (int i = 0; i < 3; ++i) offset[i] = (g.uniform() < 0.5 ? -1 : 1) * g.exp10(-8, 8);
    c.origin = centre + offset;
    dvec3 target = centre + r * dvec3(2 * g.uniform() - 1, 2 * g.uniform() - 1, 2 * g.uniform() - 1);
    c.dir = glm::normalize(target - c.origin);
    for (int j = 0; j < rays; ++j) c.outgoing.push_back(g.unitVector());
    return c;
}

void put(ProbeCase& p, int at, glm::vec3 v) {
    p.in[std::size_t(at)] = v.x;
    p.in[std::size_t(at) + 1] = v.y;
    p.in[std::size_t(at) + 2] = v.z;
}

// The GLSL's counts for one implementation; mode 0: the offset alone, 1:
// with the sphere the ray leaves handled by the framework, 2: the bounce.
// `specialised`: each sphere's program with its numbers compiled in, as the
// picture program of `raylab render` has them.
Counts glslCounts(const Implementation& impl, int mode, bool specialised = false) {
    Yardstick size(specialised);
    const ImplementationFacts facts = implementationFacts(impl);
    const ShaderProgram& generic = acc::probeProgram(4, impl);  // and the headless context
    Counts counts;
    for (int k = 0; k < size.spheres; ++k) {
        SphereCase c = sphereCase(k, size.rays);
        std::unique_ptr<ShaderProgram> own;
        if (specialised) {
            ShaderDefines defines = definesFor(c.scene, facts, Purpose::Picture);
            defines["RL_PROBE_EXERCISE"] = "4";
            own = std::make_unique<ShaderProgram>(assembleShader("fullscreen.vert", impl, {}),
                                                  assembleShader("probe.frag", impl, defines));
        }
        const ShaderProgram& program = own ? *own : generic;
        const dvec3 centre = c.scene.spheres[0].center;
        ProbeSpec spec("reintersect", "reintersect(o, d, w, mode)", 3);
        spec.needsScene = true;
        for (const dvec3& w : c.outgoing) {
            ProbeCase p;
            put(p, 0, glm::vec3(c.origin - centre));  // relative to the anchor, from double
            put(p, 4, glm::vec3(c.dir));
            put(p, 8, glm::vec3(w));
            p.in[11] = float(mode);
            spec.cases.push_back(p);
            if (mode == 2) break;  // one bounce per first hit
        }
        for (const auto& r : runProbe(program, spec, &c.scene)) {
            if (r[0] == 0.0f) {
                ++counts.firstMissed;
                continue;
            }
            ++counts.tested;
            char what[160];
            std::snprintf(what, sizeof what, "sphere %d (r %.3g), n.w %.3g, second hit sphere %d at t %.3g", k,
                          c.scene.spheres[0].radius, r[3], int(r[1]), r[2]);
            bool outward = r[3] > 0.0f || mode == 2;
            if (outward && r[1] == 0.0f) counts.fail(counts.selfHits, what);
            if (!outward && r[3] < -kInwardMargin && r[1] != 0.0f) counts.fail(counts.passThroughs, what);
        }
    }
    return counts;
}

TEST(Reintersect, GlslOffsetAloneNeverHitsItsOwnSurface) {
    Counts counts = glslCounts(acc::solutionsWith(), 0);
    std::printf("[ measured ] GLSL, 04's offset alone: %s\n", counts.summary().c_str());
    EXPECT_GT(counts.tested, 1000);
    EXPECT_EQ(counts.selfHits, 0) << counts.summary();
    EXPECT_EQ(counts.passThroughs, 0) << counts.summary();
}

TEST(Reintersect, GlslWithTheLeavingSphereAndTheBounce) {
    Counts leaving = glslCounts(acc::solutionsWith(), 1);
    std::printf("[ measured ] GLSL, offset and the sphere a ray leaves: %s\n", leaving.summary().c_str());
    EXPECT_EQ(leaving.selfHits, 0) << leaving.summary();
    EXPECT_EQ(leaving.passThroughs, 0) << leaving.summary();
    Counts bounce = glslCounts(acc::solutionsWith(), 2);
    std::printf("[ measured ] GLSL, the bounce of 09: %s\n", bounce.summary().c_str());
    EXPECT_EQ(bounce.selfHits, 0) << bounce.summary();
}

TEST(Reintersect, ThroughThePictureProgramsCodeForTheCourseAndAStudent) {
    for (const auto& [who, impl] : {std::pair<const char*, Implementation>{"the course's files", acc::solutionsWith()},
                                    {"a student's", acc::alternativesSubmission()}}) {
        Counts leaving = glslCounts(impl, 1, true);
        std::printf("[ measured ] GLSL, the picture program's code, %s, offset and leaving sphere: %s\n", who,
                    leaving.summary().c_str());
        EXPECT_GT(leaving.tested, 1000);
        EXPECT_EQ(leaving.selfHits, 0) << who << ": " << leaving.summary();
        EXPECT_EQ(leaving.passThroughs, 0) << who << ": " << leaving.summary();
        Counts bounce = glslCounts(impl, 2, true);
        EXPECT_EQ(bounce.selfHits, 0) << who << ": " << bounce.summary();
    }
}

TEST(Reintersect, SeenFailingWithAFixedEpsilonOffset) {
    // The yardstick can fail: exercise 04 with a fixed offset of 1e-3
    // (course/04-shadows/mutants/fixed-offset.glsl) leaves rays on huge
    // spheres inside the rounding of their hit point, and pushes them off
    // tiny ones by many radii.
    Implementation fixed = acc::solutionsWith({{"04-shadows.glsl", sourceRoot() / "course" / "04-shadows" / "mutants" / "fixed-offset.glsl"}});
    Counts counts = glslCounts(fixed, 0);
    std::printf("[ measured ] GLSL, a fixed 1e-3 offset: %s\n", counts.summary().c_str());
    EXPECT_GT(counts.selfHits + counts.passThroughs, 0) << counts.summary();
}

TEST(Reintersect, CpuReference) {
    Yardstick size;
    Counts offsetAlone, leaving;
    for (int k = 0; k < size.spheres; ++k) {
        SphereCase c = sphereCase(k, size.rays);
        ref::Hit hit;
        if (!ref::closestHit(c.scene, c.origin, c.dir, hit)) {
            ++offsetAlone.firstMissed;
            continue;
        }
        for (const dvec3& w : c.outgoing) {
            double nw = glm::dot(w, hit.n);
            char what[160];
            std::snprintf(what, sizeof what, "sphere %d (r %.3g), n.w %.3g", k, c.scene.spheres[0].radius, nw);
            ref::Hit next;
            bool found = ref::closestHit(c.scene, hit.p + hit.n * hit.error, w, next);
            ++offsetAlone.tested;
            if (nw > 0 && found) offsetAlone.fail(offsetAlone.selfHits, what);
            if (nw < -kInwardMargin && !found) offsetAlone.fail(offsetAlone.passThroughs, what);
            if (nw >= 0) {
                ++leaving.tested;
                if (ref::nextHit(c.scene, hit, w, next)) leaving.fail(leaving.selfHits, what);
            }
        }
    }
    std::printf("[ measured ] CPU reference, its offset alone: %s\n", offsetAlone.summary().c_str());
    std::printf("[ measured ] CPU reference, nextHit(): %s\n", leaving.summary().c_str());
    EXPECT_GT(offsetAlone.tested, 1000);
    EXPECT_EQ(offsetAlone.selfHits, 0) << offsetAlone.summary();
    EXPECT_EQ(offsetAlone.passThroughs, 0) << offsetAlone.summary();
    EXPECT_EQ(leaving.selfHits, 0) << leaving.summary();
}

}  // namespace
}  // namespace rl::meta
