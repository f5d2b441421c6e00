// intersect_scene.glsl: rays against every sphere of the scene, built on the
// exercise's intersectSphere() (02-intersect).

// Nearest hit along `dir`; hit.t = NO_HIT when nothing is hit. `dir` is
// renormalised first: a reflected direction is unit length only to ~1e-7,
// and over a long chord inside a large sphere that puts the hit point farther
// off the surface than the secondary-ray offset (the camera-inside hard case).
Hit closestHit(vec3 origin, vec3 dir) {
    dir = normalize(dir);
    Hit hit;
    hit.t = NO_HIT;
    hit.sphere = -1;
    float nearest = 3.4e38;  // FLT_MAX: any real hit is nearer
    for (int i = 0; i < sphereCount(); ++i) {
        float t = intersectSphere(origin, dir, sphereCenter(i), sphereRadius(i));
        if (isGeometryStub(t)) return hit;  // 02 not started: nothing is hit
        if (t > 0.0 && t < nearest) {
            nearest = t;
            hit.sphere = i;
        }
    }
    if (hit.sphere < 0) return hit;
    hit.t = nearest;
    hit.p = origin + nearest * dir;
    vec3 c = sphereCenter(hit.sphere);
    float r = sphereRadius(hit.sphere);
    hit.n = (hit.p - c) / r;
    if (dot(hit.n, dir) > 0.0) hit.n = -hit.n;  // hit from inside: face the ray
    hit.magnitude = max(maxAbs(hit.p), maxAbs(c) + r);
    return hit;
}

// True when some sphere is hit at 0 < t < tMax. Stops at the first occluder:
// a shadow ray needs to know only whether, not where.
bool anyHitBefore(vec3 origin, vec3 dir, float tMax) {
    for (int i = 0; i < sphereCount(); ++i) {
        float t = intersectSphere(origin, dir, sphereCenter(i), sphereRadius(i));
        if (t > 0.0 && t < tMax) return true;
    }
    return false;
}
