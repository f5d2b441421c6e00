// proposed fix of: 09-reflections (solutions/09-reflections.glsl)
// bug: the bounce direction reflect(d, n) is used without normalising it
// shown by: scenes/hard/camera-inside.json (25% of the pixels off the CPU reference, acne inside the sphere)
// Exercise 09: Fresnel-attenuated mirror bounces. Handout: docs/exercises/09-reflections.md

// Roughness-aware Schlick Fresnel of the macro normal, for reflections of the
// environment (not for point lights):
//     Fr = F0 + (max(vec3(1 - r), F0) - F0) (1 - NoV)^5,  r = clamp(roughness, 0.045, 1)
vec3 F_SchlickRoughness(vec3 F0, float NoV, float roughness) {
    float r = clamp(roughness, 0.045, 1.0);
    float m = 1.0 - clamp(NoV, 0.0, 1.0);
    float m2 = m * m;
    return F0 + (max(vec3(1.0 - r), F0) - F0) * (m2 * m2 * m);
}

// Radiance arriving at `origin` along -dir: the first hit's light, then up
// to maxBounces() mirror bounces, each weighted by the Fresnel of the hits
// before it. A ray that leaves the scene adds the background and stops.
vec3 traceRay(vec3 origin, vec3 dir) {
    vec3 radiance = vec3(0.0);
    vec3 throughput = vec3(1.0);
    for (int bounce = 0; bounce <= maxBounces(); ++bounce) {
        if (bounce > 0 && bounceCannotChangeOutput(radiance, throughput)) break;  // optional: saves time
        Hit hit = closestHit(origin, dir);
        if (hit.t == NO_HIT) {
            radiance += throughput * backgroundRadiance();
            break;
        }
        radiance += throughput * shadeHit(hit, -dir);
        Material m = sphereMaterial(hit.sphere);
        float NoV = clamp(dot(hit.n, -dir), 1e-4, 1.0);
        throughput *= F_SchlickRoughness(baseReflectance(m), NoV, m.roughness);
        origin = offsetRayOrigin(hit.p, hit.n, hit.magnitude);
        // reflect() of a unit d about an n that is unit only to ~1e-7 gives a
        // direction ~1e-6 too long; intersectSphere() assumes |dir| = 1, so a
        // chord of 8 lands 8e-6 off the sphere, beyond the offset of 2^-19 of
        // the magnitude 4 (7.6e-6): the shadow ray from there is self-occluded.
        dir = normalize(reflect(dir, hit.n));
    }
    return radiance;
}
