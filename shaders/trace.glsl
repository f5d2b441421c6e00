// trace.glsl: the radiance along a camera ray. Exercise 09's traceRay()
// follows the mirror bounces; until it is written, the framework shades the
// first hit only (no reflections).

vec3 traceFirstHitOnly(vec3 origin, vec3 dir) {
    Hit hit = closestHit(origin, dir);
    if (hit.t == NO_HIT) return backgroundRadiance();
    return shadeHit(hit, -dir);
}

// Exercise 09 builds on 04's offsetRayOrigin and 08's baseReflectance: it is
// used only when they are started too (constant arguments: folded away).
bool reflectionsReady() {
    Material probe = Material(vec3(0.5), 0.5, 0.0, 1.0);
    return !isStub(F_SchlickRoughness(vec3(0.04), 1.0, 0.5)) && !isStub(baseReflectance(probe)) &&
           !isStub(offsetRayOrigin(vec3(1.0), vec3(0.0, 0.0, 1.0), 1.0));
}

vec3 radianceAlong(vec3 origin, vec3 dir) {
    g_bounceCounter = 0;
    if (reflectionsReady()) {
        vec3 L = traceRay(origin, dir);
        if (!isStub(L)) return L;
        g_bounceCounter = 0;
    }
    return traceFirstHitOnly(origin, dir);
}
