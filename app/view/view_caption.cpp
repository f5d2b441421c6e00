#include "view/view_caption.h"

#include "reference/brdf_reference.h"
#include "reference/cpu_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rl {
namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string distributionName(const ShadingModel& m) {
    return m.distribution == DistributionModel::Beckmann ? "Beckmann" : "GGX (Trowbridge-Reitz)";
}
std::string geometryName(const ShadingModel& m) {
    switch (m.geometry) {
        case GeometryModel::SmithGGXSeparable: return "exact Smith GGX, separable";
        case GeometryModel::SmithGGXCorrelated: return "exact Smith GGX, height-correlated";
        default: return "Smith with Schlick-GGX G1";
    }
}
std::string fresnelName(const ShadingModel& m) {
    switch (m.fresnel) {
        case FresnelModel::Dielectric: return "exact dielectric";
        case FresnelModel::Conductor: return "exact conductor (edge tint)";
        default: return "Schlick";
    }
}
std::string diffuseName(const ShadingModel& m) { return m.diffuse == DiffuseModel::Burley ? "Burley" : "Lambert"; }

std::string modelSummary(const ShadingModel& m) {
    if (m.blinnPhong) return "model: Blinn-Phong";
    return "model: D " + distributionName(m) + ", G " + geometryName(m) + ", F " + fresnelName(m) + ", diffuse " +
           diffuseName(m) + (m.isReference() ? " (the reference model)" : "");
}

std::string distributionFormula(const ShadingModel& m) {
    if (m.distribution == DistributionModel::Beckmann)
        return "D = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 (n.h)^4),  alpha = r^2";
    return "D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2),  alpha = r^2";
}
std::string geometryFormula(const ShadingModel& m) {
    switch (m.geometry) {
        case GeometryModel::SmithGGXSeparable:
            return "G = G1(NoV) G1(NoL),  G1(x) = 2 x / (x + sqrt(alpha^2 + (1 - alpha^2) x^2))";
        case GeometryModel::SmithGGXCorrelated:
            return "G = 2 NoL NoV / (NoV sqrt(alpha^2 + (1 - alpha^2) NoL^2) + NoL sqrt(alpha^2 + (1 - alpha^2) "
                   "NoV^2))";
        default: return "G = G1(NoV) G1(NoL),  G1(x) = x / (x (1 - k) + k),  k = (r + 1)^2 / 8";
    }
}
std::string fresnelFormula(const ShadingModel& m) {
    switch (m.fresnel) {
        case FresnelModel::Dielectric: return "F = exact dielectric Fresnel at VoH,  n = (1 + sqrt(F0)) / (1 - sqrt(F0))";
        case FresnelModel::Conductor: return "F = exact conductor Fresnel at VoH (Gulbrandsen 2014: F0, edge tint)";
        default: return "F = F0 + (1 - F0) (1 - VoH)^5";
    }
}
const char* const kBounceWeight = "Fr = F0 + (max(1 - r, F0) - F0) (1 - NoV)^5";

ColourScale linearScale() {
    return {"linear: grey level = value", {{0, "0"}, {0.25, "0.25"}, {0.5, "0.5"}, {0.75, "0.75"}, {1, "1"}}};
}

ColourScale ticksAt(View view, const RenderSettings& render, std::string label, std::initializer_list<double> values) {
    ColourScale s{std::move(label), {}};
    for (double v : values)
        if (const double p = scalePosition(view, v, render); p >= 0) s.ticks.push_back({p, number(v)});
    return s;
}

// Radiance views: ticks at round radiance values, where the display step
// puts them; ticks closer than 12% of the bar to the last one are dropped,
// and so is any beyond 99.5% (saturated: the tone map's asymptote).
ColourScale radianceScale(View view, const RenderSettings& render) {
    ColourScale s;
    s.label = "radiance, through the display step (exposure " + number(render.exposure) + ", tone map, gamma)";
    double last = -1;
    for (double v : {0.0, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0}) {
        const double p = scalePosition(view, v, render);
        if (p < 0 || p > 0.995 || (last >= 0 && p - last < 0.12)) continue;
        s.ticks.push_back({p, number(v)});
        last = p;
    }
    return s;
}

}  // namespace

