// The probes of exercise 12-sky-shadows: sphereFormFactor for spheres above,
// across and below the horizon, touching and far, against reference.cpp,
// with the float32 tolerance and the mistakes the checker names.
#include "checks/probe_toolkit.h"
#include "reference/sphere_form_factor.h"

namespace rl {
namespace {

using namespace probes;

// Inputs (shaders/probe.glsl's texels): a.xyz p, b.xyz n, c.xyz centre, c.w radius.
dvec3 point(const ProbeCase& c) { return get(c, 0); }
dvec3 normal(const ProbeCase& c) { return get(c, 4); }
dvec3 centre(const ProbeCase& c) { return get(c, 8); }
double radius(const ProbeCase& c) { return f(c, 11); }

// h = d / radius and cos(beta) = n . w of a case, in double.
std::pair<double, double> hAndCos(const ProbeCase& c) {
    dvec3 toCentre = centre(c) - point(c);
    double d = glm::length(toCentre);
    return {d / radius(c), glm::dot(normal(c), toCentre / d)};
}

// The clipped formula with a mistake in it: the acos argument's sign times
// `acosSign` (-1: the minus lost), atan's arguments swapped.
double clippedWith(const ProbeCase& c, double acosSign, bool atanSwapped) {
    auto [h, cosBeta] = hAndCos(c);
    const double h2 = h * h, k2 = 1.0 - h2 * cosBeta * cosBeta;
    if (k2 <= 0.0) return std::max(cosBeta, 0.0) / h2;
    const double x = std::sqrt(h2 - 1.0), k = std::sqrt(k2), s = std::sqrt(1.0 - cosBeta * cosBeta);
    const double a = std::acos(std::clamp(-acosSign * x * cosBeta / s, -1.0, 1.0));
    const double v = (cosBeta * a - x * k) / h2 + (atanSwapped ? std::atan2(x, k) : std::atan2(k, x));
    return std::clamp(v / R::kPi, 0.0, 1.0);
}

double formFactor(const ProbeCase& c) {
    return ref::sphereFormFactor(point(c), normal(c), centre(c), radius(c));
}

std::vector<ProbeSpec> skyShadowProbes() {
    ProbeSpec ff{"sphereFormFactor", "sphereFormFactor(p, n, centre, radius)", 1};
    Random rng(1212);
    auto add = [&](double h, double cosBeta, const std::string& group) {
        ProbeCase c;
        vec3 p = rng.point(dvec3(-3), dvec3(3));
        vec3 n = rng.unitVector();
        vec3 w = cosBeta >= 1.0 ? n : rng.around(n, cosBeta);
        double r = rng.range(1.1, 3.0);  // d = h r > 1: a mistake that takes d for h stays defined
        put(c, 0, p);
        put(c, 4, n);
        put(c, 8, vec3(dvec3(p) + dvec3(w) * (h * r)));
        c.in[11] = float(r);
        c.group = group;
        ff.cases.push_back(c);
    };
    for (int k = 0; k < 24; ++k) {
        double h = rng.range(1.05, 12.0);
        double cosBeta = rng.range(1.0 / h + 0.02, 1.0);
        add(h, std::min(cosBeta, 1.0), "above the horizon");
    }
    for (int k = 0; k < 40; ++k) {
        double h = rng.range(1.02, 8.0);
        double cosBeta = rng.range(-0.95, 0.95) / h;
        add(h, cosBeta, "crossing the horizon");
    }
    for (int k = 0; k < 10; ++k) {
        double h = rng.range(1.05, 8.0);
        double cosBeta = -rng.range(1.0 / h + 0.02, 1.0);
        add(h, std::max(cosBeta, -1.0), "below the horizon");
    }
    for (int k = 0; k < 8; ++k) {
        double h = 1.0 + rng.range(1e-3, 2e-2);
        double cosBeta = rng.range(-0.9, 0.9);
        add(h, cosBeta, "touching (a sphere resting on the ground)");
    }
    for (int k = 0; k < 8; ++k) {
        double h = rng.range(50.0, 1000.0);
        double cosBeta = k < 4 ? rng.range(0.1, 1.0) : rng.range(-0.9, 0.9) / h;
        add(h, cosBeta, "far away (h 50 to 1000)");
    }
    add(2.0, 1.0, "straight above");
    add(1.5, 1.0, "straight above");
    ff.expected = [](const ProbeCase& c) { return value(formFactor(c)); };
    // float32 finds h and cos(beta) from p, n, centre and radius to a few
    // ulps (a length, a division, a dot product: 8 u bounds them), and F
    // moves with them: by how much is measured here, on the model itself,
    // by moving h and cos(beta) by 8 u (F's slope is steep near h = 1, where
    // x = sqrt(h^2 - 1) has an infinite one). Then acos and atan: the GLSL
    // spec leaves their precision open, and drivers approximate them by
    // short polynomials (Mesa's acos, from asin's Abramowitz-Stegun form, is
    // off by up to ~7e-5 rad); 2e-4 rad each, three times that, enters F as
    // (|cos(beta)| + 1) 2e-4 / pi in the clipped branch: at most 1.3e-4, an
    // irradiance change of 1e-4 of the sky's, far below an 8-bit step. The
    // mistakes below move F by 1e-2 and more on most of the cases where they
    // differ. 4e-6 absolute everywhere: the same trigonometry where a
    // mistaken formula sits at the edge of its clipped branch, F near 0.
    // 1e-4 relative as for every exercise (kRel).
    ff.tolerance = [](const ProbeCase& c) {
        auto [h, cosBeta] = hAndCos(c);
        const double F = ref::sphereFormFactor(h, cosBeta), u8 = 8 * kUnitRoundoff;
        double moved = 0;
        for (double sh : {-1.0, 1.0})
            for (double sc : {-1.0, 1.0}) {
                const double h2 = std::max(h * (1 + sh * u8), 1.0 + 1e-12);
                const double c2 = std::clamp(cosBeta + sc * u8, -1.0, 1.0);
                moved = std::max(moved, std::abs(ref::sphereFormFactor(h2, c2) - F));
            }
        const bool clipped = h * h * cosBeta * cosBeta < 1.0;
        const double trig = clipped ? (std::abs(cosBeta) + 1.0) * 2e-4 / R::kPi : 0.0;
        return std::make_pair(4e-6 + trig + 2 * moved, kRel);
    };
    ff.describe = [](const ProbeCase& c) {
        auto [h, cosBeta] = hAndCos(c);
        return "h=" + fmt(h) + " cos(beta)=" + fmt(cosBeta) + " radius=" + fmt(radius(c));
    };
    ff.mistakes = {
        {"a sphere across the horizon hides light from below the surface too",
         "where the sphere crosses the horizon (|h cos(beta)| < 1) only the part above it counts: the clipped formula",
         [](const ProbeCase& c) {
             auto [h, cosBeta] = hAndCos(c);
             return value(std::max(cosBeta, 0.0) / (h * h));
         }},
        {"far spheres hide far too much of the sky", "the cap's share falls as (radius / d)^2: divide by h^2, not h",
         [](const ProbeCase& c) {
             auto [h, cosBeta] = hAndCos(c);
             return value(ref::sphereFormFactor(std::sqrt(h), cosBeta));
         }},
        {"the shadow does not grow with the sphere", "h = d / radius: the distance in radii, not d itself",
         [](const ProbeCase& c) {
             auto [h, cosBeta] = hAndCos(c);
             const double d = h * radius(c);
             return d > 1.0 ? value(ref::sphereFormFactor(d, cosBeta)) : value(formFactor(c));
         }},
        {"a sphere beside the surface hides as much as one straight above it",
         "the form factor weights each direction by n.l: F = cos(beta) / h^2 above the horizon, not 1 / h^2",
         [](const ProbeCase& c) {
             auto [h, cosBeta] = hAndCos(c);
             if (h * cosBeta >= 1.0) return value(1.0 / (h * h));
             return value(ref::sphereFormFactor(h, cosBeta));
         }},
        {"a sphere across the horizon hides the light of its mirror image in the horizon",
         "acos(-x cos(beta) / sin(beta)): mind the minus",
         [](const ProbeCase& c) { return value(clippedWith(c, -1.0, false)); }},
        {"a sphere just across the horizon hides too much", "atan(k / x), not atan(x / k)",
         [](const ProbeCase& c) { return value(clippedWith(c, 1.0, true)); }},
        {"a sphere across the horizon hides about pi times too much",
         "the clipped formula is divided by pi as well",
         [](const ProbeCase& c) {
             auto [h, cosBeta] = hAndCos(c);
             const double F = ref::sphereFormFactor(h, cosBeta);
             return value(h * h * cosBeta * cosBeta < 1.0 ? std::min(F * R::kPi, 1.0) : F);
         }},
        {"spheres below the surface add light (a negative shadow)",
         "a sphere wholly below the horizon hides nothing: F = 0 there, not cos(beta) / h^2",
         [](const ProbeCase& c) {
             auto [h, cosBeta] = hAndCos(c);
             return value(h * cosBeta <= -1.0 ? cosBeta / (h * h) : ref::sphereFormFactor(h, cosBeta));
         }},
    };
    ff.groupHints = {{"crossing the horizon", "|h cos(beta)| < 1: the clipped formula, with acos, atan and the 1/pi"},
                     {"below the horizon", "h cos(beta) <= -1: F = 0"},
                     {"touching (a sphere resting on the ground)", "h close to 1: x = sqrt(h^2 - 1) is small; keep atan(k, x)"}};
    return {ff};
}

}  // namespace

RL_UNIT_PROBES { return skyShadowProbes(); }

}  // namespace rl
