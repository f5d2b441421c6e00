// Tests of the double-precision CPU reference (app/reference/). Each expected
// value is worked out by hand in the comment above it, from the spec
// (docs/model.md), or from a closed form of the physics;
// none is copied from a run of the code under test.
#include "reference/brdf_reference.h"
#include "reference/cpu_reference.h"

#include "core/error.h"
#include "core/scene_transform.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace {

using namespace rl;
using namespace rl::ref;
using glm::dvec2;
using glm::dvec3;

void expectVecNear(dvec3 got, dvec3 expected, double tolerance) {
    EXPECT_NEAR(got.x, expected.x, tolerance);
    EXPECT_NEAR(got.y, expected.y, tolerance);
    EXPECT_NEAR(got.z, expected.z, tolerance);
}

Material makeMaterial(dvec3 albedo, double roughness, double metallic, double ao = 1.0) {
    Material m;
    m.albedo = albedo;
    m.roughness = roughness;
    m.metallic = metallic;
    m.ao = ao;
    return m;
}

Sphere makeSphere(dvec3 center, double radius, const Material& material) {
    Sphere s;
    s.center = center;
    s.radius = radius;
    s.material = material;
    return s;
}

Light makeLight(dvec3 position, double intensity, dvec3 color = dvec3(1.0)) {
    Light l;
    l.position = position;
    l.color = color;
    l.intensity = intensity;
    return l;
}

// Every model variant of scene.h, one switch away from the reference each,
// plus two combinations of switches.
std::vector<ShadingModel> allModelVariants() {
    std::vector<ShadingModel> models(9);
    models[1].distribution = DistributionModel::Beckmann;
    models[2].geometry = GeometryModel::SmithGGXSeparable;
    models[3].geometry = GeometryModel::SmithGGXCorrelated;
    models[4].fresnel = FresnelModel::Dielectric;
    models[5].fresnel = FresnelModel::Conductor;
    models[6].diffuse = DiffuseModel::Burley;
    models[7].blinnPhong = true;
    models[8].distribution = DistributionModel::Beckmann;
    models[8].geometry = GeometryModel::SmithGGXCorrelated;
    models[8].fresnel = FresnelModel::Conductor;
    models[8].diffuse = DiffuseModel::Burley;
    return models;
}

// ---- 01 camera ---------------------------------------------------------------

TEST(SampleOffset, CellCentresOfTwoByTwo) {
    // n = 2: a = s % 2, b = s / 2, offset ((a + 0.5)/2, (b + 0.5)/2).
    EXPECT_EQ(sampleOffset(0, 2), dvec2(0.25, 0.25));
    EXPECT_EQ(sampleOffset(1, 2), dvec2(0.75, 0.25));
    EXPECT_EQ(sampleOffset(2, 2), dvec2(0.25, 0.75));
    EXPECT_EQ(sampleOffset(3, 2), dvec2(0.75, 0.75));
    // n = 1: the pixel centre.
    EXPECT_EQ(sampleOffset(0, 1), dvec2(0.5, 0.5));
}

TEST(CameraRay, CentreOfOddImageIsForward) {
    // 5 x 3 pixels, centre pixel (2, 1) sampled at 0.5: pixelSample = (2.5, 1.5),
    // 2 (2.5)/5 - 1 = 0 and 2 (1.5)/3 - 1 = 0, so x = y = 0 and d = normalize(forward).
    // A tilted basis, so that no component is trivially 0.
    dvec3 forward = glm::normalize(dvec3(1.0, 2.0, -3.0));
    dvec3 right = glm::normalize(glm::cross(forward, dvec3(0.0, 1.0, 0.0)));
    dvec3 up = glm::cross(right, forward);
    dvec3 d = cameraRayDirection(dvec2(2.5, 1.5), dvec2(5.0, 3.0), 1.0, right, up, forward);
    expectVecNear(d, forward, 1e-15);
}

TEST(CameraRay, TopRightCornerByHand) {
    // fov 90 deg: t = tan(45 deg) = 1; aspect = 5/3. pixelSample = (5, 3), the
    // top-right corner: x = (2*5/5 - 1) t aspect = 5/3, y = (2*3/3 - 1) t = 1.
    // right = +x, up = +y, forward = -z: d = normalize(5/3, 1, -1) = (5, 3, -3)/sqrt(43).
    dvec3 d = cameraRayDirection(dvec2(5.0, 3.0), dvec2(5.0, 3.0), kPi / 2.0, dvec3(1, 0, 0), dvec3(0, 1, 0),
                                 dvec3(0, 0, -1));
    expectVecNear(d, dvec3(5.0, 3.0, -3.0) / std::sqrt(43.0), 1e-15);
}

// ---- 02 ray/sphere -------------------------------------------------------------

TEST(IntersectSphere, FarUnitSphereHitsAtDistanceMinusRadius) {
    // Unit sphere 1e4 away along the ray: the near surface is at t = 1e4 - 1 = 9999.
    double t = intersectSphere(dvec3(0.0), dvec3(0, 0, -1), dvec3(0, 0, -1e4), 1.0);
    EXPECT_NEAR(t, 9999.0, 9999.0 * 1e-9);
}

TEST(IntersectSphere, TinyFarSphereHitOrMissByPerpendicularDistance) {
    // Radius 1e-6 at distance 1e6, the ray passing the centre at perpendicular
    // distance y0. The stable discriminant is r^2 - y0^2 exactly:
    //   y0 = 0.5e-6: 1e-12 - 0.25e-12 > 0, a hit at t = 1e6 - sqrt(0.75) 1e-6
    //   y0 = 1.5e-6: 1e-12 - 2.25e-12 < 0, a miss.
    // (b^2 - c = 1e12 - (1e12 + y0^2 - r^2) loses y0^2 - r^2 ~ 1e-12 against
    // 1e12 in double and calls both cases tangent hits.)
    double hit = intersectSphere(dvec3(0.0), dvec3(0, 0, -1), dvec3(0, 0.5e-6, -1e6), 1e-6);
    EXPECT_NEAR(hit, 1e6 - std::sqrt(0.75) * 1e-6, 1e6 * 1e-15);
    EXPECT_EQ(intersectSphere(dvec3(0.0), dvec3(0, 0, -1), dvec3(0, 1.5e-6, -1e6), 1e-6), kNoHit);
}

TEST(IntersectSphere, FromInsideReturnsTheFarRoot) {
    // Sphere of radius 2 at the origin, ray from (0,0,1): along +z the roots are
    // t = -3 (behind) and t = 1 (ahead); along -z they are -1 and 3.
    EXPECT_NEAR(intersectSphere(dvec3(0, 0, 1), dvec3(0, 0, 1), dvec3(0.0), 2.0), 1.0, 1e-15);
    EXPECT_NEAR(intersectSphere(dvec3(0, 0, 1), dvec3(0, 0, -1), dvec3(0.0), 2.0), 3.0, 1e-15);
}

TEST(IntersectSphere, SphereBehindTheOriginIsMissed) {
    // Centre (0,0,5), radius 1, ray along -z from the origin: roots t = -4 and -6.
    EXPECT_EQ(intersectSphere(dvec3(0.0), dvec3(0, 0, -1), dvec3(0, 0, 5), 1.0), kNoHit);
}

