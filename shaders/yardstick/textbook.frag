// textbook.frag: the yardstick of `raylab bench` (variant "textbook"), NOT part
// of the framework. The model of docs/model.md written the plain way, as a
// course text would: uniform arrays, a nearest-hit loop, a shadow loop per
// light, a bounce loop, world coordinates, a fixed relative ray offset. No
// exercise files, stub checks, teaching views or specialisation: the
// straightforward yardstick, beside the hand-optimised `expert` one
// (app/bench/expert.cpp) that every ratio is against (docs/performance.md);
// the host sets the tb_ uniforms (app/bench/textbook.cpp).
const float PI = 3.14159265358979;
const int MAX_SPHERES = 64;
const int MAX_LIGHTS = 16;

uniform vec3 tb_eye, tb_right, tb_up, tb_forward;  // camera frame; tb_forward unit, right/up scaled by tan(fov/2)
uniform vec2 tb_resolution;
uniform int tb_gridSize;                           // sqrt(spp)
uniform int tb_sphereCount, tb_lightCount, tb_maxBounces, tb_toneMap;
uniform float tb_ambient, tb_exposure, tb_gamma;   // tb_gamma 0: sRGB
uniform vec3 tb_background;
uniform vec3 tb_center[MAX_SPHERES];
uniform float tb_radius[MAX_SPHERES];
uniform vec3 tb_albedo[MAX_SPHERES];
uniform vec3 tb_material[MAX_SPHERES];             // roughness, metallic, ao
uniform vec3 tb_lightPos[MAX_LIGHTS];
uniform vec3 tb_lightPower[MAX_LIGHTS];            // color * intensity

layout(location = 0) out vec4 o_display;
layout(location = 1) out vec4 o_radiance;

// Nearest t > tMin along o + t d (d unit) over all spheres; -1 for none.
float nearest(vec3 o, vec3 d, float tMax, out int hitIndex) {
    float best = tMax;
    hitIndex = -1;
    for (int i = 0; i < tb_sphereCount; ++i) {
        vec3 oc = o - tb_center[i];
        float b = dot(oc, d);
        vec3 perp = oc - b * d;
        float disc = tb_radius[i] * tb_radius[i] - dot(perp, perp);
        if (disc < 0.0) continue;
        float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc);
        float t0 = q, t1 = (dot(oc, oc) - tb_radius[i] * tb_radius[i]) / q;
        float t = min(t0, t1) > 0.0 ? min(t0, t1) : max(t0, t1);
        if (t > 0.0 && t < best) { best = t; hitIndex = i; }
    }
    return best;
}

vec3 radiance(vec3 o, vec3 d) {
    vec3 sum = vec3(0.0), throughput = vec3(1.0);
    for (int bounce = 0; bounce <= tb_maxBounces; ++bounce) {
        int i;
        float t = nearest(o, d, 3.0e38, i);
        if (i < 0) return sum + throughput * tb_background;
        vec3 p = o + t * d;
        vec3 n = (p - tb_center[i]) / tb_radius[i];
        if (dot(n, d) > 0.0) n = -n;
        vec3 v = -d, albedo = tb_albedo[i];
        float r = clamp(tb_material[i].x, 0.045, 1.0), metallic = tb_material[i].y, alpha = r * r;
        vec3 F0 = mix(vec3(0.04), albedo, metallic);
        float NoV = clamp(dot(n, v), 1e-4, 1.0), k = (r + 1.0) * (r + 1.0) / 8.0;
        vec3 origin = p + n * (1e-4 * max(1.0, max(abs(p.x), max(abs(p.y), abs(p.z)))));
        vec3 direct = tb_ambient * albedo * tb_material[i].z;
        for (int j = 0; j < tb_lightCount; ++j) {
            vec3 toLight = tb_lightPos[j] - p;
            float d2 = dot(toLight, toLight);
            vec3 l = toLight / sqrt(d2);
            float NoL = clamp(dot(n, l), 0.0, 1.0);
            if (d2 <= 1e-12 || NoL <= 0.0) continue;
            int blocker;
            float dist = length(tb_lightPos[j] - origin);
            nearest(origin, (tb_lightPos[j] - origin) / dist, dist, blocker);
            if (blocker >= 0) continue;
            vec3 h = normalize(l + v);
            float NoH = dot(n, h), a2 = alpha * alpha, den = NoH * NoH * (a2 - 1.0) + 1.0;
            float D = a2 / (PI * den * den);
            float G = NoV / (NoV * (1.0 - k) + k) * NoL / (NoL * (1.0 - k) + k);
            vec3 F = F0 + (1.0 - F0) * pow(1.0 - clamp(dot(h, v), 0.0, 1.0), 5.0);
            vec3 kd = (1.0 - F) * (1.0 - metallic);
            direct += (kd * albedo / PI + D * G * F / (4.0 * NoL * NoV)) * tb_lightPower[j] / d2 * NoL;
        }
        sum += throughput * direct;
        throughput *= F0 + (max(vec3(1.0 - r), F0) - F0) * pow(1.0 - NoV, 5.0);
        o = origin;
        d = reflect(d, n);
    }
    return sum;
}

void main() {
    vec2 pixel = floor(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    for (int a = 0; a < tb_gridSize; ++a)
        for (int b = 0; b < tb_gridSize; ++b) {
            vec2 uv = 2.0 * (pixel + (vec2(a, b) + 0.5) / float(tb_gridSize)) / tb_resolution - 1.0;
            vec3 d = normalize(uv.x * tb_resolution.x / tb_resolution.y * tb_right + uv.y * tb_up + tb_forward);
            sum += radiance(tb_eye, d);
        }
    vec3 L = sum / float(tb_gridSize * tb_gridSize);
    vec3 c = L * tb_exposure;
    c = tb_toneMap == 0 ? c / (1.0 + c) : tb_toneMap == 1 ? 1.0 - exp(-c) : clamp(c, 0.0, 1.0);
    c = tb_gamma > 0.0 ? pow(c, vec3(1.0 / tb_gamma))
                       : mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
    o_display = vec4(c, 1.0);
    o_radiance = vec4(L, 1.0);
}
