// brdf_probe.glsl: the main() of the accuracy suite's BRDF probe, appended to
// shaders/raytracer.glsl (assembled with the scene model's defines) by
// tests/accuracy/accuracy_support.cpp. Like shaders/probe.glsl, case k is the
// pixel (k % width, k / width), its inputs are the six RGBA32F texels
// (6 (k % width) + i, k / width) of u_probeInputs:
//     0: n.xyz, roughness   1: v.xyz, metallic   2: l.xyz (h for D and F)
//     3: albedo.rgb         4: edge tint.rgb
// and the result (rgb, linear) goes to the pixel. The probe evaluates what the
// picture uses: surfaceBRDF() of lighting.glsl and the lobes and terms behind it.

uniform sampler2D u_probeInputs;
uniform int u_probeFunction;  // tests/accuracy/accuracy_support.h, BrdfProbe

layout(location = 0) out vec4 o_result;

const int BRDF_PROBE_BRDF = 0;
const int BRDF_PROBE_SPECULAR = 1;
const int BRDF_PROBE_DIFFUSE = 2;
const int BRDF_PROBE_D = 3;
const int BRDF_PROBE_F = 4;

void main() {
    ivec2 cell = ivec2(gl_FragCoord.xy);
    vec4 a = texelFetch(u_probeInputs, ivec2(6 * cell.x + 0, cell.y), 0);
    vec4 b = texelFetch(u_probeInputs, ivec2(6 * cell.x + 1, cell.y), 0);
    vec4 c = texelFetch(u_probeInputs, ivec2(6 * cell.x + 2, cell.y), 0);
    vec4 d = texelFetch(u_probeInputs, ivec2(6 * cell.x + 3, cell.y), 0);
    vec4 e = texelFetch(u_probeInputs, ivec2(6 * cell.x + 4, cell.y), 0);
    vec3 n = a.xyz, v = b.xyz, l = c.xyz, edgeTint = e.rgb;
    Material m = Material(d.rgb, a.w, b.w, 1.0);
    vec3 r = vec3(0.0);
    int f = u_probeFunction;
#ifdef RL_MODEL_VARIANTS
    if (f == BRDF_PROBE_BRDF) r = surfaceBRDF(n, v, l, m, edgeTint);
    else if (f == BRDF_PROBE_SPECULAR) r = modelSpecularBRDF(n, v, l, m, edgeTint);
    else if (f == BRDF_PROBE_DIFFUSE) r = modelDiffuseBRDF(n, v, l, m, edgeTint);
#ifdef RL_BLINN_PHONG
    else if (f == BRDF_PROBE_D) r = vec3(Fr_BlinnPhong(n, l, shininessFromAlpha(ggxAlpha(m.roughness))));
#else
    else if (f == BRDF_PROBE_D) r = vec3(modelD(n, l, ggxAlpha(m.roughness)));
#endif
    else if (f == BRDF_PROBE_F) r = modelF(baseReflectance(m), edgeTint, dot(v, l));
#else
    if (f == BRDF_PROBE_BRDF) r = surfaceBRDF(n, v, l, m);
    else if (f == BRDF_PROBE_SPECULAR) r = specularBRDF(n, v, l, m);
    else if (f == BRDF_PROBE_DIFFUSE) r = diffuseBRDF(n, v, l, m);
    else if (f == BRDF_PROBE_D) r = vec3(D_GGX(n, l, ggxAlpha(m.roughness)));
    else if (f == BRDF_PROBE_F) r = F_Schlick(baseReflectance(m), dot(v, l));
#endif
    o_result = vec4(r, 1.0);
}