TEST(IntersectSphere, TangentRayTouchesOnce) {
    // Unit sphere at the origin, ray from (1,0,5) along -z: f = (1,0,5), b = -5,
    // f - b d = (1,0,0), disc = 1 - 1 = 0, q = 5, c = 26 - 1 = 25: both roots 25/5 = 5.
    EXPECT_EQ(intersectSphere(dvec3(1, 0, 5), dvec3(0, 0, -1), dvec3(0.0), 1.0), 5.0);
    // 1e-9 further out: disc = 1 - (1 + 1e-9)^2 < 0, a miss.
    EXPECT_EQ(intersectSphere(dvec3(1.0 + 1e-9, 0, 5), dvec3(0, 0, -1), dvec3(0.0), 1.0), kNoHit);
}

// ---- 03, 04 light and shadow rays ---------------------------------------------

TEST(PointLight, InverseSquareTimesCosine) {
    // Light at (0,3,4) above p = 0 with n = +z: d2 = 25, l = (0, 0.6, 0.8), NoL = 0.8.
    // E = C I / 25 * 0.8 with C I = (50, 25, 0): (1.6, 0.8, 0).
    dvec3 n(0, 0, 1);
    expectVecNear(pointLightIrradiance(dvec3(0.0), n, dvec3(0, 3, 4), dvec3(50, 25, 0)), dvec3(1.6, 0.8, 0.0),
                  1e-15);
    // Behind the surface (NoL < 0), and on p itself (d2 = 0 <= 1e-12): nothing.
    EXPECT_EQ(pointLightIrradiance(dvec3(0.0), n, dvec3(0, 3, -4), dvec3(50)), dvec3(0.0));
    EXPECT_EQ(pointLightIrradiance(dvec3(0.0), n, dvec3(0.0), dvec3(50)), dvec3(0.0));
    // Lambert: albedo / pi.
    expectVecNear(Fd_Lambert(dvec3(kPi, 0.5 * kPi, 0.0)), dvec3(1.0, 0.5, 0.0), 1e-15);
}

TEST(ShadowRay, OffsetIsTwoToTheMinus19OfTheMagnitude) {
    // 2^-19 = 1/524288; magnitude 4 pushes p by 4/524288 = 2^-17 along n (exact in binary).
    EXPECT_EQ(kRayOffsetRelative, std::ldexp(1.0, -19));
    EXPECT_EQ(offsetRayOrigin(dvec3(2, -4, 1), dvec3(0, 1, 0), 4.0), dvec3(2.0, -4.0 + std::ldexp(1.0, -17), 1.0));
}

TEST(ShadowRay, OnlyOccludersBeforeTheLightCount) {
    // Receiver: unit sphere at the origin, seen from (0,0,3) straight down: hit
    // at p = (0,0,1), n = +z. Blocker: unit sphere at (0,0,5), spanning z in [4, 6].
    Scene scene;
    scene.spheres.push_back(makeSphere(dvec3(0.0), 1.0, makeMaterial(dvec3(1.0), 1.0, 0.0)));
    scene.spheres.push_back(makeSphere(dvec3(0, 0, 5), 1.0, makeMaterial(dvec3(1.0), 1.0, 0.0)));
    Hit hit;
    ASSERT_TRUE(closestHit(scene, dvec3(0, 0, 3), dvec3(0, 0, -1), hit));
    EXPECT_EQ(hit.sphere, 0);
    expectVecNear(hit.p, dvec3(0, 0, 1), 1e-15);
    expectVecNear(hit.n, dvec3(0, 0, 1), 1e-15);
    EXPECT_EQ(hit.magnitude, 1.0);  // max(maxAbs(p) = 1, maxAbs(centre) + r = 1)

    // Light at z = 10, beyond the blocker: in shadow, no direct light.
    scene.lights = {makeLight(dvec3(0, 0, 10), 100.0)};
    EXPECT_FALSE(lightVisible(scene, hit, scene.lights[0].position));
    EXPECT_EQ(directLight(scene, hit, dvec3(0, 0, 1)), dvec3(0.0));

    // Light at z = 3, before the blocker: lit.
    scene.lights = {makeLight(dvec3(0, 0, 3), 100.0)};
    EXPECT_TRUE(lightVisible(scene, hit, scene.lights[0].position));
    EXPECT_GT(directLight(scene, hit, dvec3(0, 0, 1)).x, 0.0);
}

TEST(ClosestHit, NormalFacesTheRayFromInside) {
    // Camera inside a radius-2 sphere at the origin, looking along +x: the hit is
    // at (2,0,0), where (p - c)/r = +x points away from the ray origin; flipped: -x.
    Scene scene;
    scene.spheres.push_back(makeSphere(dvec3(0.0), 2.0, Material{}));
    Hit hit;
    ASSERT_TRUE(closestHit(scene, dvec3(0.0), dvec3(1, 0, 0), hit));
    EXPECT_EQ(hit.t, 2.0);
    expectVecNear(hit.n, dvec3(-1, 0, 0), 1e-15);
    EXPECT_FALSE(closestHit(scene, dvec3(0, 0, 5), dvec3(0, 0, 1), hit));  // pointing away: miss
}

TEST(NextHit, LeavingTheOutsideNeverMeetsTheSameSphere) {
    // A sphere is convex: a ray leaving its outside (dir.n >= 0) cannot hit
    // it again, however p rounds. From (0,0,3) down -z onto the unit sphere:
    // p = (0,0,1); every direction of the upper hemisphere around n = +z,
    // down to grazing (n.d = 1e-12), misses: no offset hides anything.
    Scene scene;
    scene.spheres.push_back(makeSphere(dvec3(0.0), 1.0, Material{}));
    Hit hit;
    ASSERT_TRUE(closestHit(scene, dvec3(0, 0, 3), dvec3(0, 0, -1), hit));
    EXPECT_FALSE(hit.inside);
    for (double z : {1.0, 0.5, 1e-6, 1e-12}) {
        Hit next;
        EXPECT_FALSE(nextHit(scene, hit, glm::normalize(dvec3(1, 0.3, z)), next)) << z;
    }
}

TEST(NextHit, LeavingTheInsideMeetsTheFarRoot) {
    // From inside the radius-2 sphere at the origin: the ray from the centre
    // along +x hits (2,0,0) from inside, n = -x. Reflected back along -x, it
    // meets the sphere again at (-2,0,0): t = -2 (p - c).d = 4, from inside.
    Scene scene;
    scene.spheres.push_back(makeSphere(dvec3(0.0), 2.0, Material{}));
    Hit hit;
    ASSERT_TRUE(closestHit(scene, dvec3(0.0), dvec3(1, 0, 0), hit));
    EXPECT_TRUE(hit.inside);
    Hit next;
    ASSERT_TRUE(nextHit(scene, hit, dvec3(-1, 0, 0), next));
    EXPECT_EQ(next.sphere, 0);
    EXPECT_TRUE(next.inside);
    EXPECT_EQ(next.t, 4.0);
    expectVecNear(next.p, dvec3(-2, 0, 0), 1e-15);
    expectVecNear(next.n, dvec3(1, 0, 0), 1e-15);
}

