// mutant of: 04-shadows
// mistake: the offset's length is |pError|, not the bound's extent along n
// caught by: the check's message or hint contains "not its extent along n"
// Exercise 04: shadow rays. Handout: course/04-shadows/handout.md

// Start of a secondary ray from hit point p: pushed along the normal n just
// past the bound pError on p's rounding error (Hit.error), whose extent along
// n is dot(|n|, pError) (pbrt-v4, section 6.8.6):
//     origin = p + dot(abs(n), pError) * n
vec3 offsetRayOrigin(vec3 p, vec3 n, vec3 pError) {
    return p + length(pError) * n;
}

// 1.0 when the light at lightPosition is visible from the hit, 0.0 when a
// sphere lies between them. Only occluders BEFORE the light count.
float lightVisibility(Hit hit, vec3 lightPosition) {
    vec3 origin = offsetRayOrigin(hit.p, hit.n, hit.error);
    vec3 toLight = lightPosition - origin;
    float distance = length(toLight);
    return anyHitBefore(origin, toLight / distance, distance, hit.sphere) ? 0.0 : 1.0;
}
