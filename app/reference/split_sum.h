// split_sum.h: the host side of the split-sum approximation of specular
// environment light (Karis 2013, "Real Shading in Unreal Engine 4", pp. 5-7),
// in double, for the shader of issue 24 and the checks of its exercise. Pure
// functions.
//
// The split sum replaces the specular integral of environment light by
//     (prefiltered environment at r, for roughness r) * (F0 * scale + bias)
// where the first factor is the environment blurred by the GGX lobe under
// the assumption n = v = r (Karis's "we assume the view direction equals the
// normal and the reflection direction"), and the second is the BRDF's
// directional albedo split by Schlick's F = F0 (1 - Fc) + Fc, Fc = (1 - v.h)^5:
//     scale = integral f_s / F (1 - Fc) n.l dl,   bias = integral f_s / F Fc n.l dl
// with f_s = D G F / (4 n.l n.v) THE REFERENCE'S specular lobe (D_GGX, and
// G_SchlickGGX with k = (r + 1)^2 / 8, docs/model.md): Karis uses k = alpha/2
// for image-based light, which would make the table disagree with the model
// the reference integrates; here scale + bias is exactly that model's
// specular albedo for F0 = 1, so the split is the approximation's only error.
#pragma once

#include "core/image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace rl::ref {

// scale (x) and bias (y) at n.v = NoV (clamped to [1e-4, 1]) and perceptual
// roughness r (clamped to [0.045, 1]), by stratified quadrature on
// samples x samples cells of GGX half vectors (pdf D n.h), l = reflect(-v, h):
//     mean over the cells with n.l > 0 of  G v.h / (n.v n.h) * ((1 - Fc), Fc)
glm::dvec2 splitSumBrdf(double NoV, double roughness, int samples);

// The lookup table of size x size entries, [j * size + i] at texel centres
// NoV = (i + 1/2)/size and roughness = (j + 1/2)/size (Filament's and
// Karis's layout: n.v along x, roughness along y).
std::vector<glm::dvec2> splitSumTable(int size, int samples);

// A GGX half vector around +z for (u1, u2) in [0, 1)^2 (Walter et al. 2007
// eq. 35): the sample directions of both the table and the prefiltering.
glm::dvec3 ggxHalfVector(double u1, double u2, double alpha);

// The environment prefiltered for perceptual roughness r (clamped to
// [0.045, 1]) with n = v = r: each output pixel of a width x height
// equirectangular image holds, for its centre direction r,
//     sum L(l_i) n.l_i / sum n.l_i,   h_i GGX-distributed around r (Hammersley points), l_i = reflect(-r, h_i), n.l_i > 0
// (Karis 2013, PrefilterEnvMap), L the bilinear radiance map of `image`,
// in the image's own frame and without intensity, each draw read from the
// map's pyramid (2 x 2 blocks averaged by solid angle) at the level whose
// pixel covers the draw's share of the lobe, 1 / (N pdf(l)), one level
// coarser (filtered importance sampling, Krivanek and Colbert 2008): a small
// sun reflects as one smooth highlight, not as the few draws that met it
// (roughness 0 reads the map itself).
RadianceImage prefilterEnvironment(const RadianceImage& image, double roughness, int width, int height, int samples);

// The prefiltered chain: level k of `levels` (>= 2) for roughness
// k / (levels - 1), each as wide as its lobe needs: the smallest power of
// two W with a texel of at most the lobe's alpha radians, 2 pi / W <= 2 alpha
// (W >= pi / alpha, alpha = roughness^2), from 8 up to `width` (the sharper
// levels all `width`), and as high as width x height gives it (never below
// 4). Many levels at small sizes: a roughness between two levels blends two
// lobes of nearly the same width (between 0 and 0.2 the lobe's solid angle
// grows 1000-fold; six levels blended a near-mirror with a fifth of that).
// The shader picks the level roughness * (levels - 1).
double prefilterLevelRoughness(int level, int levels);
int prefilterLevelWidth(double roughness, int width);
std::vector<RadianceImage> prefilterChain(const RadianceImage& image, int width, int height, int levels, int samples);

}  // namespace rl::ref