TEST(NextHit, HitPointIsOnTheSphereWhateverTheRayOrigin) {
    // Seen from 3000 away, p = origin + t d carries 3000 x 1e-16 of rounding;
    // reprojected, p lies on the unit sphere to a few 1e-16, and Hit::error
    // bounds its distance from the surface by 2^-48 (|c| + r).
    Scene scene;
    scene.spheres.push_back(makeSphere(dvec3(0.0), 1.0, Material{}));
    Hit hit;
    dvec3 eye(1800, 7, 2400);
    ASSERT_TRUE(closestHit(scene, eye, glm::normalize(dvec3(0.1, 0.3, 0.2) - eye), hit));
    EXPECT_NEAR(glm::length(hit.p), 1.0, 4e-16);
    EXPECT_NEAR(glm::length(hit.n), 1.0, 4e-16);
    EXPECT_EQ(hit.error, std::ldexp(1.0, -48));
    EXPECT_LE(std::abs(glm::length(hit.p) - 1.0), hit.error);
}

TEST(NextHit, CoincidentSpheresDoNotShadowEachOther) {
    // Two identical spheres (the first wins the hit), and a copy whose centre
    // rounded 2 ulps away (4.4e-16, as a transformed copy's may): their
    // surfaces pass through p, up to rounding. The identical one is handled
    // exactly, like the sphere the ray leaves; the near copy is kept off by
    // the rounding-sized push along n (Hit::error = 3.6e-15 here), so a ray
    // leaving the outside does not meet it at t = 1e-16.
    Scene scene;
    scene.spheres.push_back(makeSphere(dvec3(0.3, -0.2, 0.1), 0.7, Material{}));
    scene.spheres.push_back(scene.spheres[0]);
    scene.spheres.push_back(makeSphere(dvec3(0.3 + 2 * std::ldexp(1.0, -54), -0.2, 0.1), 0.7, Material{}));
    scene.lights = {makeLight(dvec3(0.3, 5, 0.1), 10)};
    for (double x : {-0.3, -0.1, 0.0, 0.37, 0.6, 0.9}) {
        Hit hit;
        ASSERT_TRUE(closestHit(scene, dvec3(x, 4, 0.3), dvec3(0, -1, 0), hit));
        EXPECT_EQ(hit.sphere, 0);
        EXPECT_TRUE(lightReachable(scene, hit, scene.lights[0].position)) << x;
        Hit next;
        EXPECT_FALSE(nextHit(scene, hit, glm::normalize(dvec3(0.2, 1, 0.1)), next)) << x;
    }
}

TEST(ShadowRay, LightInsideTheSphereOfTheHitOnlyLightsItsInside) {
    // A light at the centre of a hollow radius-3 sphere: its inner surface is
    // lit, the far root lies beyond the light; a light outside it is cut off
    // by the wall the shadow ray crosses.
    Scene scene;
    scene.spheres.push_back(makeSphere(dvec3(0.0), 3.0, Material{}));
    Hit hit;
    ASSERT_TRUE(closestHit(scene, dvec3(0.0), dvec3(0, -1, 0), hit));
    ASSERT_TRUE(hit.inside);
    EXPECT_TRUE(lightReachable(scene, hit, dvec3(0.0)));
    EXPECT_TRUE(lightReachable(scene, hit, dvec3(0, 2.9, 0)));
    EXPECT_FALSE(lightReachable(scene, hit, dvec3(0, 3.1, 0)));
}

TEST(CpuRender, ClosedMirrorSphereStaysBlack) {
    // Inside a closed mirror sphere with no light, no ambient and 16 bounces
    // every path ends inside after its 17th hit: the answer is exactly black.
    // (Before the exact handling of the sphere a ray leaves, the origin
    // drifted out after about 11 bounces and 58% of the pixels showed the
    // white background.)
    Scene scene;
    scene.camera.position = dvec3(0.2, 0.1, 0.3);
    scene.camera.target = dvec3(0, 0, -1);
    scene.render.width = 48;
    scene.render.height = 36;
    scene.render.maxBounces = 16;
    scene.render.ambient = 0.0;
    scene.render.background = dvec3(1.0);
    scene.spheres.push_back(makeSphere(dvec3(0.0), 1.0, makeMaterial(dvec3(0.98), 0.045, 1.0)));
    for (double s : {1.0, 1e-3, 1e3}) {
        Scene sized = scaledScene(scene, s);
        Rendering out = renderCpu(sized);
        long lit = 0;
        for (float v : out.radiance.rgb) lit += v != 0.0f;
        EXPECT_EQ(lit, 0) << "scale " << s;
    }
}

// ---- 05 D ----------------------------------------------------------------------

TEST(NormalDistribution, PeakIsOneOverPiAlphaSquared) {
    // At h = n: |n x h| = 0, NoH = 1, D = alpha^2 / (pi (alpha^2)^2) = 1 / (pi alpha^2).
    // Beckmann at h = n: exp(0) / (pi alpha^2 1^4) = 1 / (pi alpha^2) too.
    dvec3 n = glm::normalize(dvec3(1, -2, 2));
    for (double alpha : {0.045 * 0.045, 0.1, 0.5, 1.0}) {
        double peak = 1.0 / (kPi * alpha * alpha);
        EXPECT_NEAR(D_GGX(n, n, alpha), peak, peak * 1e-14) << "alpha " << alpha;
        EXPECT_NEAR(D_Beckmann(n, n, alpha), peak, peak * 1e-14) << "alpha " << alpha;
    }
}

// Integral of D NoH over the hemisphere, by the midpoint rule in theta:
// dw = 2 pi sin(theta) dtheta, h = (sin theta, 0, cos theta) around n = +z.
// Steps of 6e-6 rad: over 300 per lobe width even at alpha = 0.002.
template <class Distribution>
double projectedArea(Distribution D, double alpha) {
    const int steps = 1 << 18;
    const double dTheta = 0.5 * kPi / steps;
    const dvec3 n(0, 0, 1);
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        double theta = (i + 0.5) * dTheta;
        dvec3 h(std::sin(theta), 0.0, std::cos(theta));
        sum += D(n, h, alpha) * h.z * 2.0 * kPi * std::sin(theta) * dTheta;
    }
    return sum;
}

TEST(NormalDistribution, ProjectedAreaIsOne) {
    // GGX, with x = NoH^2 (dx = 2 NoH dNoH):
    //   int D NoH dw = 2 pi int_0^1 D NoH dNoH = alpha^2 int_0^1 dx / (1 + x (alpha^2 - 1))^2
    //                = alpha^2 [-1 / ((alpha^2 - 1)(1 + x (alpha^2 - 1)))]_0^1
    //                = alpha^2 (1 - 1/alpha^2) / (alpha^2 - 1) = alpha^2 / alpha^2 = 1.
    // Beckmann, with u = tan^2 theta (du = 2 tan / cos^2 dtheta):
    //   int D NoH dw = int_0^inf exp(-u/alpha^2) / alpha^2 du = 1.
    for (double alpha : {0.045 * 0.045, 0.01, 0.1, 0.5, 1.0}) {
        EXPECT_NEAR(projectedArea(D_GGX, alpha), 1.0, 1e-6) << "GGX alpha " << alpha;
        EXPECT_NEAR(projectedArea(D_Beckmann, alpha), 1.0, 1e-6) << "Beckmann alpha " << alpha;
    }
}

