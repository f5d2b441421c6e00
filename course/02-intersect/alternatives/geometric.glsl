// alternative of: 02-intersect
// written as: the geometric form (Scratchapixel / Ray Tracing Gems ch. 7): the distance tca to the point of the ray closest to the centre, its squared distance d2 to the centre (from the perpendicular vector, so far spheres stay exact), then tca -/+ sqrt(r^2 - d2)
// expected: PASS (a correct solution written differently)
// Exercise 02: ray/sphere intersection. Handout: course/02-intersect/handout.md

// Distance t > 0 along the unit direction `dir` to the nearest point where
// the ray origin + t dir meets the sphere, or NO_HIT.
// Numerically stable form (Haines et al., "Precision Improvements for
// Ray/Sphere Intersection", Ray Tracing Gems, 2019, ch. 7):
//     f = origin - center,  b = dot(f, dir)
//     discriminant = r^2 - |f - b dir|^2     (perpendicular distance: no cancellation of b^2 - c)
//     q = -b - sign(b) sqrt(discriminant),   roots t0 = c / q, t1 = q,  c = |f|^2 - r^2
float intersectSphere(vec3 origin, vec3 dir, vec3 center, float radius) {
    vec3 toCenter = center - origin;
    float tca = dot(toCenter, dir);         // along the ray, to the point closest to the centre
    vec3 closest = toCenter - tca * dir;    // from that point to the centre
    float d2 = dot(closest, closest);
    float r2 = radius * radius;
    if (d2 > r2) return NO_HIT;
    float thc = sqrt(r2 - d2);              // half the chord
    float t0 = tca - thc;
    float t1 = tca + thc;
    if (t0 > 0.0) return t0;
    if (t1 > 0.0) return t1;
    return NO_HIT;
}
