// mutant of: 09-reflections
// mistake: the background added after the loop, whatever ended it: a path that ends after maxBounces() bounces takes the background too, as if it had escaped (issue 35: it was told to stop after maxBounces() bounces, which it does)
// caught by: the check's message or hint contains "the background counts only for a ray that misses every sphere"
// Exercise 09: Fresnel-attenuated mirror bounces. Handout: course/09-reflections/handout.md

// Roughness-aware Schlick Fresnel of the macro normal, for reflections of the
// environment (not for point lights):
//     Fr = F0 + (max(vec3(1 - r), F0) - F0) (1 - NoV)^5,  r = clamp(roughness, MIN_ROUGHNESS, 1)
vec3 F_SchlickRoughness(vec3 F0, float NoV, float roughness) {
    float r = clamp(roughness, MIN_ROUGHNESS, 1.0);
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
    int leaving = NO_SPHERE;  // the sphere the ray starts on: none for the camera
    for (int bounce = 0; bounce <= maxBounces(); ++bounce) {
        if (bounce > 0 && bounceCannotChangeOutput(radiance, throughput)) break;  // optional: saves time
        Hit hit = closestHit(origin, dir, leaving);
        if (hit.t == NO_HIT) break;
        radiance += throughput * shadeHit(hit, -dir);
        Material m = sphereMaterial(hit.sphere);
        float NoV = clamp(dot(hit.n, -dir), 1e-4, 1.0);
        throughput *= F_SchlickRoughness(baseReflectance(m), NoV, m.roughness);
        origin = offsetRayOrigin(hit.p, hit.n, hit.error);
        dir = reflect(dir, hit.n);
        leaving = hit.sphere;
    }
    radiance += throughput * backgroundRadiance();  // the mistake: also after the last bounce
    return radiance;
}