// ---- 06 G ----------------------------------------------------------------------

TEST(Geometry, IsOneAtNormalIncidence) {
    // NoV = NoL = 1: Schlick G1(1) = 1 / (1 (1 - k) + k) = 1;
    // Smith G1(1) = 2 / (1 + sqrt(alpha^2 + 1 - alpha^2)) = 1;
    // correlated 2 / (1 sqrt(1) + 1 sqrt(1)) = 1.
    for (double r : {0.0, 0.045, 0.5, 1.0}) {
        double alpha = ggxAlpha(r);
        EXPECT_NEAR(G_SchlickGGX(1.0, 1.0, r), 1.0, 1e-15) << "r " << r;
        EXPECT_NEAR(G_SmithGGXSeparable(1.0, 1.0, alpha), 1.0, 1e-15) << "r " << r;
        EXPECT_NEAR(G_SmithGGXCorrelated(1.0, 1.0, alpha), 1.0, 1e-15) << "r " << r;
    }
}

TEST(Geometry, SchlickGGXByHand) {
    // r = 0.5: k = 1.5^2 / 8 = 0.28125; G1(0.5) = 0.5 / (0.5 * 0.71875 + 0.28125)
    // = 0.5 / 0.640625 = 32/41; G(0.5, 1) = 32/41 * 1.
    EXPECT_NEAR(G1_SchlickGGX(0.5, 0.28125), 32.0 / 41.0, 1e-15);
    EXPECT_NEAR(G_SchlickGGX(0.5, 1.0, 0.5), 32.0 / 41.0, 1e-15);
    // Roughness is clamped to 0.045 first: r = 0 gives k = 1.045^2 / 8.
    double k = 1.045 * 1.045 / 8.0;
    EXPECT_NEAR(G_SchlickGGX(0.5, 0.5, 0.0), std::pow(0.5 / (0.5 * (1 - k) + k), 2.0), 1e-15);
}

// ---- 07 F ----------------------------------------------------------------------

TEST(Fresnel, SchlickEndpoints) {
    // F0 + (1 - F0)(1 - VoH)^5: VoH = 1 gives F0, VoH = 0 gives 1, VoH = 0.5 gives
    // F0 + (1 - F0)/32. VoH is clamped to [0, 1].
    dvec3 F0(0.04, 0.5, 1.0);
    expectVecNear(F_Schlick(F0, 1.0), F0, 1e-15);
    expectVecNear(F_Schlick(F0, 0.0), dvec3(1.0), 1e-15);
    expectVecNear(F_Schlick(F0, 0.5), F0 + (1.0 - F0) / 32.0, 1e-15);
    expectVecNear(F_Schlick(F0, -0.3), dvec3(1.0), 1e-15);
    expectVecNear(F_Schlick(F0, 1.7), F0, 1e-15);
}

TEST(Fresnel, ExactFresnelEndpoints) {
    // The indices derived from F0 reflect exactly F0 at normal incidence, and
    // every interface reflects everything at grazing incidence.
    dvec3 F0(0.04, 0.5, 0.9);
    dvec3 edgeTint(0.2, 0.5, 1.0);
    expectVecNear(F_Dielectric(F0, 1.0), F0, 1e-12);
    expectVecNear(F_Dielectric(F0, 0.0), dvec3(1.0), 1e-12);
    expectVecNear(F_Conductor(F0, edgeTint, 1.0), F0, 1e-12);
    expectVecNear(F_Conductor(F0, edgeTint, 0.0), dvec3(1.0), 1e-12);
    // A perfect mirror stays one at every angle (F0 = 1 is held at 1 - 1e-9).
    for (double c : {0.0, 0.3, 1.0}) {
        expectVecNear(F_Dielectric(dvec3(1.0), c), dvec3(1.0), 1e-8);
        expectVecNear(F_Conductor(dvec3(1.0), edgeTint, c), dvec3(1.0), 1e-8);
    }
}

TEST(Fresnel, DielectricMatchesSnellAndFresnelAt45Degrees) {
    // F0 = 0.04 is glass, n = (1 + 0.2)/(1 - 0.2) = 1.5. At 45 deg, Snell:
    // sin t = sin 45 / 1.5, and the s and p amplitude coefficients
    //   rs = (cos i - n cos t)/(cos i + n cos t),  rp = (n cos i - cos t)/(n cos i + cos t)
    // give F = (rs^2 + rp^2)/2 = (0.092013 + 0.008466)/2 = 0.050240.
    double ci = std::sqrt(0.5);
    double st = ci / 1.5;
    double ct = std::sqrt(1.0 - st * st);
    double rs = (ci - 1.5 * ct) / (ci + 1.5 * ct);
    double rp = (1.5 * ci - ct) / (1.5 * ci + ct);
    double expected = 0.5 * (rs * rs + rp * rp);
    EXPECT_NEAR(expected, 0.050240, 1e-6);
    EXPECT_NEAR(F_Dielectric(dvec3(0.04), ci).x, expected, 1e-14);
}

TEST(Fresnel, ConductorWithoutAbsorptionIsTheDielectric) {
    // Edge tint g = 0 gives n = (1 + sqrt r)/(1 - sqrt r), and then
    // r (n + 1)^2 = 4 r / (1 - sqrt r)^2 = (n - 1)^2, so k = 0: the conductor
    // equations must reduce to the dielectric ones (two independent formulas).
    dvec3 F0(0.04, 0.3, 0.8);
    for (double c : {0.05, 0.3, 0.7, 1.0}) {
        expectVecNear(F_Conductor(F0, dvec3(0.0), c), F_Dielectric(F0, c), 1e-9);
    }
}

TEST(Fresnel, SchlickRoughnessByHand) {
    // Fr = F0 + (max(1 - r, F0) - F0)(1 - NoV)^5.
    // r = 1: max(0, F0) = F0, so Fr = F0 at every angle.
    dvec3 F0(0.04, 0.5, 1.0);
    expectVecNear(F_SchlickRoughness(F0, 0.0, 1.0), F0, 1e-15);
    // r = 0 clamps to 0.045; at NoV = 0: max(0.955, F0) = (0.955, 0.955, 1).
    expectVecNear(F_SchlickRoughness(F0, 0.0, 0.0), dvec3(0.955, 0.955, 1.0), 1e-15);
    // NoV = 1: F0.
    expectVecNear(F_SchlickRoughness(F0, 1.0, 0.3), F0, 1e-15);
}

// ---- diffuse and Blinn-Phong variants ----------------------------------------------

