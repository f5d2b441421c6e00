// Exercise 11: environment light, as real-time renderers approximate it.
// Handout: course/11-environment/handout.md

// Irradiance E(n) from the environment's nine spherical-harmonic coefficients
// L_k = shCoefficient(k) (Ramamoorthi and Hanrahan 2001), n a unit normal in
// the environment's own frame:
//     E(n) = sum_k A_l(k) L_k Y_k(n),  A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4
//     Y_0 = 0.282095;  Y_1, Y_2, Y_3 = 0.488603 (y, z, x)
//     Y_4, Y_5, Y_7 = 1.092548 (xy, yz, xz);  Y_6 = 0.315392 (3 z^2 - 1);  Y_8 = 0.546274 (x^2 - y^2)
vec3 shIrradiance(vec3 n) {
    return vec3(NOT_STARTED);
}

// The prefiltered level for perceptual roughness: level k of `levels` holds
// roughness k / (levels - 1). Return the (fractional) level for `roughness`.
float prefilteredLevel(float roughness, int levels) {
    return NOT_STARTED;
}

// What environment light the hit sends to the viewer, from its parts:
//     diffuse  = (1 - metallic) (1 - F0) albedo / pi * irradiance
//     specular = prefiltered * (F0 * scale + bias)        (split sum, Karis 2013)
// with F0 = baseReflectance(m) and scaleBias = (scale, bias) from the table.
vec3 environmentShading(vec3 irradiance, vec3 prefiltered, vec2 scaleBias, Material m) {
    return vec3(NOT_STARTED);
}
