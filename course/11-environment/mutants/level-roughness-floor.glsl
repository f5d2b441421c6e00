// mutant of: 11-environment
// mistake: the roughness clamped to [MIN_ROUGHNESS, 1] (ggxAlpha's floor) before it picks the level: level 0, the mirror-sharp one, is never used (issue 35: it was told to clamp to [0, 1], which it did, differently)
// caught by: the check's message or hint contains "not [MIN_ROUGHNESS, 1]: level 0 holds roughness 0"
// Exercise 11: environment light, as real-time renderers approximate it.
// Handout: course/11-environment/handout.md

// Irradiance E(n) from the environment's nine spherical-harmonic coefficients
// L_k = shCoefficient(k) (Ramamoorthi and Hanrahan 2001), n a unit normal in
// the environment's own frame:
//     E(n) = sum_k A_l(k) L_k Y_k(n),  A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4
//     Y_0 = 0.282095;  Y_1, Y_2, Y_3 = 0.488603 (y, z, x)
//     Y_4, Y_5, Y_7 = 1.092548 (xy, yz, xz);  Y_6 = 0.315392 (3 z^2 - 1);  Y_8 = 0.546274 (x^2 - y^2)
vec3 shIrradiance(vec3 n) {
    const float A0 = 3.14159265;  // pi
    const float A1 = 2.09439510;  // 2 pi / 3
    const float A2 = 0.78539816;  // pi / 4
    vec3 E = A0 * 0.282095 * shCoefficient(0);
    E += A1 * 0.488603 * (n.y * shCoefficient(1) + n.z * shCoefficient(2) + n.x * shCoefficient(3));
    E += A2 * (1.092548 * (n.x * n.y * shCoefficient(4) + n.y * n.z * shCoefficient(5) + n.x * n.z * shCoefficient(7)) +
               0.315392 * (3.0 * n.z * n.z - 1.0) * shCoefficient(6) + 0.546274 * (n.x * n.x - n.y * n.y) * shCoefficient(8));
    return E;
}

// The prefiltered level for perceptual roughness: level k of `levels` holds
// roughness k / (levels - 1), so the level is roughness * (levels - 1)
// (roughness clamped to [0, 1]), a fraction between two levels.
float prefilteredLevel(float roughness, int levels) {
    return clamp(roughness, MIN_ROUGHNESS, 1.0) * float(levels - 1);
}

// What environment light the hit sends to the viewer, from its parts:
//     diffuse  = (1 - metallic) (1 - F0) albedo / pi * irradiance
//     specular = prefiltered * (F0 * scale + bias)        (split sum, Karis 2013)
// with F0 = baseReflectance(m) and scaleBias = (scale, bias) from the table.
vec3 environmentShading(vec3 irradiance, vec3 prefiltered, vec2 scaleBias, Material m) {
    vec3 F0 = baseReflectance(m);
    vec3 diffuse = (1.0 - m.metallic) * (1.0 - F0) * m.albedo / PI * irradiance;
    vec3 specular = prefiltered * (F0 * scaleBias.x + scaleBias.y);
    return diffuse + specular;
}