TEST(Variants, BurleyAndBlinnPhongByHand) {
    // Burley at NoV = NoL = 1: both (1 - x)^5 vanish, f = albedo / pi for any F90.
    expectVecNear(Fd_Burley(dvec3(1.0), 1.0, 1.0, 0.3, 0.7), dvec3(1.0 / kPi), 1e-15);
    // At NoV = NoL = 0, LoH = 1, alpha = 1: F90 = 0.5 + 2 = 2.5, f = 2.5^2 / pi.
    expectVecNear(Fd_Burley(dvec3(1.0), 0.0, 0.0, 1.0, 1.0), dvec3(6.25 / kPi), 1e-14);
    // s = 2/alpha^2 - 2: alpha = 1 gives 0, alpha = 0.5 gives 6.
    EXPECT_EQ(shininessFromAlpha(1.0), 0.0);
    EXPECT_EQ(shininessFromAlpha(0.5), 6.0);
    // s = 0: (2)(4) / (8 pi (1 + 0)) NoH^0 = 1/pi, Lambert's white.
    EXPECT_NEAR(Fr_BlinnPhong(0.3, 0.0), 1.0 / kPi, 1e-15);
    // s = 2: (4)(6) / (8 pi (0.5 + 2)) = 24 / (20 pi) = 1.2 / pi, at NoH = 0.5: 0.3 / pi.
    EXPECT_NEAR(Fr_BlinnPhong(0.5, 2.0), 0.3 / kPi, 1e-15);
}

TEST(Variants, BurleyUsesAlphaLikeFilament) {
    // White dielectric, r = 0.5 (alpha = 0.25), v = l at 60 deg from n: h = v, so
    // VoH = LoH = 1 and F = F0 = 0.04, kd = 0.96. F90 = 0.5 + 2 alpha 1^2 = 1, so
    // both scatter factors are 1 and f = 0.96/pi. (Burley's r in place of alpha
    // would give F90 = 1.5 and (1 + 0.5/32)^2 = 1.0315 times more.)
    ShadingModel burley;
    burley.diffuse = DiffuseModel::Burley;
    dvec3 n(0, 0, 1), v(std::sqrt(0.75), 0.0, 0.5);
    expectVecNear(diffuseBRDF(n, v, v, makeMaterial(dvec3(1.0), 0.5, 0.0), burley), dvec3(0.96 / kPi), 1e-15);
}

TEST(Variants, EachSwitchSelectsItsTerm) {
    // The table of brdf_reference.h, term by term, for every combination of
    // switches: specular D G F / (4 NoL NoV), diffuse (1 - F)(1 - metallic) Fd.
    dvec3 n = glm::normalize(dvec3(0.1, 0.2, 1.0));
    dvec3 v = glm::normalize(dvec3(-0.5, 0.3, 0.8));
    dvec3 l = glm::normalize(dvec3(0.6, -0.1, 0.7));
    Material m = makeMaterial(dvec3(0.9, 0.6, 0.2), 0.35, 0.7);
    m.edgeTint = dvec3(0.3, 0.6, 0.9);
    double r = 0.35, alpha = r * r;
    dvec3 h = glm::normalize(l + v);
    double NoV = glm::dot(n, v), NoL = glm::dot(n, l), VoH = glm::dot(v, h);
    dvec3 F0 = baseReflectance(m);
    for (DistributionModel distribution : {DistributionModel::GGX, DistributionModel::Beckmann})
        for (GeometryModel geometry :
             {GeometryModel::SchlickGGX, GeometryModel::SmithGGXSeparable, GeometryModel::SmithGGXCorrelated})
            for (FresnelModel fresnel : {FresnelModel::Schlick, FresnelModel::Dielectric, FresnelModel::Conductor})
                for (DiffuseModel diffuse : {DiffuseModel::Lambert, DiffuseModel::Burley}) {
                    ShadingModel model;
                    model.distribution = distribution;
                    model.geometry = geometry;
                    model.fresnel = fresnel;
                    model.diffuse = diffuse;
                    double D = distribution == DistributionModel::GGX ? D_GGX(n, h, alpha) : D_Beckmann(n, h, alpha);
                    double G = geometry == GeometryModel::SchlickGGX          ? G_SchlickGGX(NoV, NoL, r)
                               : geometry == GeometryModel::SmithGGXSeparable ? G_SmithGGXSeparable(NoV, NoL, alpha)
                                                                               : G_SmithGGXCorrelated(NoV, NoL, alpha);
                    dvec3 F = fresnel == FresnelModel::Schlick      ? F_Schlick(F0, VoH)
                              : fresnel == FresnelModel::Dielectric ? F_Dielectric(F0, VoH)
                                                                    : F_Conductor(F0, m.edgeTint, VoH);
                    dvec3 Fd = diffuse == DiffuseModel::Lambert ? Fd_Lambert(m.albedo)
                                                                : Fd_Burley(m.albedo, NoV, NoL, VoH, alpha);
                    dvec3 expected = (1.0 - F) * (1.0 - m.metallic) * Fd + D * G * F / (4.0 * NoL * NoV);
                    SCOPED_TRACE(int(distribution) * 100 + int(geometry) * 10 + int(fresnel) + 1000 * int(diffuse));
                    expectVecNear(cookTorranceBRDF(n, v, l, m, model), expected, 1e-13);
                }
    // Blinn-Phong replaces the whole model, whatever the other switches say:
    // (1 - F0)(1 - metallic) albedo/pi + F0 Fr_BlinnPhong(NoH, 2/alpha^2 - 2).
    ShadingModel blinnPhong;
    blinnPhong.blinnPhong = true;
    blinnPhong.distribution = DistributionModel::Beckmann;
    blinnPhong.fresnel = FresnelModel::Conductor;
    dvec3 expected = (1.0 - F0) * (1.0 - m.metallic) * m.albedo / kPi +
                     F0 * Fr_BlinnPhong(glm::dot(n, h), 2.0 / (alpha * alpha) - 2.0);
    expectVecNear(cookTorranceBRDF(n, v, l, m, blinnPhong), expected, 1e-13);
    expectVecNear(blinnPhongBRDF(n, v, l, m), expected, 1e-13);
}

// ---- 08 Cook-Torrance --------------------------------------------------------------

TEST(CookTorrance, WhiteDielectricAtNormalIncidenceByHand) {
    // n = v = l, white, r = 1 (alpha = 1), metallic 0: F = F0 = 0.04, D = 1/pi,
    // G = 1, specular = D G F / 4 = 0.01/pi; kd = 0.96, diffuse = 0.96/pi.
    // f = 0.97 / pi.
    dvec3 n(0, 0, 1);
    Material m = makeMaterial(dvec3(1.0), 1.0, 0.0);
    expectVecNear(cookTorranceBRDF(n, n, n, m), dvec3(0.97 / kPi), 1e-15);
    expectVecNear(specularBRDF(n, n, n, m), dvec3(0.01 / kPi), 1e-15);
    expectVecNear(diffuseBRDF(n, n, n, m), dvec3(0.96 / kPi), 1e-15);
}

