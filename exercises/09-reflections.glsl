// Exercise 09: Fresnel-attenuated mirror bounces. Handout: course/09-reflections/handout.md
//
// Until you write these, the framework shades the first hit only.

// Roughness-aware Schlick Fresnel of the macro normal (for reflections of the
// scene, not for point lights):
//     r = clamp(roughness, MIN_ROUGHNESS, 1)
//     Fr = F0 + (max(vec3(1 - r), F0) - F0) (1 - NoV)^5
vec3 F_SchlickRoughness(vec3 F0, float NoV, float roughness) {
    return vec3(NOT_STARTED);  // TODO
}

// Radiance seen along the ray origin + t dir (dir unit length):
//     radiance = 0, throughput = 1
//     leaving = NO_SPHERE (the camera lies on no sphere)
//     repeat for the primary hit and up to maxBounces() bounces:
//         hit = closestHit(origin, dir, leaving)
//         miss: radiance += throughput * backgroundRadiance(); stop
//         radiance += throughput * shadeHit(hit, -dir)
//         throughput *= F_SchlickRoughness(F0 of the hit's material, clamp(n.v, 1e-4, 1), its roughness)
//         continue from offsetRayOrigin(hit.p, hit.n, hit.error) in reflect(dir, hit.n),
//         leaving = hit.sphere
// Framework: closestHit, shadeHit, backgroundRadiance, sphereMaterial(hit.sphere), maxBounces.
// Optional, once it works: at the top of each bounce after the first,
//         if (bounceCannotChangeOutput(radiance, throughput)) stop
// saves the bounces that can no longer change the picture (docs/performance.md).
vec3 traceRay(vec3 origin, vec3 dir) {
    return vec3(NOT_STARTED);  // TODO
}
