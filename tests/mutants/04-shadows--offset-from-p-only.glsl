// mutant of: 04-shadows
// mistake: an offset relative to |p| alone: near the origin it vanishes, while the hit point on a big sphere far from the origin carries the rounding error of its centre (acne)
// caught by: the check's message or hint contains "follows |p| alone"
// also breaks the hard case: scenes/hard/ground-1e4.json, ground-1e5.json
// Exercise 04: shadow rays. Handout: docs/exercises/04-shadows.md

// Start of a secondary ray from hit point p: pushed along the normal n by an
// amount that follows the size of the numbers behind p (hit.magnitude), so
// that the scene renders the same at any scale:
//     origin = p + n * RAY_OFFSET_RELATIVE * magnitude
vec3 offsetRayOrigin(vec3 p, vec3 n, float magnitude) {
    return p + n * (RAY_OFFSET_RELATIVE * maxAbs(p));
}

// 1.0 when the light at lightPosition is visible from the hit, 0.0 when a
// sphere lies between them. Only occluders BEFORE the light count.
float lightVisibility(Hit hit, vec3 lightPosition) {
    vec3 origin = offsetRayOrigin(hit.p, hit.n, hit.magnitude);
    vec3 toLight = lightPosition - origin;
    float distance = length(toLight);
    return anyHitBefore(origin, toLight / distance, distance) ? 0.0 : 1.0;
}