TEST(CookTorrance, MatchesTheSpecFormulaWrittenOut) {
    // The spec's lines, literally (D in its (n.h)^2 (alpha^2 - 1) + 1 form), at
    // a generic configuration with a coloured, half-metallic material.
    dvec3 n = glm::normalize(dvec3(0.1, 0.2, 1.0));
    dvec3 v = glm::normalize(dvec3(-0.5, 0.3, 0.8));
    dvec3 l = glm::normalize(dvec3(0.6, -0.1, 0.7));
    Material m = makeMaterial(dvec3(0.9, 0.6, 0.2), 0.35, 0.4);

    double r = 0.35, alpha = r * r;
    dvec3 F0 = dvec3(0.04) * (1.0 - 0.4) + m.albedo * 0.4;
    double NdotV = glm::dot(n, v), NdotL = glm::dot(n, l);  // both inside (1e-4, 1)
    dvec3 h = glm::normalize(l + v);
    double NdotH = glm::dot(n, h);
    double D = alpha * alpha / (kPi * std::pow(NdotH * NdotH * (alpha * alpha - 1.0) + 1.0, 2.0));
    double k = (r + 1.0) * (r + 1.0) / 8.0;
    double G = NdotV / (NdotV * (1 - k) + k) * NdotL / (NdotL * (1 - k) + k);
    dvec3 F = F0 + (1.0 - F0) * std::pow(1.0 - glm::dot(h, v), 5.0);
    dvec3 kd = (1.0 - F) * (1.0 - 0.4);
    dvec3 expected = kd * m.albedo / kPi + D * G * F / (4.0 * NdotL * NdotV);
    expectVecNear(cookTorranceBRDF(n, v, l, m), expected, 1e-13);
    // The default ShadingModel is the reference.
    expectVecNear(cookTorranceBRDF(n, v, l, m, ShadingModel{}), expected, 1e-13);
}

TEST(CookTorrance, NothingFromBelowTheHorizon) {
    // NoL = clamp(n.l, 0, 1) = 0: every model returns 0.
    dvec3 n(0, 0, 1), v = glm::normalize(dvec3(0.3, 0, 1)), l = glm::normalize(dvec3(-0.3, 0.2, -0.1));
    for (const ShadingModel& model : allModelVariants())
        EXPECT_EQ(cookTorranceBRDF(n, v, l, makeMaterial(dvec3(0.8), 0.5, 0.3), model), dvec3(0.0));
}

TEST(CookTorrance, ReciprocityForEveryVariant) {
    // Helmholtz reciprocity f(l, v) = f(v, l): every term depends on l and v
    // symmetrically (VoH = LoH, and G, D, Burley are symmetric in NoV, NoL),
    // as long as both cosines are above the 1e-4 clamp.
    dvec3 n = glm::normalize(dvec3(0.2, -0.1, 1.0));
    const dvec3 directions[] = {glm::normalize(dvec3(0.5, 0.1, 0.8)), glm::normalize(dvec3(-0.7, 0.4, 0.3)),
                                glm::normalize(dvec3(0.05, -0.9, 0.45)), n};
    const Material materials[] = {makeMaterial(dvec3(0.9, 0.5, 0.1), 0.045, 1.0),
                                  makeMaterial(dvec3(0.2, 0.7, 0.4), 0.4, 0.0),
                                  makeMaterial(dvec3(1.0), 1.0, 0.5)};
    for (const ShadingModel& model : allModelVariants())
        for (const Material& m : materials)
            for (dvec3 a : directions)
                for (dvec3 b : directions) {
                    dvec3 fab = cookTorranceBRDF(n, a, b, m, model);
                    dvec3 fba = cookTorranceBRDF(n, b, a, m, model);
                    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fab[c], fba[c], 1e-12 * std::max(1.0, fab[c]));
                }
}

// ---- energy ------------------------------------------------------------------------------

// The quadrature of directionalAlbedo() at 128 x 128 cells per lobe is exact
// to ~1e-3 where the lobe is cut by the horizon (O(1/N) error of a step in
// the integrand; measured 1.0e-3 at 128, 6e-4 at 256), and to 1e-6 elsewhere.
constexpr int kAlbedoSamples = 128;
constexpr double kAlbedoQuadratureError = 2e-3;

TEST(Energy, DirectionalAlbedoNeverExceedsOne) {
    // A passive surface reflects at most what it receives: int f NoL dl <= 1,
    // for every view angle, roughness and F0 (including the perfect F0 = 1),
    // for metals (metallic = 1: the specular lobe alone) and for every variant.
    const dvec3 F0s[] = {dvec3(1.0), dvec3(0.5), dvec3(1.0, 0.78, 0.34)};
    for (const ShadingModel& model : allModelVariants())
        for (dvec3 F0 : F0s)
            for (double NoV : {0.02, 0.1, 0.3, 0.6, 0.9, 1.0})
                for (double roughness : {0.045, 0.1, 0.3, 0.6, 1.0}) {
                    dvec3 albedo = directionalAlbedo(NoV, roughness, F0, 1.0, model, kAlbedoSamples);
                    for (int c = 0; c < 3; ++c)
                        EXPECT_LE(albedo[c], 1.0 + kAlbedoQuadratureError)
                            << "NoV " << NoV << " roughness " << roughness << " F0 " << F0[c] << " model "
                            << int(model.distribution) << int(model.geometry) << int(model.fresnel)
                            << int(model.diffuse) << model.blinnPhong;
                }
}

TEST(Energy, ClosedFormsOfTheAlbedo) {
    ShadingModel smith;
    smith.geometry = GeometryModel::SmithGGXCorrelated;
    ShadingModel blinnPhong;
    blinnPhong.blinnPhong = true;
    for (double roughness : {0.045, 0.3, 1.0}) {
        // Blinn-Phong's normalisation is exact at NoV = 1: a white mirror lobe
        // (F0 = 1) reflects everything, int (s+2)(s+4)/(8 pi (2^(-s/2) + s)) NoH^s NoL dl = 1.
        EXPECT_NEAR(directionalAlbedo(1.0, roughness, dvec3(1.0), 1.0, blinnPhong, kAlbedoSamples).x, 1.0,
                    kAlbedoQuadratureError)
            << roughness;
        // White dielectric Blinn-Phong at NoV = 1: diffuse (1 - 0.04) + specular 0.04 * 1 = 1.
        EXPECT_NEAR(directionalAlbedo(1.0, makeMaterial(dvec3(1.0), roughness, 0.0), blinnPhong, kAlbedoSamples).x,
                    1.0, kAlbedoQuadratureError)
            << roughness;
    }
    // A near-mirror (r = 0.045, alpha = 0.002) with exact Smith G and F0 = 1 seen
    // head-on reflects everything: G = 1 on the whole (tiny) lobe. This shows the
    // quadrature resolves a lobe 0.002 rad wide.
    EXPECT_NEAR(directionalAlbedo(1.0, 0.045, dvec3(1.0), 1.0, smith, kAlbedoSamples).x, 1.0, 1e-6);
}

// ---- display -----------------------------------------------------------------------------

