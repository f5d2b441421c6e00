// sh9.h: irradiance from nine spherical-harmonic coefficients (Ramamoorthi
// and Hanrahan 2001, "An Efficient Representation for Irradiance Environment
// Maps"), computed on the host in double for the shader of issue 24 and for
// the checks of the exercise that evaluates them. Pure functions.
//
// The basis: real spherical harmonics up to l = 2 of a unit direction
// d = (x, y, z) in the image's own frame (y up), in this order:
//     0: Y00  = 0.282095                      (1 / (2 sqrt(pi)))
//     1: Y1-1 = 0.488603 y    2: Y10 = 0.488603 z    3: Y11 = 0.488603 x     (sqrt(3 / (4 pi)))
//     4: Y2-2 = 1.092548 xy   5: Y2-1 = 1.092548 yz  7: Y21 = 1.092548 xz    (sqrt(15 / (4 pi)))
//     6: Y20  = 0.315392 (3 z^2 - 1)                                         (sqrt(5 / (16 pi)))
//     8: Y22  = 0.546274 (x^2 - y^2)                                         (sqrt(15 / (16 pi)))
// (Ramamoorthi-Hanrahan's table with its z taken as given: the nine
// functions are orthonormal in any frame, so which axis is "up" only
// relabels them; the projection and the evaluation below agree.)
// The coefficients L_k = integral of L(d) Y_k(d) dd over the sphere, and the
// irradiance of a unit normal n
//     E(n) = sum_k A_l(k) L_k Y_k(n),   A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4
// (the clamped cosine's own coefficients, R-H eq. 8 and 9). E is
// irradiance: a Lambert surface of albedo a reflects a E / pi.
#pragma once

#include "core/environment_image.h"

#include <glm/vec3.hpp>

#include <array>

namespace rl::ref {

using Sh9 = std::array<glm::dvec3, 9>;  // RGB coefficients, in the order above

// The nine basis functions at the unit direction d.
std::array<double, 9> sh9Basis(glm::dvec3 d);

// The band of coefficient k (0, 1 or 2) and its clamped-cosine factor A_l.
int sh9Band(int k);
double sh9CosineFactor(int band);

// Projection of a radiance map, in the image's own frame and without its
// intensity: each pixel's value times the exact integral of Y_k over the
// pixel (phi in [2 pi (x/W - 1/2), 2 pi ((x+1)/W - 1/2)], cos theta between
// its top and bottom edge: products of polynomials in cos theta, sin theta
// and sin, cos of phi, integrated in closed form). So the map is taken as
// constant over each pixel, and a uniform map of radiance L gives
// L_0 = 4 pi L Y00 and the others 0 to rounding, hence E = pi L.
Sh9 projectSh9(const RadianceImage& image);

// E(n) from the coefficients, n a unit direction in the same frame.
glm::dvec3 sh9Irradiance(const Sh9& coefficients, glm::dvec3 n);

// A scene's environment: intensity * sh9Irradiance(coefficients of its image,
// the world normal turned into the image's frame).
glm::dvec3 environmentIrradianceSh9(const Environment& environment, const Sh9& coefficients, glm::dvec3 worldNormal);

}  // namespace rl::ref
