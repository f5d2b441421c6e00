// The bench's "environment" sweep (issue 24): speed against error of the GL
// picture's approximations of environment light (docs/model.md,
// "Environment light") on scenes that have an environment. Each row changes
// ONE setting of the default approximation (irradiance from nine SH
// coefficients or from an N x N/2 irradiance map; the prefiltered
// environment's level count and sample count; the split-sum table's size),
// is timed with the bench's clock and compared with the EXACT reference:
// the CPU reference's Monte Carlo integral of environment light (fixed seed),
// computed once per scene and run, with visibility (the truth) and without
// (what the approximations aim at: none of them is shadowed). The row
// "exact:no-V" is that second reference itself, against the first: the
// error that leaving visibility out costs every approximation alike.
// docs/performance.md, "Environment light: speed against error", shows a run.
#pragma once

#include "core/image.h"
#include "core/scene.h"
#include "render/environment_resources.h"
#include "shader/shader_library.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace rl::bench {

struct Measurement;

// How the GL picture approximates environment light. 0 in a field: the
// renderer's own default for it.
struct EnvironmentApproximation {
    int irradianceMap = 0;     // 0: the nine SH coefficients; N: an N x N/2 irradiance map (double on the host)
    int prefilterWidth = 0;    // level 0 of the prefiltered chain is prefilterWidth x prefilterWidth/2
    int prefilterLevels = 0;   // levels of the roughness-prefiltered environment
    int prefilterSamples = 0;  // GGX samples per prefiltered texel
    int lutSize = 0;           // the split-sum table is lutSize x lutSize
    int occlusion = -1;        // -1: the table's RL_ENV_OCCLUSION; 0: none; 1, 2: its strategies (environment_occlusion.glsl)
};
// The renderer's settings for it: EnvironmentSettings{} with the non-zero fields put in.
EnvironmentSettings environmentSettings(const EnvironmentApproximation& approximation);

// "env:irradiance-map=32x16", "env:prefilter=256x128", "env:levels=6",
// "env:prefilter-samples=64", "env:lut=32", "env:occlusion=none|caps|directional",
// and "env:default" when every field is 0 (occlusion -1).
std::string environmentVariantName(const EnvironmentApproximation& approximation);

// The sweep's rows, in table order: the default, then one setting changed at
// a time (a row equal to the default is left out).
std::vector<EnvironmentApproximation> environmentSweep();
// The irradiance maps' widths in the sweep (each N x N/2).
constexpr int kIrradianceMapWidths[] = {16, 32, 64, 128};

// The defines a row's program adds to the picture's: RL_ENV_IRRADIANCE_MAP
// for an irradiance map (shaders/environment.glsl), RL_ENV_OCCLUSION for an
// occlusion strategy other than the table's, none otherwise.
ShaderDefines environmentDefines(const EnvironmentApproximation& approximation);

// Why the GL picture cannot show `approximation` in this build ("" when it
// can): a variant with a reason is a skipped row.
std::string environmentApproximationUnsupported(const EnvironmentApproximation& approximation);

// The error budget of the default approximation on the shipped environment
// scenes (scenes/environments/*-spheres.json), written beside the table in
// docs/performance.md and held by EnvironmentBudget.TheDefaultStaysWithinTheBudget.
// The default is shadowed by the spheres (RL_ENV_OCCLUSION, issue 34), so it
// is held to the exact reference WITH visibility, the truth:
//  * its mean less the reference's own noise (Measurement::referenceNoiseLsb:
//    the error bar taken out) at most meanLsb, and its share of pixels off
//    by over 1/255 less the noise's own share at most offFraction;
//  * mean at most noVisibilityShare of the row exact:no-V's (the reference
//    without visibility against the one with it): occlusion must buy back
//    most of what leaving visibility out costs, where that is more than
//    meanLsb (else nothing is left to buy back).
struct EnvironmentBudget {
    double meanLsb;
    double offFraction;
    double noVisibilityShare;
};
const EnvironmentBudget& environmentBudget();
// A row of the sweep (`m`, usually env:default) against the budget, with the
// scene's row exact:no-V.
struct EnvironmentBudgetCheck {
    bool mean = false, off = false, belowNoVisibility = false;
    // exact:no-V is itself within the mean's budget: belowNoVisibility holds
    // with nothing to buy back.
    bool nothingToBuyBack = false;
    bool meets() const { return mean && off && belowNoVisibility; }
};
EnvironmentBudgetCheck checkEnvironmentBudget(const Measurement& m, const Measurement& exact);

// The exact references of one scene at its own size and spp (the GL
// picture's own rays: the error is the light's, not the pixel filter's).
struct ExactReferences {
    int samples = 0;  // per strategy per hit (ref::EnvironmentOptions::samples)
    // Each the mean of two estimates of samples / 2 (seeds 1 and 2).
    Rendering withVisibility;
    Rendering withoutVisibility;
    // The references' own noise: mean |seed 1 - seed 2| / 2 over the display
    // channels, in 8-bit steps (the difference of two independent estimates
    // has twice the variance of one, their mean half of it), and the share of
    // pixels where that exceeds 1/255 in a channel.
    double noiseMeanLsb = 0, noiseOffFraction = 0;  // with visibility
    double noiseMeanLsbWithoutVisibility = 0;
    double msWithVisibility = 0, msWithoutVisibility = 0;  // wall clock of each (threads: all cores)
};
// Samples per strategy per hit of the bench's exact references: 1024, four
// times the reference's default, so that the reference's noise (printed with
// each run) is well below the errors it ranks.
constexpr int kExactReferenceSamples = 1024;
ExactReferences exactReferences(const Scene& scene, int samples, std::ostream& log);

// The environment rows of `measurements` as their own table: the default,
// each row's error against both references, the budget and whether the
// default meets it; "" without environment rows.
std::string formatEnvironmentTable(const std::vector<Measurement>& measurements);

}  // namespace rl::bench