TEST(Display, ToneMapAndGammaByHand) {
    // reinhard(1) = 1/2; exponential(ln 2) = 1 - 1/2; none clamps 1.7 to 1.
    expectVecNear(toneMap(dvec3(1.0), ToneMap::Reinhard), dvec3(0.5), 1e-15);
    expectVecNear(toneMap(dvec3(std::log(2.0)), ToneMap::Exponential), dvec3(0.5), 1e-15);
    expectVecNear(toneMap(dvec3(1.7, 0.3, 0.0), ToneMap::None), dvec3(1.0, 0.3, 0.0), 1e-15);
    // gamma 2: 0.25^(1/2) = 0.5.
    expectVecNear(encodeGamma(dvec3(0.25), 2.0, false), dvec3(0.5), 1e-15);
    // sRGB: linear part 12.92 * 0.0031308 = 0.040449936; 1 -> 1.055 - 0.055 = 1;
    // 0.5 -> 1.055 * 0.5^(1/2.4) - 0.055 = 1.055 * 0.7491535 - 0.055 = 0.7353570.
    expectVecNear(encodeGamma(dvec3(0.0031308, 1.0, 0.5), 0.0, true), dvec3(0.040449936, 1.0, 0.7353570), 1e-7);
    // Display step: exposure 2 * 0.5 = 1, reinhard 0.5, gamma 2.2: 0.5^(1/2.2) = 0.7297400.
    RenderSettings settings;
    settings.exposure = 2.0;
    expectVecNear(displayEncode(dvec3(0.5), settings), dvec3(0.7297400), 1e-7);
}

// ---- whole pictures ------------------------------------------------------------------------

// The scene of the hand-computed picture below.
Scene headOnWhiteSphere() {
    Scene scene;
    scene.camera.position = dvec3(0.0);
    scene.camera.target = dvec3(0, 0, -1);
    scene.camera.fovYDegrees = 60.0;
    scene.render.width = 3;
    scene.render.height = 3;
    scene.render.ambient = 0.02;
    scene.render.background = dvec3(0.25);
    scene.spheres.push_back(makeSphere(dvec3(0, 0, -3), 1.0, makeMaterial(dvec3(1.0), 1.0, 0.0)));
    scene.lights.push_back(makeLight(dvec3(0, 0, 1), 9.0 * kPi));  // behind the camera
    return scene;
}

TEST(CpuRender, WhiteSphereHeadOnByHand) {
    // Centre pixel (1, 1): ray -z hits p = (0,0,-2), n = v = l = +z.
    //   light: d2 = 3^2 = 9, E = 9 pi / 9 * 1 = pi; f = 0.97/pi (see
    //   WhiteDielectricAtNormalIncidenceByHand): direct = 0.97
    //   ambient 0.02 * 1 * 1 = 0.02
    //   bounce: throughput F_SchlickRoughness(0.04, 1, r = 1) = 0.04, the
    //   reflected ray (+z) leaves: 0.04 * background 0.25 = 0.01
    //   L = 0.97 + 0.02 + 0.01 = 1.00; reinhard 1/2; 0.5^(1/2.2) = 0.72974;
    //   255 * 0.72974 = 186.08 -> 186.
    // Every other pixel misses: the sphere subtends asin(1/3) = 19.47 deg, the
    // nearest other pixel centre is atan((2/3) tan 30 deg) = 21.05 deg off axis.
    //   L = 0.25; reinhard 0.2; 0.2^(1/2.2) = 0.481157; 255 * 0.481157 = 122.70 -> 123.
    Rendering out = renderCpu(headOnWhiteSphere());
    ASSERT_EQ(out.display.width, 3);
    ASSERT_EQ(out.display.height, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) {
            bool centre = (x == 1 && y == 1);
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(out.display.at(x, y)[c], centre ? 186 : 123) << x << "," << y;
                EXPECT_NEAR(out.radiance.at(x, y)[c], centre ? 1.0 : 0.25, 1e-6) << x << "," << y;
            }
        }
}

TEST(CpuRender, RowZeroIsTheTop) {
    // A 1 x 3 image, fov 60: the top pixel (j = 2 from the bottom) looks along
    // (0, (2*2.5/3 - 1) tan 30, -1) = (0, 0.385, -1) and meets z = -3 at y = 1.155,
    // inside the sphere at (0, 1.5, -3) of radius 0.5; the bottom pixel looks down
    // and sees the black background. Row 0 of the image must be the top.
    Scene scene;
    scene.render.width = 1;
    scene.render.height = 3;
    scene.render.ambient = 1.0;
    scene.spheres.push_back(makeSphere(dvec3(0, 1.5, -3), 0.5, makeMaterial(dvec3(1.0), 1.0, 0.0)));
    Rendering out = renderCpu(scene);
    EXPECT_GT(out.display.at(0, 0)[0], 0);
    EXPECT_EQ(out.display.at(0, 2)[0], 0);
}

TEST(CpuRender, SamplesAreAveragedOverTheFourCellCentres) {
    // spp = 4 on the head-on scene: sample offsets (0.25|0.75, 0.25|0.75). For the
    // centre pixel the samples sit at ndc = 2 (1.25)/3 - 1 = -1/6 (or +1/6) on each
    // axis, atan(1/6 tan 30 deg sqrt 2) = 7.7 deg off axis: all four still hit the
    // sphere (19.5 deg), and the pixel is the mean of the four traceRadiance calls.
    Scene scene = headOnWhiteSphere();
    scene.render.spp = 4;
    CameraBasis camera = cameraBasis(scene.camera);
    dvec3 sum(0.0);
    for (dvec2 offset : {dvec2(0.25, 0.25), dvec2(0.75, 0.25), dvec2(0.25, 0.75), dvec2(0.75, 0.75)}) {
        dvec3 d = cameraRayDirection(dvec2(1.0) + offset, dvec2(3.0), kPi / 3.0, camera.right, camera.up,
                                     camera.forward);
        sum += traceRadiance(scene, camera.position, d);
    }
    Rendering out = renderCpu(scene);
    EXPECT_NEAR(out.radiance.at(1, 1)[0], sum.x / 4.0, 1e-6);
    EXPECT_LT(out.radiance.at(1, 1)[0], 1.0);  // off-centre samples see less light than the centre
}

// ---- mirror bounces ------------------------------------------------------------------------

TEST(Bounces, MetalSphereReflectsTheBackground) {
    // No lights; metal (metallic 1) of albedo a: F0 = a. With r = 1,
    // max(1 - r, F0) = F0, so the bounce Fresnel is F0 at every angle.
    // Albedo 0.5, ambient 0.1, background 1: the hit adds 0.1 * 0.5 * 1 = 0.05, the
    // reflected ray leaves the scene with throughput 0.5: L = 0.05 + 0.5 * 1 = 0.55.
    Scene scene;
    scene.render.ambient = 0.1;
    scene.render.background = dvec3(1.0);
    scene.spheres.push_back(makeSphere(dvec3(0, 0, -3), 1.0, makeMaterial(dvec3(0.5), 1.0, 1.0)));
    expectVecNear(traceRadiance(scene, dvec3(0.0), dvec3(0, 0, -1)), dvec3(0.55), 1e-15);
    expectVecNear(traceRadiance(scene, dvec3(0.0), glm::normalize(dvec3(0.2, 0.1, -1))), dvec3(0.55), 1e-15);
    // A perfect mirror (albedo 1, F0 = 1; any roughness: max(1 - r, 1) = 1) passes
    // the background unchanged: L = 0.1 * 1 + 1 * 1 = 1.1.
    scene.spheres[0].material = makeMaterial(dvec3(1.0), 0.045, 1.0);
    expectVecNear(traceRadiance(scene, dvec3(0.0), dvec3(0, 0, -1)), dvec3(1.1), 1e-15);
}