double scalePosition(View view, double value, const RenderSettings& render) {
    switch (view) {
        case View::D: return value / (1.0 + value);
        case View::F:
        case View::FresnelNoV: return std::clamp(std::log10(std::max(value, 0.01)) / 2.0 + 1.0, 0.0, 1.0);
        case View::Normals: return std::clamp(value * 0.5 + 0.5, 0.0, 1.0);
        case View::Final:
        case View::Bounce:
        case View::Diffuse:
        case View::Specular:
        case View::EnvIrradiance:
        case View::EnvPrefiltered:
            // The display step in double is the reference's (exercise 10's
            // answer): a student edition has none, and its bar no ticks (-1).
            return ref::referenceInThisCopy() ? ref::displayEncode(glm::dvec3(value), render).x : -1.0;
        default: return std::clamp(value, 0.0, 1.0);
    }
}

ViewCaption viewCaption(View view, int bounce, const Scene& scene, const ShadingModel& m) {
    const RenderSettings& r = scene.render;
    ViewCaption c;
    c.model = modelSummary(m);
    switch (view) {
        case View::Final:
            c.title = "0  final picture";
            c.formula = "L = sum over bounces k of (Fr_1 ... Fr_k) L_direct(hit k);  pixel = gamma(tonemap(exposure L))";
            c.scale = radianceScale(view, r);
            break;
        case View::D:
            c.title = "1  D: normal distribution (key light)";
            c.model = m.blinnPhong ? "D: GGX (Blinn-Phong has no D; the view shows GGX)" : "D: " + distributionName(m);
            c.formula = distributionFormula(m);
            c.scale = ticksAt(view, r, "D / (1 + D): D = 1 is mid grey", {0, 0.25, 1, 4, 20});
            break;
        case View::G:
            c.title = "2  G: geometry, masking-shadowing (key light)";
            c.model = "G: " + geometryName(m) + (m.blinnPhong ? " (Blinn-Phong has no G)" : "");
            c.formula = geometryFormula(m);
            c.scale = linearScale();
            break;
        case View::F:
            c.title = "3  F(v.h): Fresnel of the key light's highlight";
            c.model = "F: " + fresnelName(m) + (m.blinnPhong ? " (Blinn-Phong has no F)" : "");
            c.formula = fresnelFormula(m);
            c.scale = ticksAt(view, r, "log scale: 0.01 .. 1 (rgb: per channel)", {0.01, 0.04, 0.1, 0.3, 1});
            break;
        case View::FresnelNoV:
            c.title = "V  F(n.v): reflection weight of the mirror bounces";
            c.model = "Fr: F_SchlickRoughness (exercise 09), whatever the model";
            c.formula = kBounceWeight;
            c.scale = ticksAt(view, r, "log scale: 0.01 .. 1 (rgb: per channel)", {0.01, 0.04, 0.1, 0.3, 1});
            break;
        case View::Diffuse:
            c.title = "4  diffuse radiance of all lights";
            c.model = m.blinnPhong ? "diffuse: Blinn-Phong" : "diffuse: " + diffuseName(m) + ", kd with F " + fresnelName(m);
            c.formula = m.blinnPhong ? "L_d = sum_l f_d E_l,  f_d = (1 - F0)(1 - metallic) albedo / pi"
                        : m.diffuse == DiffuseModel::Burley
                            ? "L_d = sum_l f_d E_l,  f_d = (1 - F)(1 - metallic) Fd_Burley(albedo, NoV, NoL, VoH)"
                            : "L_d = sum_l f_d E_l,  f_d = (1 - F)(1 - metallic) albedo / pi";
            c.scale = radianceScale(view, r);
            break;
        case View::Specular:
            c.title = "5  specular radiance of all lights";
            c.model = m.blinnPhong ? "specular: Blinn-Phong"
                                   : "specular: Cook-Torrance, D " + distributionName(m) + ", G " + geometryName(m) +
                                         ", F " + fresnelName(m);
            c.formula = m.blinnPhong ? "L_s = sum_l f_s E_l,  f_s = F0 Fr_BlinnPhong(NoH, s)"
                                     : "L_s = sum_l f_s E_l,  f_s(l, v) = D(h) G(l, v) F(v.h) / (4 NoL NoV)";
            c.scale = radianceScale(view, r);
            break;
        case View::NdotL:
            c.title = "6  n.l of the key light";
            c.formula = "NoL = clamp(n.l, 0, 1),  l = normalize(light - p)";
            c.scale = linearScale();
            break;
        case View::Shadow:
            c.title = "7  shadow of the key light";
            c.formula = "1 where the shadow ray from p reaches the key light, 0 where a sphere blocks it";
            c.scale = {"two values, nothing between", {{0.25, "0 shadow"}, {0.75, "1 lit"}}, true};
            break;
        case View::Normals:
            c.title = "8  normals";
            c.formula = "rgb = n * 0.5 + 0.5  (x red, y green, z blue)";
            c.scale = ticksAt(view, r, "each component of n", {-1, 0, 1});
            break;
        case View::Bounce:
            c.title = "9  bounce " + std::to_string(bounce) + " alone" +
                      (bounce > r.maxBounces ? "  (beyond max bounces = " + std::to_string(r.maxBounces) + ": black)"
                                             : "");
            c.formula = "L_" + std::to_string(bounce) + " = (Fr_1 ... Fr_" + std::to_string(bounce) +
                        ") L_direct(hit " + std::to_string(bounce) + "),  " + kBounceWeight;
            if (bounce == 0) c.formula = "L_0 = L_direct(primary hit): the lights and ambient, no reflection";
            c.scale = radianceScale(view, r);
            break;
        case View::EnvIrradiance:
            c.title = "E  environment irradiance E(n) / pi";
            c.model = "SH9: nine coefficients of the map, computed on the host in double (exercise 11)";
            c.formula = "E(n) = sum_k A_l(k) L_k Y_k(n),  A = pi, 2 pi / 3, pi / 4;  shown: what a white Lambert surface reflects";
            c.scale = radianceScale(view, r);
            break;
        case View::EnvPrefiltered:
            c.title = "L  prefiltered environment towards r = reflect(-v, n)";
            c.model = "GGX-prefiltered levels (n = v = r), the level from the roughness (exercise 11)";
            c.formula = "L_pre(r, level = roughness (levels - 1)): the first factor of the split sum";
            c.scale = radianceScale(view, r);
            break;
        case View::EnvScale:
        case View::EnvBias:
            c.title = view == View::EnvScale ? "Y  split-sum scale at (n.v, roughness)" : "U  split-sum bias at (n.v, roughness)";
            c.model = "the table of the reference's specular lobe (GGX, Schlick-GGX G), in double";
            c.formula = "specular = L_pre (F0 scale + bias);  scale + bias = the lobe's albedo for F0 = 1";
            c.scale = linearScale();
            break;
    }
    if (!scene.environment && (view == View::EnvIrradiance || view == View::EnvPrefiltered || view == View::EnvScale ||
                               view == View::EnvBias))
        c.title += "  (this scene has no environment: black)";
    return c;
}

CaptionLayout captionLayout(int width, int height, float uiScale) {
    CaptionLayout l;
    const float s = uiScale;
    l.scale = s;
    l.margin = 10 * s;    // as the other overlays (overlays.cpp)
    l.pad = 6 * s;        // as the wipe's labels
    l.fontSize = 13 * s;  // ImGui's default font (ProggyClean, 13 px)
    l.right = float(width) - l.margin;
    l.bottom = float(height) - l.margin;
    const float inside = std::max(1.0f, float(width) - 2 * l.margin - 2 * l.pad);
    l.barWidth = std::min(256 * s, inside);  // 256: one column per 8-bit grey level at scale 1
    l.barHeight = 12 * s;                    // a stripe as tall as the text: visible from the back row
    l.barX = l.right - l.pad - l.barWidth;
    // Under the bar: 4 px (scaled) of tick marks, the tick labels, the pad.
    l.barY = l.bottom - l.pad - l.fontSize - 4 * s - l.barHeight;
    l.textWidth = std::min(inside, std::max(l.barWidth, 0.5f * float(width)));
    return l;
}

}  // namespace rl
