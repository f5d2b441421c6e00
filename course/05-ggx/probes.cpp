// The probes of exercise 05-ggx: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 05 D -------------------------------------------------------------------------------

// n and h with n.h = cosTheta: h is n turned by theta.
void putNormalHalf(ProbeCase& c, Random& rng, double cosTheta) {
    vec3 n = rng.unitVector();
    put(c, 0, n);
    put(c, 4, cosTheta >= 1 ? n : rng.around(n, cosTheta));
}

std::vector<ProbeSpec> ggxProbes() {
    ProbeSpec d{"D_GGX", "D_GGX(n, h, alpha)", 1};
    Random rng(505);
    for (int k = 0; k < 50; ++k) {
        ProbeCase c;
        putNormalHalf(c, rng, rng.range(0.05, 0.999));
        double r = rng.range(0.1, 1);
        c.in[8] = float(r * r);
        c.group = "random";
        d.cases.push_back(c);
    }
    for (double r : {R::kMinRoughness, 0.06, 0.1}) {  // the peak of a nearly mirror surface
        for (double cosTheta : {1.0, 1.0 - 1e-7, 1.0 - 1e-6, 1.0 - 4e-6}) {
            ProbeCase c;
            putNormalHalf(c, rng, cosTheta);
            c.in[8] = float(r * r);
            c.group = "near the peak, smooth surface";
            d.cases.push_back(c);
        }
    }
    for (int k = 0; k < 10; ++k) {
        ProbeCase c;
        putNormalHalf(c, rng, rng.range(0.01, 1));
        c.in[8] = 1.0f;
        c.group = "roughness 1";
        d.cases.push_back(c);
    }
    for (float alpha : {1.0f, 0.75f, 0.5f, 0.25f}) {  // the peak, n = h along an axis: every form computes it exactly
        ProbeCase c;
        put(c, 0, vec3(0, 0, 1));
        put(c, 4, vec3(0, 0, 1));
        c.in[8] = alpha;
        c.group = "peak with n = h exactly";
        d.cases.push_back(c);
    }
    d.expected = [](const ProbeCase& c) { return value(R::D_GGX(get(c, 0), get(c, 4), f(c, 8))); };
    // Near the peak the float32 inputs are themselves exact; a cancellation-free
    // form stays within 1e-3, the textbook 1 - (n.h)^2 loses several percent:
    // 1% is the budget for the peak. Elsewhere the cross-product form
    // is a handful of roundings (~1e-6); a form that computes 1 - (n.h)^2
    // loses up to ~1e-4 at n.h = 0.999, alpha = 0.01 (6e-8 absolute against
    // a denominator of 2e-3, doubled by the square): 2e-4 keeps the random
    // cases above that, and catches pi written as 3.14 (5.1e-4). With
    // alpha = 1, D = 1/pi whatever n.h, but the cross and dot products of
    // unit vectors add ~4e-7 to a denominator of 1, doubled by the square:
    // 1e-5. At the peak with n = h = (0, 0, 1) and alpha^2 exact in float32,
    // D = 1 / (pi alpha^2) is a constant, two products and a division, each
    // correctly rounded or within 2.5 ulp: at most ~4 ulp = 2.4e-7, and 1e-6
    // catches even pi written as 3.1416 (2.3e-6).
    d.tolerance = [](const ProbeCase& c) {
        if (c.group.rfind("near the peak", 0) == 0) return std::make_pair(kAbs, 1e-2);
        if (c.group == "peak with n = h exactly") return std::make_pair(0.0, 1e-6);  // D >= 1/pi here
        return std::make_pair(kAbs, c.group == "roughness 1" ? 1e-5 : 2e-4);
    };
    d.describe = [](const ProbeCase& c) {
        double NoH = glm::dot(get(c, 0), get(c, 4));
        // Near the peak n.h prints as 1: show how far from 1 it is instead.
        std::string angle = NoH > 0.999 ? "1-n.h=" + fmt(1.0 - NoH) : "n.h=" + fmt(NoH);
        return angle + " alpha=" + fmt(f(c, 8));
    };
    // D with the pi or the square of alpha missing. The denominator as
    // |n x h|^2 + (n.h)^2 alpha^2, like the reference: the float32 inputs are
    // unit vectors only to ~1e-7, which (n.h)^2 (alpha^2 - 1) + 1 turns into
    // percents near the peak, even in double.
    auto dTextbookLike = [](const ProbeCase& c, double piFactor, bool alphaSquared) {
        dvec3 n = get(c, 0), h = get(c, 4);
        double NoH = glm::dot(n, h), a = f(c, 8);
        double a2 = alphaSquared ? a * a : a;
        double den = glm::length2(glm::cross(n, h)) + NoH * NoH * a2;
        return value(a2 / (piFactor * den * den));
    };
    d.mistakes = {
        {"highlights pi times too bright", "D = alpha^2 / (pi (...)^2): the pi is missing",
         [=](const ProbeCase& c) { return dTextbookLike(c, 1.0, true); }},
        {"highlights too wide and too dim (alpha used where alpha^2 belongs)",
         "alpha is already roughness^2; the formula squares it again: alpha^2",
         [=](const ProbeCase& c) { return dTextbookLike(c, R::kPi, false); }},
    };
    // The denominator clamped from below against a division by zero that
    // cannot happen (alpha >= MIN_ROUGHNESS^2 keeps it >= alpha^4 > 0): at the peak
    // of a smooth surface (pi (...)^2 ~ 1e-11) the clamp caps D. Clamps of
    // the square or of the bracket, at the usual epsilons; any other
    // epsilon gets the group hint below, which names the clamp too.
    // (The bracket is at least alpha^2 >= 4.1e-6, so only its larger
    // epsilons change a value.)
    for (double eps : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
        for (bool ofSquare : {true, false}) {
            if (!ofSquare && eps < 4.1e-6) continue;
            d.mistakes.push_back(
                {"the highlights of smooth surfaces too dim and flat-topped (the denominator clamped)",
                 "the denominator is clamped (max(" + std::string(ofSquare ? "denom * denom" : "denom") + ", " +
                     fmt(eps) + ")): at the peak of a smooth surface it is far smaller, and D must reach "
                     "1 / (pi alpha^2) there: leave it unclamped (alpha >= MIN_ROUGHNESS^2 keeps it above 0)",
                 [=](const ProbeCase& c) {
                     dvec3 n = get(c, 0), h = get(c, 4);
                     double NoH = glm::dot(n, h), a = f(c, 8), a2 = a * a;
                     double den = glm::length2(glm::cross(n, h)) + NoH * NoH * a2;
                     double den2 = ofSquare ? std::max(den * den, eps) : std::max(den, eps) * std::max(den, eps);
                     return value(a2 / (R::kPi * den2));
                 }});
        }
    }
    d.groupHints = {{"near the peak, smooth surface",
                     "near n.h = 1, 1 - (n.h)^2 cancels in float32 (write it as |cross(n, h)|^2), and a clamp of "
                     "the denominator (max(..., eps)) caps the peak, which reaches 1 / (pi alpha^2)"}};
    return {d};
}

}  // namespace

RL_UNIT_PROBES { return ggxProbes(); }

}  // namespace rl