TEST(Bounces, TwoFacingMirrorsSumAGeometricSeries) {
    // Metal spheres (albedo 0.5, r = 1: Fr = 0.5) at z = -2 and z = +2, radius 1;
    // a ray along the axis bounces between them forever. Each hit adds
    // throughput * ambient 0.1 * albedo 0.5; after max_bounces = k there were k + 1
    // hits and the ray stops without reaching the background:
    //   L = 0.05 (1 + 0.5 + ... + 0.5^k) = 0.1 (1 - 0.5^(k+1)).
    Scene scene;
    scene.render.ambient = 0.1;
    scene.render.background = dvec3(7.0);  // never reached
    Material mirror = makeMaterial(dvec3(0.5), 1.0, 1.0);
    scene.spheres.push_back(makeSphere(dvec3(0, 0, -2), 1.0, mirror));
    scene.spheres.push_back(makeSphere(dvec3(0, 0, 2), 1.0, mirror));
    for (int k : {0, 1, 2, 5}) {
        scene.render.maxBounces = k;
        double expected = 0.1 * (1.0 - std::pow(0.5, k + 1));
        SCOPED_TRACE(k);
        expectVecNear(traceRadiance(scene, dvec3(0.0), dvec3(0, 0, -1)), dvec3(expected), 1e-15);
    }
}

// ---- robustness ------------------------------------------------------------------------------

// Spheres resting on a large "floor" sphere (contact shadows), two lights, a
// metal and a dielectric: every path of the model in one small picture.
Scene contactScene() {
    Scene scene;
    scene.camera.position = dvec3(0.0, 1.0, 4.0);
    scene.camera.target = dvec3(0.0, 0.3, 0.0);
    scene.render.width = 64;
    scene.render.height = 48;
    scene.render.maxBounces = 3;
    scene.render.background = dvec3(0.1, 0.2, 0.3);
    scene.spheres.push_back(makeSphere(dvec3(0, -100, 0), 100.0, makeMaterial(dvec3(0.8), 0.9, 0.0)));
    scene.spheres.push_back(makeSphere(dvec3(0, 0.5, 0), 0.5, makeMaterial(dvec3(0.9, 0.1, 0.1), 0.3, 0.0)));
    scene.spheres.push_back(makeSphere(dvec3(1.1, 0.4, 0.2), 0.4, makeMaterial(dvec3(0.95, 0.8, 0.4), 0.1, 1.0)));
    scene.spheres.push_back(makeSphere(dvec3(-1.0, 0.3, 0.5), 0.3, makeMaterial(dvec3(0.2, 0.5, 0.9), 0.6, 0.5)));
    scene.lights.push_back(makeLight(dvec3(2, 4, 3), 40.0));
    scene.lights.push_back(makeLight(dvec3(-3, 2, -1), 15.0, dvec3(0.6, 0.7, 1.0)));
    return scene;
}

Scene scaled(Scene scene, double s) {
    // Lengths x s; intensities x s^2 keep C I / d2, and so the picture, unchanged.
    scene.camera.position *= s;
    scene.camera.target *= s;
    for (Sphere& sphere : scene.spheres) {
        sphere.center *= s;
        sphere.radius *= s;
    }
    for (Light& light : scene.lights) {
        light.position *= s;
        light.intensity *= s * s;
    }
    return scene;
}

TEST(CpuRender, ScaleInvariance) {
    // The same scene at 1e-3 and 1e3 times the size renders the same 8-bit
    // picture: the ray offset follows the magnitude of the hit (no acne, no
    // leaks at either scale). Up to 0.1% of the pixels may differ by one level
    // (rounding of the scaled inputs), none by more.
    Rendering reference = renderCpu(contactScene());
    for (double s : {1e-3, 1e3}) {
        Rendering got = renderCpu(scaled(contactScene(), s));
        ASSERT_EQ(got.display.rgb.size(), reference.display.rgb.size());
        int pixelsOff = 0, worst = 0;
        for (size_t p = 0; p < reference.display.rgb.size(); p += 3) {
            int pixelWorst = 0;
            for (int c = 0; c < 3; ++c) {
                int difference = int(got.display.rgb[p + c]) - int(reference.display.rgb[p + c]);
                pixelWorst = std::max(pixelWorst, std::abs(difference));
            }
            pixelsOff += pixelWorst > 0;
            worst = std::max(worst, pixelWorst);
        }
        int pixels = reference.display.width * reference.display.height;
        EXPECT_LE(pixelsOff, pixels / 1000) << "scale " << s;
        EXPECT_LE(worst, 1) << "scale " << s;
    }
}

TEST(CpuRender, ShadowsAreVisibleInTheContactScene) {
    // Guards ScaleInvariance against passing on a picture without shadows:
    // the floor next to the red sphere's contact point, p = (0.05, -1.25e-5, 0),
    // is lit by neither light: the lines to (2,4,3) and (-3,2,-1) pass 0.36 and
    // 0.40 from the red sphere's centre, inside its radius 0.5.
    Scene scene = contactScene();
    Hit hit;
    ASSERT_TRUE(closestHit(scene, dvec3(0.05, 0.001, 0.0), dvec3(0, -1, 0), hit));
    EXPECT_EQ(hit.sphere, 0);
    EXPECT_FALSE(lightVisible(scene, hit, scene.lights[0].position));
    EXPECT_FALSE(lightVisible(scene, hit, scene.lights[1].position));
}

TEST(CpuRender, NoNaNForAnyVariantOrDegenerateGeometry) {
    // Camera inside a big sphere (every ray hits from inside), a light at a
    // sphere's centre (inside it: shadowed), a light on a surface, mirror-like
    // metal at the roughness clamp, 16 bounces, 4 samples.
    Scene scene = contactScene();
    scene.render.width = 24;
    scene.render.height = 16;
    scene.render.spp = 4;
    scene.render.maxBounces = 16;
    scene.spheres.push_back(makeSphere(dvec3(0.0), 20.0, makeMaterial(dvec3(0.5), 0.0, 1.0)));
    scene.lights.push_back(makeLight(dvec3(0, 0.5, 0), 10.0));  // the red sphere's centre
    scene.lights.push_back(makeLight(dvec3(0, 1.0, 0), 10.0));  // on the red sphere's top
    for (const ShadingModel& model : allModelVariants()) {
        scene.model = model;
        Rendering out = renderCpu(scene);
        long bad = 0;
        for (float value : out.radiance.rgb) bad += !std::isfinite(value);
        EXPECT_EQ(bad, 0);
    }
}

TEST(CpuRender, ThreadCountDoesNotChangeThePicture) {
    Scene scene = contactScene();
    Rendering one = renderCpu(scene, 1);
    Rendering three = renderCpu(scene, 3);
    EXPECT_EQ(one.radiance.rgb, three.radiance.rgb);
    EXPECT_EQ(one.display.rgb, three.display.rgb);
}

TEST(CpuRender, DegenerateInputThrows) {
    Scene scene = contactScene();
    scene.camera.up = scene.camera.target - scene.camera.position;  // up along the view: no roll
    EXPECT_THROW(renderCpu(scene), rl::Error);
    scene = contactScene();
    scene.render.spp = 3;  // not a square
    EXPECT_THROW(renderCpu(scene), rl::Error);
}

}  // namespace
