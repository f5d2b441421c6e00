// Exercise 04: shadow rays.            Handout: course/04-shadows/handout.md
//
// Until you write these, every light is visible from everywhere (no shadows).

// Where a secondary ray from hit point p (unit normal n) starts: p pushed
// along n just past its rounding error. pError is the componentwise bound on
// how far the computed p can be from the exact surface point (Hit.error); its
// extent along n is dot(|n|, pError). Contract:
//     origin = p + dot(abs(n), pError) * n
vec3 offsetRayOrigin(vec3 p, vec3 n, vec3 pError) {
    return vec3(NOT_STARTED);  // TODO
}

// 1.0 when the light at lightPosition is visible from hit.p, 0.0 when a
// sphere lies between them. Start the shadow ray at offsetRayOrigin(...),
// and count only occluders BEFORE the light. The framework gives you
//     bool anyHitBefore(vec3 origin, vec3 unitDir, float tMax, int leaving)
// leaving = hit.sphere, the sphere the ray starts on (handled exactly).
float lightVisibility(Hit hit, vec3 lightPosition) {
    return NOT_STARTED;  // TODO
}
